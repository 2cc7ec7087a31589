#version 450
#extension GL_GOOGLE_include_directive : require
// The scheduled classify's dispatch (cache_classify_scheduled.comp): a workgroup per chunk the
// schedule listed, or per chunk of the crowd when the cache filled an entry this step (it may
// have evicted one that a still character's pose source names). One invocation.
#include "shared_types.h"
#include "synth_bindings.h"
#include "update_rate.h"

layout(local_size_x = 1) in;
layout(std430, binding = kClassifyArgsBindingFreshSlots) readonly buffer Fresh { uint freshSlots[]; };
layout(std430, binding = kClassifyArgsBindingSchedule) readonly buffer Schedule { uint scheduleArgs[]; };
layout(std430, binding = kClassifyArgsBindingArgs) writeonly buffer Args { ScheduledClassifyArgs args; };
layout(push_constant) uniform Push { uint chunkCount; } push;

void main() {
  bool all = freshSlots[0] > 0u;
  args = ScheduledClassifyArgs(all ? push.chunkCount : scheduleArgs[0], 1u, 1u, all ? 1u : 0u);
}
