#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
// The update-rate LOD's schedule (update_rate.h), one invocation per chunk: lists the chunks
// that move this step with the seconds since their last move, resets their largest height (the
// scheduled root motion raises it again) and counts the list in the indirect dispatch's x, which
// the host zeroes first. One atomic per subgroup: on lavapipe the two threads contend for it.
// CPU twin: synth::UpdateScheduleCpu::schedule.
#include "shared_types.h"
#include "synth_bindings.h"
#include "update_rate.h"

layout(local_size_x = 64) in;
layout(std430, binding = kUpdateScheduleBindingChunkState) buffer State { uvec2 chunkState[]; };
layout(std430, binding = kUpdateScheduleBindingChunkList) writeonly buffer List { uvec2 chunkList[]; };
layout(std430, binding = kUpdateScheduleBindingArgs) buffer Args { uint args[]; };
layout(push_constant) uniform Push { UpdateSchedulePush push; };

void main() {
  uint chunk = gl_GlobalInvocationID.x;
  if (chunk >= push.chunkCount) return;
  uvec2 state = chunkState[chunk];
  uint interval = updateInterval(uintBitsToFloat(state.x), push.lagPerHeight, push.maxLag, push.maxInterval);
  bool due = updateDue(push.step, state.y, chunk, interval, push.blockShift);
  uvec4 ballot = subgroupBallot(due);
  uint total = subgroupBallotBitCount(ballot);
  uint at = 0u;
  if (subgroupElect() && total > 0u) at = atomicAdd(args[0], total);
  at = subgroupBroadcastFirst(at) + subgroupBallotExclusiveBitCount(ballot);
  if (!due) return;
  // At most maxInterval steps pass between two moves: the schedule runs every step.
  uint elapsed = min(push.step - state.y, kUpdateMaxInterval);
  chunkList[at] = uvec2(chunk, floatBitsToUint(push.sinceSeconds[elapsed - 1u]));
  chunkState[chunk] = uvec2(0u, push.step);
}
