#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
// The far joints, step 0: one invocation per character lists the characters on screen (any
// joint in their coverage mask; every character without masks) for joint_splat.comp, which is
// dispatched by the list's length. On lavapipe a character that returns at the first line of
// the far-body pass still costs all of its lines (every lane of 8 runs them), so a character
// off screen costs this pass's few lines instead. One atomic per subgroup; the list's order
// follows the atomics, and nothing drawn depends on it (every pixel keeps its nearest hit).
// CPU twin: the characters whose mask is not empty (render::splatInputsCpu draws exactly them).
#include "shared_types.h"
#include "render_bindings.h"

layout(local_size_x = kSplatBodyGroupSize) in;
layout(std430, binding = kRenderBindingMasks) readonly buffer Masks { uvec2 masks[]; };  // CoverageMask's joint bits
layout(std430, binding = kRenderBindingOnScreenList) writeonly buffer OnScreenList { uint onScreenList[]; };
layout(std430, binding = kRenderBindingListCounts) buffer ListCounts { uint listCounts[]; };
layout(push_constant) uniform Push { SplatPush push; };

void main() {
  uint local = gl_GlobalInvocationID.x;  // the character within the chunk
  bool listed = local * push.jointCount < push.jointTotal;
  if (listed && (push.flags & kDrawUseMasks) != 0u) {
    uvec2 mask = masks[2u * (local + push.firstCharacter)];
    listed = (mask.x | mask.y) != 0u;
  }
  uvec4 ballot = subgroupBallot(listed);
  uint total = subgroupBallotBitCount(ballot);
  uint args = kSplatListArgsWords * push.chunk + kSplatOnScreenArgs;
  uint at = 0u;
  if (total > 0u && subgroupElect()) {
    at = atomicAdd(listCounts[args], total);
    atomicMax(listCounts[args + 1u], (at + total + kSplatBodyGroupSize - 1u) / kSplatBodyGroupSize);
  }
  at = subgroupBroadcastFirst(at);
  if (listed) onScreenList[push.firstCharacter + at + subgroupBallotExclusiveBitCount(ballot)] = local;
}
