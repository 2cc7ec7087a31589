// The pose of one character computed joint by joint (slerp per joint, hierarchy, joint points),
// shared by the pose pass and the motion-cache fill. The including shader declares the buffers
// this reads and writes: the motion texels (motion_texels.glsl), jointRadius, constantOffsets
// and storeJoint for the output. CPU twin: anim::poseCharacterFrames.
#ifndef THRONG_POSE_SKELETON_GLSL
#define THRONG_POSE_SKELETON_GLSL

#include "synth_bindings.h"

// The skeleton is baked into the pipeline as specialization constants (joint count and parent
// array), so the joint loop has a constant trip count and constant parent indices: the compiler
// unrolls it and keeps the hierarchy in registers instead of a per-invocation array in memory.
layout(constant_id = kPoseConstantJointCount) const int kJointCount = 1;
layout(constant_id = kPoseConstantParents + 0u) const int kParent0 = -1;
layout(constant_id = kPoseConstantParents + 1u) const int kParent1 = -1;
layout(constant_id = kPoseConstantParents + 2u) const int kParent2 = -1;
layout(constant_id = kPoseConstantParents + 3u) const int kParent3 = -1;
layout(constant_id = kPoseConstantParents + 4u) const int kParent4 = -1;
layout(constant_id = kPoseConstantParents + 5u) const int kParent5 = -1;
layout(constant_id = kPoseConstantParents + 6u) const int kParent6 = -1;
layout(constant_id = kPoseConstantParents + 7u) const int kParent7 = -1;
layout(constant_id = kPoseConstantParents + 8u) const int kParent8 = -1;
layout(constant_id = kPoseConstantParents + 9u) const int kParent9 = -1;
layout(constant_id = kPoseConstantParents + 10u) const int kParent10 = -1;
layout(constant_id = kPoseConstantParents + 11u) const int kParent11 = -1;
layout(constant_id = kPoseConstantParents + 12u) const int kParent12 = -1;
layout(constant_id = kPoseConstantParents + 13u) const int kParent13 = -1;
layout(constant_id = kPoseConstantParents + 14u) const int kParent14 = -1;
layout(constant_id = kPoseConstantParents + 15u) const int kParent15 = -1;
layout(constant_id = kPoseConstantParents + 16u) const int kParent16 = -1;
layout(constant_id = kPoseConstantParents + 17u) const int kParent17 = -1;
layout(constant_id = kPoseConstantParents + 18u) const int kParent18 = -1;
layout(constant_id = kPoseConstantParents + 19u) const int kParent19 = -1;
layout(constant_id = kPoseConstantParents + 20u) const int kParent20 = -1;
layout(constant_id = kPoseConstantParents + 21u) const int kParent21 = -1;
layout(constant_id = kPoseConstantParents + 22u) const int kParent22 = -1;
layout(constant_id = kPoseConstantParents + 23u) const int kParent23 = -1;
layout(constant_id = kPoseConstantParents + 24u) const int kParent24 = -1;
layout(constant_id = kPoseConstantParents + 25u) const int kParent25 = -1;
layout(constant_id = kPoseConstantParents + 26u) const int kParent26 = -1;
layout(constant_id = kPoseConstantParents + 27u) const int kParent27 = -1;
layout(constant_id = kPoseConstantParents + 28u) const int kParent28 = -1;
layout(constant_id = kPoseConstantParents + 29u) const int kParent29 = -1;
layout(constant_id = kPoseConstantParents + 30u) const int kParent30 = -1;
layout(constant_id = kPoseConstantParents + 31u) const int kParent31 = -1;
layout(constant_id = kPoseConstantParents + 32u) const int kParent32 = -1;
layout(constant_id = kPoseConstantParents + 33u) const int kParent33 = -1;
layout(constant_id = kPoseConstantParents + 34u) const int kParent34 = -1;
layout(constant_id = kPoseConstantParents + 35u) const int kParent35 = -1;
layout(constant_id = kPoseConstantParents + 36u) const int kParent36 = -1;
layout(constant_id = kPoseConstantParents + 37u) const int kParent37 = -1;
layout(constant_id = kPoseConstantParents + 38u) const int kParent38 = -1;
layout(constant_id = kPoseConstantParents + 39u) const int kParent39 = -1;
layout(constant_id = kPoseConstantParents + 40u) const int kParent40 = -1;
layout(constant_id = kPoseConstantParents + 41u) const int kParent41 = -1;
layout(constant_id = kPoseConstantParents + 42u) const int kParent42 = -1;
layout(constant_id = kPoseConstantParents + 43u) const int kParent43 = -1;
layout(constant_id = kPoseConstantParents + 44u) const int kParent44 = -1;
layout(constant_id = kPoseConstantParents + 45u) const int kParent45 = -1;
layout(constant_id = kPoseConstantParents + 46u) const int kParent46 = -1;
layout(constant_id = kPoseConstantParents + 47u) const int kParent47 = -1;
layout(constant_id = kPoseConstantParents + 48u) const int kParent48 = -1;
layout(constant_id = kPoseConstantParents + 49u) const int kParent49 = -1;
layout(constant_id = kPoseConstantParents + 50u) const int kParent50 = -1;
layout(constant_id = kPoseConstantParents + 51u) const int kParent51 = -1;
layout(constant_id = kPoseConstantParents + 52u) const int kParent52 = -1;
layout(constant_id = kPoseConstantParents + 53u) const int kParent53 = -1;
layout(constant_id = kPoseConstantParents + 54u) const int kParent54 = -1;
layout(constant_id = kPoseConstantParents + 55u) const int kParent55 = -1;
layout(constant_id = kPoseConstantParents + 56u) const int kParent56 = -1;
layout(constant_id = kPoseConstantParents + 57u) const int kParent57 = -1;
layout(constant_id = kPoseConstantParents + 58u) const int kParent58 = -1;
layout(constant_id = kPoseConstantParents + 59u) const int kParent59 = -1;
layout(constant_id = kPoseConstantParents + 60u) const int kParent60 = -1;
layout(constant_id = kPoseConstantParents + 61u) const int kParent61 = -1;
layout(constant_id = kPoseConstantParents + 62u) const int kParent62 = -1;
layout(constant_id = kPoseConstantParents + 63u) const int kParent63 = -1;
// True in the LOD variant of the pipeline: joints outside a character's mask are skipped. A
// constant, so the variant without LOD carries no per-joint branch at all.
layout(constant_id = kPoseConstantUseMasks) const bool kUseMasks = false;

// Bit j set: joint j's offset changes over frames (read per lane from the motion texels).
layout(constant_id = kPoseConstantAnimatedOffsets) const uint kAnimatedOffsetsLow = 1u;
layout(constant_id = kPoseConstantAnimatedOffsets + 1u) const uint kAnimatedOffsetsHigh = 0u;
bool offsetAnimated(int j) {
  return j < 32 ? ((kAnimatedOffsetsLow >> uint(j)) & 1u) != 0u : ((kAnimatedOffsetsHigh >> uint(j - 32)) & 1u) != 0u;
}

// Bit j set: joint j's bone is the same in both clips and never changes (synth::fixedBones): its
// offset and length are specialization constants (fixedBoneOffset/Length, generated), so the
// compiler folds them into the arithmetic: no square root per joint, and the zero components of
// an axis-aligned bone (most BVH skeletons have many) drop out of the rotation altogether.
layout(constant_id = kPoseConstantFixedBones) const uint kFixedBonesLow = 0u;
layout(constant_id = kPoseConstantFixedBones + 1u) const uint kFixedBonesHigh = 0u;
bool boneFixed(int j) {
  return j < 32 ? ((kFixedBonesLow >> uint(j)) & 1u) != 0u : ((kFixedBonesHigh >> uint(j - 32)) & 1u) != 0u;
}
#include "pose_bones.glsl"

// A switch rather than an array: glslang has no constant arrays of specialization constants,
// and once the loop is unrolled every call folds to one constant.
int parentOf(int j) {
  switch (j) {
    case 0: return kParent0;
    case 1: return kParent1;
    case 2: return kParent2;
    case 3: return kParent3;
    case 4: return kParent4;
    case 5: return kParent5;
    case 6: return kParent6;
    case 7: return kParent7;
    case 8: return kParent8;
    case 9: return kParent9;
    case 10: return kParent10;
    case 11: return kParent11;
    case 12: return kParent12;
    case 13: return kParent13;
    case 14: return kParent14;
    case 15: return kParent15;
    case 16: return kParent16;
    case 17: return kParent17;
    case 18: return kParent18;
    case 19: return kParent19;
    case 20: return kParent20;
    case 21: return kParent21;
    case 22: return kParent22;
    case 23: return kParent23;
    case 24: return kParent24;
    case 25: return kParent25;
    case 26: return kParent26;
    case 27: return kParent27;
    case 28: return kParent28;
    case 29: return kParent29;
    case 30: return kParent30;
    case 31: return kParent31;
    case 32: return kParent32;
    case 33: return kParent33;
    case 34: return kParent34;
    case 35: return kParent35;
    case 36: return kParent36;
    case 37: return kParent37;
    case 38: return kParent38;
    case 39: return kParent39;
    case 40: return kParent40;
    case 41: return kParent41;
    case 42: return kParent42;
    case 43: return kParent43;
    case 44: return kParent44;
    case 45: return kParent45;
    case 46: return kParent46;
    case 47: return kParent47;
    case 48: return kParent48;
    case 49: return kParent49;
    case 50: return kParent50;
    case 51: return kParent51;
    case 52: return kParent52;
    case 53: return kParent53;
    case 54: return kParent54;
    case 55: return kParent55;
    case 56: return kParent56;
    case 57: return kParent57;
    case 58: return kParent58;
    case 59: return kParent59;
    case 60: return kParent60;
    case 61: return kParent61;
    case 62: return kParent62;
    case 63: return kParent63;
  }
  return -1;
}
// An animated offset: each clip's lerped between its two rows, then the two blended by w.
vec3 animatedOffset(int slowRow, int slowNext, float ts, int fastRow, int fastNext, float tf, int j, float w) {
  vec3 slow = slowTexel(slowRow + 2 * j + 1).xyz * (1.0 - ts) + slowTexel(slowNext + 2 * j + 1).xyz * ts;
  vec3 fast = fastTexel(fastRow + 2 * j + 1).xyz * (1.0 - tf) + fastTexel(fastNext + 2 * j + 1).xyz * tf;
  return slow * (1.0 - w) + fast * w;
}

vec3 globalPosition[64];
vec4 globalRotation[64];

// Writes the kJointCount joint points of one character at joints[base …] through the includer's
// storeJoint(index, point): each clip sampled between its two rows (slerped rotations, lerped
// offsets; anim::clipSample), the two clips blended by w, placed by M = T(origin)·R(yaw)·S(scale).
// With yaw = identity, origin = 0, scale = 1 this is the character-space pose the motion cache
// stores. A point is the joint's position and its bone's drawn radius (JointPoint): the bone's
// draw matrix, which needs the bone's alignment, is left to its readers (boneMatrix).
// Joints whose bit is clear in `activeJoints` (the coverage LOD mask) are neither blended nor written;
// their children are never activeJoints (the mask keeps parents before children).
void composePose(uint base, ClipSample slow, ClipSample fast, float w, vec4 yaw, vec3 origin, float scale,
                 uvec2 activeJoints) {
  SlerpWeights weights = makeSlerpWeights(w);
  SlerpWeights slowWeights = makeSlerpWeights(slow.t), fastWeights = makeSlerpWeights(fast.t);
  // Row starts in the motion textures (texel (x, f) is element f·2J + x).
  int slowRow = slow.row * 2 * kJointCount, slowNext = slow.next * 2 * kJointCount;
  int fastRow = fast.row * 2 * kJointCount, fastNext = fast.next * 2 * kJointCount;
  // The hierarchy is composed directly in world space (root = M · root pose), which saves a
  // quaternion product and a rotation per joint over composing in character space first.
  [[unroll]] for (int j = 0; j < kJointCount; ++j) {
    // A per-lane skip: a GPU jumps over the joint when no lane of the group needs it; lavapipe
    // runs the joint with those lanes masked, so their loads and stores do not happen. (Testing
    // subgroupAny first, to jump when no lane needs it, cost lavapipe more than it saved: its
    // subgroupAny is a loop over the lanes, and 100k characters with LOD took 6% longer.)
    bool jointNeeded = !kUseMasks || ((j < 32 ? activeJoints.x >> uint(j) : activeJoints.y >> uint(j - 32)) & 1u) != 0u;
    if (!jointNeeded) continue;
    vec4 qSlow = slerpFast(slowTexel(slowRow + 2 * j), slowTexel(slowNext + 2 * j), slowWeights);
    vec4 qFast = slerpFast(fastTexel(fastRow + 2 * j), fastTexel(fastNext + 2 * j), fastWeights);
    vec4 q = slerpFast(qSlow, qFast, weights);
    vec3 o = boneFixed(j) ? fixedBoneOffset(j)
             : offsetAnimated(j) ? animatedOffset(slowRow, slowNext, slow.t, fastRow, fastNext, fast.t, j, w)
                                 : constantOffsets[2 * j].xyz * (1.0 - w) + constantOffsets[2 * j + 1].xyz * w;
    int p = parentOf(j);
    float radius = jointRadius[j];
    if (p < 0) {
      globalRotation[j] = quatMul(yaw, q);
      globalPosition[j] = origin + vec3(0.0, scale * o.y, 0.0);
    } else {
      vec4 parentRotation = globalRotation[p];
      globalPosition[j] = globalPosition[p] + quatRotate(parentRotation, scale * o);
      globalRotation[j] = quatMul(parentRotation, q);
      float len = boneFixed(j) ? fixedBoneLength(j) : length(o);
      if (len <= 1e-6) radius = 0.0;  // zero-length bones are not drawn
    }
    storeJoint(base + uint(j), vec4(globalPosition[j], scale * radius));
  }
}

#endif
