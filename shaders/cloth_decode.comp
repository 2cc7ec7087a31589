#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_shuffle : require
// Cloth playback: decode B'·c' + mean for the used states only, at the level they were classified
// at (the coarse-first vertex prefix and the first bases of that level), into the vertex pool;
// characters in the same state share it. One dispatch per level, one invocation per state: every
// invocation walks the same rows and bases. Twin: secondary::decodeStateSubset (same summation
// order).
#include "cloth_types.h"
#include "cloth_bindings.h"

layout(local_size_x = 8) in;  // kClothDecodeGroup: one lavapipe subgroup, so a few states spread over threads
layout(constant_id = kClothDecodeConstantLanes) const uint kLanes = 8u;  // rows shared per round: min(subgroup size, 8)
layout(std430, binding = kClothDecodeBindingMean) readonly buffer Mean { vec4 mean[]; };  // rows, coarse-first order
layout(std430, binding = kClothDecodeBindingBases) readonly buffer Bases { vec4 bases[]; };  // b × rowVectors
layout(std430, binding = kClothDecodeBindingCoefficients) readonly buffer Coefficients { float coefficients[]; };  // S × b
layout(std430, binding = kClothDecodeBindingLevels) readonly buffer Levels { ClothLevel levels[]; };
layout(std430, binding = kClothDecodeBindingCounters) readonly buffer Counters { ClothCounters counters; };
layout(std430, binding = kClothDecodeBindingLevelLists) readonly buffer LevelLists { uint levelLists[]; };
layout(std430, binding = kClothDecodeBindingSlots) readonly buffer Slots { uvec2 slots[]; };
layout(std430, binding = kClothDecodeBindingPool) buffer Pool { vec4 pool[]; };
layout(push_constant) uniform Push { ClothDecodePush push; };

void main() {
  // Surplus lanes of a partly used subgroup redo the last state (identical writes), so every lane
  // runs the same loops and the shuffles below see every lane; wholly surplus subgroups leave.
  uint count = counters.levelStates[push.level];
  if (gl_GlobalInvocationID.x - gl_SubgroupInvocationID >= count) return;
  uint k = min(gl_GlobalInvocationID.x, count - 1u);
  uint state = levelLists[push.level * push.maxUsedStates + k];
  uint out0 = 3u * slots[state].x / 4u;
  ClothLevel level = levels[push.level];
  uint rows = (3u * level.vertices + 3u) / 4u;
  uint c0 = state * push.basisCount;
  uint lane = gl_SubgroupInvocationID % kLanes;
  // A block of kLanes rows: each lane loads one row of a basis (one gather brings kLanes useful
  // rows; lavapipe gathers lane by lane), every lane takes all of them by shuffles from constant
  // lanes (lavapipe 22.3 makes subgroupBroadcast a search for the first active lane) and adds
  // them with its own state's coefficient.
  for (uint j0 = 0u; j0 < rows; j0 += kLanes) {
    vec4 acc[8];
    vec4 m = mean[j0 + lane];
    [[unroll]] for (uint r = 0u; r < 8u; ++r) if (r < kLanes) acc[r] = subgroupShuffle(m, r);
    for (uint i = 0u; i < level.bases; ++i) {
      float ci = coefficients[c0 + i];
      vec4 row = bases[i * push.rowVectors + j0 + lane];
      [[unroll]] for (uint r = 0u; r < 8u; ++r) if (r < kLanes) acc[r] += subgroupShuffle(row, r) * ci;
    }
    [[unroll]] for (uint r = 0u; r < 8u; ++r)
      if (r < kLanes && j0 + r < rows) pool[out0 + j0 + r] = acc[r];
  }
}
