#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
// The far joints, step 3: one invocation per reserved pixel entry (joint_splat.comp,
// joint_splat_walk.comp) ray-casts its sprite's ellipsoid through that pixel, so neighbouring
// lanes do equal work whatever the sprites' sizes. A fixed number of workgroups strides over the
// entries, so the pass needs no indirect arguments. The pixels hit first here, and those a far
// body hit first (its entries name them, kSplatPixelEntry), go to the resolve list: each
// splatted pixel once, so joint_splat_resolve.comp visits neither misses nor a pixel twice.
// CPU twin: render::splatJointsCpu.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"

layout(local_size_x = 64) in;
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(std430, binding = kRenderBindingVisibility) buffer Visibility { uint64_t visibility[]; };
#include "joint_splat_common.glsl"
layout(std430, binding = kRenderBindingSprites) readonly buffer Sprites { SplatSprite sprites[]; };
layout(std430, binding = kRenderBindingPixelOwners) readonly buffer Owners { uint owners[]; };
layout(std430, binding = kRenderBindingSplatCounters) buffer Counters { SplatCounters counters; };
layout(std430, binding = kRenderBindingResolveList) writeonly buffer ResolveList { uint resolveList[]; };

// Appends the pixels the subgroup's lanes hit first to the resolve list, one atomic per
// subgroup (lavapipe runs a lane's atomics one at a time).
void listForResolve(bool first, uint pixel) {
  uvec4 ballot = subgroupBallot(first);
  uint total = subgroupBallotBitCount(ballot), base = 0u;
  if (total == 0u) return;
  if (subgroupElect()) base = atomicAdd(counters.resolved, total);
  base = subgroupBroadcastFirst(base);
  if (first) resolveList[base + subgroupBallotExclusiveBitCount(ballot)] = pixel;
}

void main() {
  uint total = min(counters.pixels, kPixelCapacity);
  uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  for (uint entry = gl_GlobalInvocationID.x; entry < total; entry += stride) {
    uint owner = owners[entry];
    bool first = owner != kSplatNoSprite && (owner & kSplatPixelEntry) != 0u;  // a far body's
    uint pixel = owner & ~kSplatPixelEntry;
    if (owner != kSplatNoSprite && !first) {
      SplatSprite s = sprites[owner];
      // The entry's row in the box by a float division: exact for boxes this small (fewer than
      // 2^16 entries), and lavapipe divides integers one lane at a time.
      uint local = entry - s.box.w;
      uint row = uint((float(local) + 0.5) / float(s.box.z));
      int x = int(s.box.x + local - row * s.box.z), y = int(s.box.y + row);
      first = splatPixel(x, y, s.inverse0, s.inverse1, s.inverse2, s.tint.xyz);
      pixel = uint(y) * uint(frame.viewport.x) + uint(x);
    }
    listForResolve(first, pixel);
  }
}
