#version 450
#extension GL_GOOGLE_include_directive : require
// Cloth playback: indirect sizes. Mode 0 (after the mark pass): the classify pass, one invocation
// per used state. Mode 1 (after classify): the decode pass of each level, one invocation per state
// decoded there, and the splat, one invocation per splatted cape.
#include "cloth_types.h"
#include "cloth_bindings.h"

layout(local_size_x = 1) in;
layout(std430, binding = kClothArgsBindingCounters) readonly buffer Counters { ClothCounters counters; };
layout(std430, binding = kClothArgsBindingDraws) readonly buffer Draws { uint draws[]; };
layout(std430, binding = kClothArgsBindingDispatchArgs) writeonly buffer DispatchArgs { uint dispatchArgs[]; };
layout(push_constant) uniform Push { ClothArgsPush push; };

void write(uint at, uint invocations, uint group) {
  dispatchArgs[at] = min((invocations + group - 1u) / group, kClothMaxGroups);
  dispatchArgs[at + 1u] = 1u;
  dispatchArgs[at + 2u] = 1u;
}

void main() {
  if (push.mode == 0u) {
    write(0u, min(counters.usedStates, push.maxUsedStates), 64u);
    return;
  }
  for (uint level = 0u; level < kClothLevelCount; ++level)
    write(3u + 3u * level, counters.levelStates[level], kClothDecodeGroup);
  write(3u + 3u * kClothLevelCount, draws[5u * kClothSplatLevel + 1u], 64u);
}
