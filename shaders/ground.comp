#version 450
#extension GL_GOOGLE_include_directive : require
// The ground (the quad ±eye.w metres at y = 0) or the clear colour per pixel, as the visibility
// buffer's words (colour in the low 32 bits, depth in the high 32): the renderer keeps them while
// the camera stands still and copies them into each frame's visibility buffer before the splat,
// whose atomicMin then keeps the nearer of the ground and each hit (on lavapipe a full-screen
// fragment pass costs more than the whole splat). Same colours as
// ground.frag and the splat resolve: grid-line widths from the neighbouring pixels' ground
// points, as a fragment quad's derivatives are.
#include "shared_types.h"
#include "render_bindings.h"
#include "ground.glsl"

layout(local_size_x = 64) in;
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(std430, binding = kRenderBindingGroundVisibility) writeonly buffer Ground { uvec2 ground[]; };  // (colour, depth bits)
layout(push_constant) uniform Push { vec4 clearColour; };

// Unnormalized ray through a pixel centre (the ground point needs no normalize).
vec3 rayThrough(vec2 pixel) {
  vec2 ndc = pixel / frame.viewport.xy * 2.0 - 1.0;
  return frame.rayForward.xyz + ndc.x * frame.rayRight.xyz + ndc.y * frame.rayDown.xyz;
}

vec2 groundXz(vec3 eye, vec2 pixel) {
  vec3 d = rayThrough(pixel);
  return eye.xz - (eye.y / d.y) * d.xz;
}

// Workgroups walk rows in segments of 64 pixels, so no invocation divides by the width.
void main() {
  uint width = uint(frame.viewport.x), height = uint(frame.viewport.y);
  uint segments = (width + 63u) / 64u;
  for (uint group = gl_WorkGroupID.x; group < segments * height; group += gl_NumWorkGroups.x) {
    uint row = group / segments;
    uint x = (group - row * segments) * 64u + gl_LocalInvocationID.x;
    if (x >= width) continue;
    vec2 centre = vec2(x, row) + 0.5;
    vec3 eye = frame.eye.xyz;
    vec3 d = rayThrough(centre);
    float t = d.y < 0.0 ? -eye.y / d.y : -1.0;
    vec3 world = eye + t * d;
    vec4 clip = frame.viewProjection * vec4(world, 1.0);
    float depth = clip.z / clip.w;
    uint colour = packUnorm4x8(clearColour);
    if (t > 0.0 && all(lessThanEqual(abs(world.xz), vec2(frame.eye.w))) && depth >= 0.0 && depth <= 1.0) {
      // A fragment quad's derivatives: differences across the 2×2 quad holding the pixel.
      vec2 quad = vec2(uvec2(x, row) & ~1u) + 0.5;
      vec2 ddx = groundXz(eye, vec2(quad.x + 1.0, centre.y)) - groundXz(eye, vec2(quad.x, centre.y));
      vec2 ddy = groundXz(eye, vec2(centre.x, quad.y + 1.0)) - groundXz(eye, vec2(centre.x, quad.y));
      colour = packUnorm4x8(groundColour(world, abs(ddx) + abs(ddy), eye));
    } else {
      depth = 1.0;
    }
    // One step further than the ground (below 1.0, which the depth image needs): a hit at the
    // ground's own depth (a foot on it) wins the atomicMin, as it wins splat_resolve.frag's test.
    uint depthBits = floatBitsToUint(depth);
    if (depth < 1.0) depthBits += 1u;
    ground[row * width + x] = uvec2(colour, depthBits);
  }
}
