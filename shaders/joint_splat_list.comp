#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_KHR_shader_subgroup_shuffle : require
// The far joints, step 0: lists the characters on screen (any joint in their coverage mask;
// every character without masks) for joint_splat.comp, which is dispatched by the list's
// length. On lavapipe a character that returns at the first line of the far-body pass still
// costs all of its lines (every lane of 8 runs them), so a character off screen costs this
// pass's few lines instead. Each invocation tests kSplatListRun consecutive characters and a
// subgroup claims its place in the list with one atomic: the atomics are what this pass costs
// on lavapipe (the two threads contend for the counter), so one per subgroup of runs rather than
// per subgroup of characters. Within a subgroup the list keeps the characters' order.
// CPU twin: the characters whose mask is not empty (render::splatInputsCpu draws exactly them).
#include "shared_types.h"
#include "render_bindings.h"

layout(local_size_x = kSplatBodyGroupSize) in;
layout(std430, binding = kRenderBindingMasks) readonly buffer Masks { uvec2 masks[]; };  // CoverageMask's joint bits
layout(std430, binding = kRenderBindingOnScreenList) writeonly buffer OnScreenList { uint onScreenList[]; };
layout(std430, binding = kRenderBindingListCounts) buffer ListCounts { uint listCounts[]; };
// Copied at the top of main, as in joint_splat_walk.comp (lavapipe reads uniforms inside
// branches and loops lane by lane).
layout(push_constant) uniform Push { SplatPush pushBlock; };
SplatPush push;

void main() {
  push = pushBlock;
  uint first = gl_GlobalInvocationID.x * kSplatListRun;  // the run's first character in the chunk
  uint characters = push.jointTotal / push.jointCount;
  uint listed = 0u;  // bit k: character first + k is on screen
  [[unroll]] for (uint k = 0u; k < kSplatListRun; ++k) {
    bool onScreen = first + k < characters;
    if (onScreen && (push.flags & kDrawUseMasks) != 0u) {
      uvec2 mask = masks[2u * (push.firstCharacter + first + k)];
      onScreen = (mask.x | mask.y) != 0u;
    }
    listed |= onScreen ? 1u << k : 0u;
  }
  // Where each lane's characters go: a Hillis-Steele scan of the counts by shuffles.
  uint lane = gl_SubgroupInvocationID;
  uint count = bitCount(listed);
  uint inclusive = count;
  for (uint d = 1u; d < gl_SubgroupSize; d <<= 1u) {
    uint below = subgroupShuffle(inclusive, lane >= d ? lane - d : lane);
    inclusive += lane >= d ? below : 0u;
  }
  // The subgroup's last lane; a subgroup wider than the workgroup has only its first lanes.
  uint total = subgroupShuffle(inclusive, min(gl_SubgroupSize, gl_WorkGroupSize.x) - 1u);
  uint args = kSplatListArgsWords * push.chunk + kSplatOnScreenArgs;
  uint at = 0u;
  if (total > 0u && lane == 0u) {
    at = atomicAdd(listCounts[args], total);
    atomicMax(listCounts[args + 1u], (at + total + kSplatBodyGroupSize - 1u) / kSplatBodyGroupSize);
  }
  at = subgroupShuffle(at, 0u) + inclusive - count;
  [[unroll]] for (uint k = 0u; k < kSplatListRun; ++k)
    if ((listed & (1u << k)) != 0u) onScreenList[push.firstCharacter + at++] = first + k;
}
