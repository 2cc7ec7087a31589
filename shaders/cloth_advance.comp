#version 450
#extension GL_GOOGLE_include_directive : require
// Cloth playback, pass 1: each character's cloth state follows its own traversal of the
// secondary graph (twin: secondary::advanceCharacter).
#include "cloth_common.glsl"
#include "cloth_bindings.h"

layout(local_size_x = 64) in;
layout(std430, binding = kClothAdvanceBindingMotion) readonly buffer Motion { vec4 motion[]; };  // (phase, w, wTarget, scale)
layout(std430, binding = kClothAdvanceBindingCharacters) buffer Characters { ClothCharacter characters[]; };
layout(std430, binding = kClothAdvanceBindingGraph) readonly buffer Graph { uint graph[]; };
layout(push_constant) uniform Push { ClothAdvancePush push; };

uint table(uint which, uint index) { return graph[graph[which] + index]; }

uint characterNode(vec4 m) {
  uint bucket = speedBucket(speedWeight(m), push.bucketWidth, push.bucketCount);
  uint first = table(kTableRunFirst, bucket);
  uint frames = table(kTableRunFirst, bucket + 1u) - first;
  if (frames == 0u) return kClothNone;
  uint frame = min(uint(max(cyclePhase(m), 0.0) * float(frames)), frames - 1u);
  return table(kTableRunNodes, first + frame);
}

uint successorIndex(uint from, uint to) {
  uint begin = table(kTableFirstSuccessor, from), end = table(kTableFirstSuccessor, from + 1u);
  for (uint e = begin; e < end; ++e)
    if (table(kTableSuccessors, e) == to) return e - begin;
  return kClothNone;
}

// A new blend starts from `shown` only when none is under way; one under way goes on.
void startBlend(inout ClothCharacter c, uint shown) {
  if (c.countdown > 0u) {
    c.countdown -= 1u;
    return;
  }
  c.blendSource = shown;
  c.countdown = push.blendFrames;
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.characterCount) return;
  ClothCharacter c = characters[i];
  uint target = characterNode(motion[i]);
  if (target == kClothNone || target == c.node) return;
  if (c.node != kClothNone && c.state != kClothNone) {
    ClothCharacter walk = c;
    for (uint step = 0u; step < push.maxWalkSteps; ++step) {
      uint k = successorIndex(walk.node, target);
      bool arrived = k != kClothNone;
      if (!arrived) k = table(kTableNaturalSuccessor, walk.node);
      if (k == kClothNone) break;
      uint edge = table(kTableFirstEdge, walk.state) + k;
      if (table(kTableEdgeIsMerge, edge) != 0u) {
        startBlend(walk, walk.state);
      } else if (walk.countdown > 0u) {
        walk.countdown -= 1u;
      }
      walk.state = table(kTableEdgeTarget, edge);
      walk.node = table(kTableSuccessors, table(kTableFirstSuccessor, walk.node) + k);
      if (arrived) {
        characters[i] = walk;
        return;
      }
    }
  }
  uint state = table(kTableFirstStateAtNode, target);
  if (state == kClothNone) return;
  if (c.state != kClothNone) startBlend(c, c.state);
  c.state = state;
  c.node = target;
  characters[i] = c;
}
