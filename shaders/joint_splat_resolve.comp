#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The far joints, step 3 on targets that take copies: one invocation per reserved pixel entry
// (the pixel it names) writes the pixel's nearest splat hit into the frame's colour and depth
// planes (the ground's, copied in) where it is not behind the ground; the planes are then copied
// into the target. So the resolve costs the splatted pixels, not a full-screen fragment pass.
// Entries of one pixel write the same value, an entry whose ray missed too (nothing where no ray
// hit). Sprites past the work lists' capacities have no entries: invocation 0
// then sets the fragment resolve's indirect draw (otherwise empty) to cover the screen.
#include "shared_types.h"
#include "render_bindings.h"

layout(local_size_x = 64) in;
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(std430, binding = kRenderBindingVisibility) readonly buffer Visibility { uint64_t visibility[]; };
#include "joint_splat_counters.glsl"
layout(std430, binding = kRenderBindingPixelOwners) readonly buffer Owners { uint64_t owners[]; };
layout(std430, binding = kRenderBindingSplatCounters) readonly buffer Counters { SplatCounters counters; };
layout(std430, binding = kRenderBindingFramePlanes) buffer Planes { uint planes[]; };  // colour plane, then depth plane
layout(std430, binding = kRenderBindingResolveDraw) writeonly buffer ResolveDraw { uint resolveDraw[4]; };

void main() {
  uint bodies = bodyEntries(counters);
  uint spritePixels = spriteEntries(counters);
  if (gl_GlobalInvocationID.x == 0u) {
    bool overflow = counters.sprites > kSpriteCapacity || counters.bodyPixels > kPixelCapacity ||
                    counters.pixels > spriteEntryLimit(counters);
    resolveDraw[0] = overflow ? 3u : 0u;
    resolveDraw[1] = 1u;
    resolveDraw[2] = 0u;
    resolveDraw[3] = 0u;
  }
  uint width = uint(frame.viewport.x), pixels = width * uint(frame.viewport.y);
  uint total = spritePixels + bodies;
  uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  for (uint k = gl_GlobalInvocationID.x; k < total; k += stride) {
    // A sprite's pixel (hit or not), a far body's hit pixel, or no entry.
    uint64_t e = owners[k < spritePixels ? k : kPixelCapacity - 1u - (k - spritePixels)];
    if (entrySprite(e) == kSplatNoSprite) continue;
    ivec2 xy = entryPixel(e);
    uint i = uint(xy.y) * width + uint(xy.x);
    uint64_t v = visibility[i];
    if (v == 0xFFFFFFFFFFFFFFFFul) continue;
    uint depthBits = uint(v >> 32);
    if (uintBitsToFloat(depthBits) > uintBitsToFloat(planes[pixels + i])) continue;  // behind the ground
    planes[i] = uint(v & 0xFFFFFFFFul);
    planes[pixels + i] = depthBits;
  }
}
