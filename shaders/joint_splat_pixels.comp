#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
// The far joints, step 3 of a walk per joint (joint_splat_walk.comp; a walk per character
// ray-casts its pixels itself): one invocation per reserved pixel entry ray-casts
// its sprite's ellipsoid through the pixel the entry names, so neighbouring lanes do equal work
// whatever the sprites' sizes. A fixed number of workgroups strides over the entries, so the pass
// needs no indirect arguments. CPU twin: render::splatJointsCpu.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"

layout(local_size_x = 64) in;
// Copied at the top of main, as in joint_splat_walk.comp (lavapipe reads uniforms inside
// branches and loops lane by lane).
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frameBlock; };
FrameUniforms frame;
layout(std430, binding = kRenderBindingVisibility) buffer Visibility { uint64_t visibility[]; };
#include "joint_splat_common.glsl"
layout(std430, binding = kRenderBindingSprites) readonly buffer Sprites { SplatSprite sprites[]; };
layout(std430, binding = kRenderBindingPixelOwners) readonly buffer Owners { uint64_t owners[]; };
layout(std430, binding = kRenderBindingSplatCounters) readonly buffer Counters { SplatCounters counters; };

void main() {
  frame = frameBlock;
  uint total = spriteEntries(counters);
  uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  FrameRays f = frameRays();
  for (uint entry = gl_GlobalInvocationID.x; entry < total; entry += stride) {
    uint64_t e = owners[entry];
    uint sprite = entrySprite(e);
    if (sprite == kSplatNoSprite) continue;
    SplatSprite s = sprites[sprite];
    ivec2 xy = entryPixel(e);
    // The walk per character's arithmetic, so both walks give the same bits.
    SpriteRays rays = spriteRays(s.inverse0, s.inverse1, s.inverse2, f);
    splatRayPixel(rays, f, rowRays(rays, f, xy.y), xy.x, xy.y, s.tint.xyz);
  }
}
