#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_KHR_shader_subgroup_vote : require
// Pose pass for the characters whose speed bucket is in the motion cache (listed by
// cache_classify.comp): no blending and no hierarchy, A = M · P with P the cached
// character-space pose of the character's (slow frame, fast frame) segment and
// M = T(origin) · R_y(heading) · S(scale). CPU twin: synth::MotionCacheCpu::pose.
#include "shared_types.h"
#include "motion_common.glsl"
#include "cache_common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 3) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = 4) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = 5) writeonly buffer Joints { JointMatrix joints[]; };
layout(std430, binding = 7) readonly buffer CharacterList { uint characterList[]; };
layout(std430, binding = 8) readonly buffer ListCounts { uint listCounts[]; };
layout(std430, binding = 9) readonly buffer BucketSlot { int bucketSlot[]; };
layout(std430, binding = 10) readonly buffer CacheData { JointMatrix cacheData[]; };
layout(std430, binding = 11) readonly buffer Masks { uvec4 masks[]; };
layout(push_constant) uniform Push { PosePush push; };

layout(constant_id = 0) const int kJointCount = 1;

void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= listCounts[push.countIndex]) return;
  uint local = characterList[push.listBase + k];
  uint i = push.firstCharacter + local;
  vec4 place = placement[i];
  vec4 m = motion[i];
  int fs = int(frameAt(m.x, push.slowFrames));
  int ff = int(frameAt(m.x, push.fastFrames));
  int slot = bucketSlot[speedBucket(m.y, push.bucketWidth, uint(bucketSlot.length()))];
  // fs + ff names the (slow frame, fast frame) segment: it grows at every frame boundary.
  uint entry = (uint(slot) * push.segmentCount + uint(fs + ff)) * uint(kJointCount);
  uint base = local * uint(kJointCount);
  float c = cos(place.w), s = sin(place.w), scale = m.w;
  uvec2 activeJoints = (push.flags & kPoseUseMasks) != 0u ? masks[i].xy : uvec2(0xFFFFFFFFu);
  [[unroll]] for (int j = 0; j < kJointCount; ++j) {
    // A subgroup-uniform skip: lavapipe runs 8 characters per SIMD group and can only jump over
    // the joint when none of them needs it; a lane that does not need it just does not write.
    bool jointNeeded = ((j < 32 ? activeJoints.x >> uint(j) : activeJoints.y >> uint(j - 32)) & 1u) != 0u;
    if (!subgroupAny(jointNeeded)) continue;
    if (!jointNeeded) continue;
    JointMatrix p = cacheData[entry + uint(j)];
    joints[base + uint(j)].row0 = scale * (c * p.row0 + s * p.row2) + vec4(0.0, 0.0, 0.0, place.x);
    joints[base + uint(j)].row1 = scale * p.row1 + vec4(0.0, 0.0, 0.0, place.y);
    joints[base + uint(j)].row2 = scale * (c * p.row2 - s * p.row0) + vec4(0.0, 0.0, 0.0, place.z);
  }
}
