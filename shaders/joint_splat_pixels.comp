#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
// The far joints, step 2: one invocation per reserved pixel entry (joint_splat.comp) ray-casts
// its sprite's ellipsoid through that pixel, so neighbouring lanes do equal work whatever the
// sprites' sizes. A fixed number of workgroups strides over the entries, so the pass needs no
// indirect arguments. Each entry is left holding its pixel's index (kSplatNoSprite on a miss) for
// joint_splat_resolve.comp. The far bodies' entries, counted down from the last (SplatCounters),
// name their pixels already and are not visited. CPU twin: render::splatJointsCpu.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"

layout(local_size_x = 64) in;
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(std430, binding = kRenderBindingVisibility) buffer Visibility { uint64_t visibility[]; };
#include "joint_splat_common.glsl"
layout(std430, binding = kRenderBindingSprites) readonly buffer Sprites { SplatSprite sprites[]; };
layout(std430, binding = kRenderBindingPixelOwners) buffer Owners { uint owners[]; };
layout(std430, binding = kRenderBindingSplatCounters) readonly buffer Counters { SplatCounters counters; };

void main() {
  uint total = spriteEntries(counters);  // the sprites' entries alone
  uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  for (uint entry = gl_GlobalInvocationID.x; entry < total; entry += stride) {
    uint owner = owners[entry];
    if (owner == kSplatNoSprite) continue;
    SplatSprite s = sprites[owner & kSplatOwnerSpriteMask];
    // The pixel's row in the box by a float division: exact for boxes this small (fewer than
    // 2^16 pixels), and lavapipe divides integers one lane at a time.
    uint local = owner >> kSplatOwnerPixelShift;
    uint row = uint((float(local) + 0.5) / float(s.box.z));
    int x = int(s.box.x + local - row * s.box.z), y = int(s.box.y + row);
    bool hit = splatPixel(x, y, s.inverse0, s.inverse1, s.inverse2, s.tint.xyz);
    // The entry now names its pixel, or nothing where the ray missed, for the resolve.
    owners[entry] = hit ? uint(y) * uint(frame.viewport.x) + uint(x) : kSplatNoSprite;
  }
}
