#version 450
#extension GL_GOOGLE_include_directive : require
// The frame's visibility buffer into the colour and depth planes the target is copied from. The
// buffer started as the ground (ground.comp's words, copied in) and every splat kept each pixel's
// nearest hit in it by atomicMin, so it holds the whole picture: a pixel's word is its colour
// (low 32 bits) and its depth (high 32). Two pixels per invocation: lavapipe runs each storage
// access as a loop over the lanes, so one 16-byte load and two 8-byte stores move two pixels.
#include "shared_types.h"
#include "render_bindings.h"

layout(local_size_x = 64) in;
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
// The visibility words as pairs (colour, depth), and two pixels' pairs at a time.
layout(std430, binding = kRenderBindingVisibility) readonly buffer Visibility { uvec2 visibility[]; };
layout(std430, binding = kRenderBindingVisibility) readonly buffer VisibilityPairs { uvec4 visibilityPairs[]; };
// The colour plane, then the depth plane from word visibilityDepthPlane(pixels) (even, so that
// both planes hold whole uvec2s).
layout(std430, binding = kRenderBindingFramePlanes) writeonly buffer Planes { uint planes[]; };
layout(std430, binding = kRenderBindingFramePlanes) writeonly buffer PlanePairs { uvec2 planePairs[]; };

void main() {
  uint pixels = uint(frame.viewport.x) * uint(frame.viewport.y);
  uint depthPairs = visibilityDepthPlane(pixels) / 2u;
  uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  for (uint i = gl_GlobalInvocationID.x; i < pixels / 2u; i += stride) {
    uvec4 two = visibilityPairs[i];
    planePairs[i] = two.xz;
    planePairs[depthPairs + i] = two.yw;
  }
  if ((pixels & 1u) != 0u && gl_GlobalInvocationID.x == 0u) {
    uvec2 last = visibility[pixels - 1u];
    planes[pixels - 1u] = last.x;
    planes[visibilityDepthPlane(pixels) + pixels - 1u] = last.y;
  }
}
