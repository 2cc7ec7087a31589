#version 450
#extension GL_GOOGLE_include_directive : require
// Cloth playback: each used state gets its pool slot (the finest level a character needs, or the
// coarsest when the fine region is full) and joins the list of states decoded at that level.
#include "cloth_types.h"
#include "cloth_bindings.h"

layout(local_size_x = 64) in;
layout(std430, binding = kClothClassifyBindingLevels) readonly buffer Levels { ClothLevel levels[]; };
layout(std430, binding = kClothClassifyBindingCounters) buffer Counters { ClothCounters counters; };
layout(std430, binding = kClothClassifyBindingStateLevel) readonly buffer StateLevel { uint stateLevel[]; };
layout(std430, binding = kClothClassifyBindingUsedStates) readonly buffer UsedStates { uint usedStates[]; };
layout(std430, binding = kClothClassifyBindingSlots) writeonly buffer Slots { uvec2 slots[]; };  // per state: (pool vertex, level)
layout(std430, binding = kClothClassifyBindingLevelLists) writeonly buffer LevelLists { uint levelLists[]; };
layout(push_constant) uniform Push { ClothClassifyPush push; };

uint slotVertices(uint level) { return (levels[level].vertices + 3u) & ~3u; }

void main() {
  uint u = gl_GlobalInvocationID.x;
  if (u >= min(counters.usedStates, push.maxUsedStates)) return;
  const uint coarsest = kClothLevelCount - 1u;
  uint state = usedStates[u];
  uint level = stateLevel[state];
  uint offset = u * slotVertices(coarsest);  // the coarse region always has room
  if (level < coarsest) {
    uint n = slotVertices(level);
    uint fine = atomicAdd(counters.fineCursor, n);
    if (fine + n <= push.fineBudget) {
      offset = push.reservedVertices + fine;
    } else {
      level = coarsest;
      atomicAdd(counters.demoted, 1u);
    }
  }
  slots[state] = uvec2(offset, level);
  uint k = atomicAdd(counters.levelStates[level], 1u);
  levelLists[level * push.maxUsedStates + k] = state;
}
