#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Pose pass, one invocation per character: per joint slerp of the slow and fast motion textures
// by w (shortest arc), hierarchy composition down the parent array, and the joint draw matrices
// A = M·O·F (DESIGN eq. 11). A character whose speed bucket is in the motion cache skips all of
// that: A = M · (cached character-space pose). CPU twins: anim::poseCharacter and
// synth::MotionCacheCpu.
#include "shared_types.h"
#include "motion_common.glsl"
#include "cache_common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer SlowMotion { vec4 slowMotion[]; };
layout(std430, binding = 1) readonly buffer FastMotion { vec4 fastMotion[]; };
layout(std430, binding = 2) readonly buffer Radius { float jointRadius[]; };
// Offsets of joints whose offset never changes: (slow, fast) at (2j, 2j + 1). Read at a
// constant index, so every lane shares one load instead of gathering per lane.
layout(std140, binding = 6) uniform ConstantOffsets { vec4 constantOffsets[128]; };
layout(std430, binding = 3) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = 4) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = 5) writeonly buffer Joints { JointMatrix joints[]; };
// The motion cache: the slot of each speed bucket (−1 when not resident) and the entries.
layout(std430, binding = 7) readonly buffer BucketSlot { int bucketSlot[]; };
layout(std430, binding = 8) readonly buffer CacheData { JointMatrix cacheData[]; };
layout(push_constant) uniform Push { PosePush push; };

#include "pose_skeleton.glsl"

// A = M · P with M = T(origin) · R_y(heading) · S(scale) and P a cached character-space matrix.
void writePlaced(uint index, JointMatrix p, float c, float s, vec3 origin, float scale) {
  joints[index].row0 = scale * (c * p.row0 + s * p.row2) + vec4(0.0, 0.0, 0.0, origin.x);
  joints[index].row1 = scale * p.row1 + vec4(0.0, 0.0, 0.0, origin.y);
  joints[index].row2 = scale * (c * p.row2 - s * p.row0) + vec4(0.0, 0.0, 0.0, origin.z);
}

void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= push.characterCount) return;
  uint i = push.firstCharacter + local;
  vec4 place = placement[i];
  vec4 m = motion[i];
  float phase = m.x, w = m.y, scale = m.w;
  int fs = int(frameAt(phase, push.slowFrames));
  int ff = int(frameAt(phase, push.fastFrames));
  uint base = local * uint(kJointCount);
  if (push.cacheEnabled != 0u) {
    int slot = bucketSlot[speedBucket(w, push.bucketWidth, uint(bucketSlot.length()))];
    if (slot >= 0) {
      // fs + ff names the (slow frame, fast frame) segment: it grows at every frame boundary.
      uint entry = (uint(slot) * push.segmentCount + uint(fs + ff)) * uint(kJointCount);
      float c = cos(place.w), s = sin(place.w);
      [[unroll]] for (int j = 0; j < kJointCount; ++j) writePlaced(base + uint(j), cacheData[entry + uint(j)], c, s, place.xyz, scale);
      return;
    }
  }
  // Row starts of this frame in the motion textures (texel (x, f) is element f·2J + x).
  composePose(base, fs * 2 * kJointCount, ff * 2 * kJointCount, makeSlerpWeights(w), w, yawQuat(place.w), place.xyz,
              scale);
}
