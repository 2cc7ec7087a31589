#version 450
#extension GL_GOOGLE_include_directive : require
// The ground quad's colour (ground.glsl); drawn when the joints are not splatted (the splat
// resolve shades the ground otherwise).
#include "shared_types.h"
#include "render_bindings.h"
#include "ground.glsl"

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(location = 0) in vec3 worldPosition;
layout(location = 0) out vec4 color;

void main() { color = groundColour(worldPosition, fwidth(worldPosition.xz), frame.eye.xyz); }
