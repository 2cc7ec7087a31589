// The pose of one character computed joint by joint (slerp per joint, hierarchy, draw matrices
// A = M·O·F), shared by the pose pass and the motion-cache fill. The including shader declares
// the buffers this reads and writes: the motion texels (motion_texels.glsl), jointRadius,
// constantOffsets and the output `joints`. CPU twin: anim::poseCharacterFrames.
#ifndef THRONG_POSE_SKELETON_GLSL
#define THRONG_POSE_SKELETON_GLSL

// The skeleton is baked into the pipeline as specialization constants (joint count and parent
// array), so the joint loop has a constant trip count and constant parent indices: the compiler
// unrolls it and keeps the hierarchy in registers instead of a per-invocation array in memory.
layout(constant_id = 0) const int kJointCount = 1;
layout(constant_id = 1) const int kParent0 = -1;
layout(constant_id = 2) const int kParent1 = -1;
layout(constant_id = 3) const int kParent2 = -1;
layout(constant_id = 4) const int kParent3 = -1;
layout(constant_id = 5) const int kParent4 = -1;
layout(constant_id = 6) const int kParent5 = -1;
layout(constant_id = 7) const int kParent6 = -1;
layout(constant_id = 8) const int kParent7 = -1;
layout(constant_id = 9) const int kParent8 = -1;
layout(constant_id = 10) const int kParent9 = -1;
layout(constant_id = 11) const int kParent10 = -1;
layout(constant_id = 12) const int kParent11 = -1;
layout(constant_id = 13) const int kParent12 = -1;
layout(constant_id = 14) const int kParent13 = -1;
layout(constant_id = 15) const int kParent14 = -1;
layout(constant_id = 16) const int kParent15 = -1;
layout(constant_id = 17) const int kParent16 = -1;
layout(constant_id = 18) const int kParent17 = -1;
layout(constant_id = 19) const int kParent18 = -1;
layout(constant_id = 20) const int kParent19 = -1;
layout(constant_id = 21) const int kParent20 = -1;
layout(constant_id = 22) const int kParent21 = -1;
layout(constant_id = 23) const int kParent22 = -1;
layout(constant_id = 24) const int kParent23 = -1;
layout(constant_id = 25) const int kParent24 = -1;
layout(constant_id = 26) const int kParent25 = -1;
layout(constant_id = 27) const int kParent26 = -1;
layout(constant_id = 28) const int kParent27 = -1;
layout(constant_id = 29) const int kParent28 = -1;
layout(constant_id = 30) const int kParent29 = -1;
layout(constant_id = 31) const int kParent30 = -1;
layout(constant_id = 32) const int kParent31 = -1;
layout(constant_id = 33) const int kParent32 = -1;
layout(constant_id = 34) const int kParent33 = -1;
layout(constant_id = 35) const int kParent34 = -1;
layout(constant_id = 36) const int kParent35 = -1;
layout(constant_id = 37) const int kParent36 = -1;
layout(constant_id = 38) const int kParent37 = -1;
layout(constant_id = 39) const int kParent38 = -1;
layout(constant_id = 40) const int kParent39 = -1;
layout(constant_id = 41) const int kParent40 = -1;
layout(constant_id = 42) const int kParent41 = -1;
layout(constant_id = 43) const int kParent42 = -1;
layout(constant_id = 44) const int kParent43 = -1;
layout(constant_id = 45) const int kParent44 = -1;
layout(constant_id = 46) const int kParent45 = -1;
layout(constant_id = 47) const int kParent46 = -1;
layout(constant_id = 48) const int kParent47 = -1;
layout(constant_id = 49) const int kParent48 = -1;
layout(constant_id = 50) const int kParent49 = -1;
layout(constant_id = 51) const int kParent50 = -1;
layout(constant_id = 52) const int kParent51 = -1;
layout(constant_id = 53) const int kParent52 = -1;
layout(constant_id = 54) const int kParent53 = -1;
layout(constant_id = 55) const int kParent54 = -1;
layout(constant_id = 56) const int kParent55 = -1;
layout(constant_id = 57) const int kParent56 = -1;
layout(constant_id = 58) const int kParent57 = -1;
layout(constant_id = 59) const int kParent58 = -1;
layout(constant_id = 60) const int kParent59 = -1;
layout(constant_id = 61) const int kParent60 = -1;
layout(constant_id = 62) const int kParent61 = -1;
layout(constant_id = 63) const int kParent62 = -1;
layout(constant_id = 64) const int kParent63 = -1;
// True in the LOD variant of the pipeline: joints outside a character's mask are skipped. A
// constant, so the variant without LOD carries no per-joint branch at all.
layout(constant_id = 67) const bool kUseMasks = false;

// Bit j set: joint j's offset changes over frames (read per lane from the motion texels).
layout(constant_id = 65) const uint kAnimatedOffsetsLow = 1u;
layout(constant_id = 66) const uint kAnimatedOffsetsHigh = 0u;
bool offsetAnimated(int j) {
  return j < 32 ? ((kAnimatedOffsetsLow >> uint(j)) & 1u) != 0u : ((kAnimatedOffsetsHigh >> uint(j - 32)) & 1u) != 0u;
}

// Bit j set: joint j's bone is the same in both clips and never changes (synth::fixedBones): its
// offset, length and the rotation aligning +y with it are specialization constants
// (fixedBoneOffset/Length/Align, generated), so the compiler folds them into the arithmetic:
// no square root, division or alignYTo per joint, and the zero components of an axis-aligned
// bone (most BVH skeletons have many) drop out of the rotations altogether.
layout(constant_id = 68) const uint kFixedBonesLow = 0u;
layout(constant_id = 69) const uint kFixedBonesHigh = 0u;
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

void writeRows(uint index, vec4 q, vec3 scale, vec3 t) {
  float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  vec4 row0 = vec4((1.0 - 2.0 * (yy + zz)) * scale.x, 2.0 * (xy - wz) * scale.y, 2.0 * (xz + wy) * scale.z, t.x);
  vec4 row1 = vec4(2.0 * (xy + wz) * scale.x, (1.0 - 2.0 * (xx + zz)) * scale.y, 2.0 * (yz - wx) * scale.z, t.y);
  vec4 row2 = vec4(2.0 * (xz - wy) * scale.x, 2.0 * (yz + wx) * scale.y, (1.0 - 2.0 * (xx + yy)) * scale.z, t.z);
  storeJoint(index, row0, row1, row2);
}

// Writes the kJointCount draw matrices of one character at joints[base …]: each clip sampled
// between its two rows (slerped rotations, lerped offsets; anim::clipSample), the two clips
// blended by w, placed by M = T(origin)·R(yaw)·S(scale). With yaw = identity, origin = 0,
// scale = 1 this is the character-space pose the motion cache stores.
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
    vec3 start;
    vec4 orientation;
    float len;
    if (p < 0) {
      // The root is drawn as a sphere around it: a vertical "bone" of length 2r.
      globalRotation[j] = quatMul(yaw, q);
      globalPosition[j] = origin + vec3(0.0, scale * o.y, 0.0);
      start = globalPosition[j] + quatRotate(globalRotation[j], vec3(0.0, -scale * radius, 0.0));
      orientation = globalRotation[j];
      len = 2.0 * radius;
    } else {
      vec4 parentRotation = globalRotation[p];
      vec3 parentPosition = globalPosition[p];
      globalPosition[j] = parentPosition + quatRotate(parentRotation, scale * o);
      globalRotation[j] = quatMul(parentRotation, q);
      vec4 align;
      if (boneFixed(j)) {
        len = fixedBoneLength(j);
        align = fixedBoneAlign(j);
      } else {
        len = length(o);
        align = alignYTo(len > 1e-6 ? o / len : vec3(0.0, 1.0, 0.0));
      }
      start = parentPosition;
      orientation = quatMul(parentRotation, align);
      if (len <= 1e-6) radius = 0.0;  // zero-length bones are not drawn
    }
    writeRows(base + uint(j), orientation, scale * vec3(radius, len, radius), start);
  }
}

#endif
