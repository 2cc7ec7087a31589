#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Pose pass, one invocation per character: per joint, each motion texture slerped between the
// two rows on either side of the phase (continuous sampling, no judder), then slow and fast
// slerped by w (shortest arc); hierarchy composition down the parent array, and each joint's
// point (the draw matrix A = M·O·F of the paper's eq. 11 follows from it and its parent's,
// shared_types.h boneMatrix; docs/design.md). CPU twin: anim::poseCharacter. Characters whose speed bucket is in
// the motion cache skip all of that in synth_pose_cached.comp.
#include "shared_types.h"
#include "synth_bindings.h"
#include "motion_common.glsl"

layout(local_size_x = 64) in;
#include "motion_texels.glsl"
layout(std430, binding = kPoseBindingRadius) readonly buffer Radius { float jointRadius[]; };
// Offsets of joints whose offset never changes: (slow, fast) at (2j, 2j + 1). Read at a
// constant index, so every lane shares one load instead of gathering per lane.
layout(std140, binding = kPoseBindingConstantOffsets) uniform ConstantOffsets { vec4 constantOffsets[128]; };
// Read as 64-bit words too (two per vec4, see motion_texels.glsl).
layout(std430, binding = kPoseBindingPlacement) readonly buffer Placement { u64vec2 placement[]; };
layout(std430, binding = kPoseBindingMotion) readonly buffer Motion { u64vec2 motion[]; };
// One JointPoint per joint: a single 16-byte store, the least a joint can take (shared_types.h).
layout(std430, binding = kPoseBindingJoints) writeonly buffer Joints { JointPoint joints[]; };
// Whether this invocation has a character: main has no early return, because lavapipe reads
// every uniform after one (the constant offsets, the push constants) lane by lane; only the
// stores are skipped.
bool poseActive = false;
void storeJoint(uint index, vec4 point) {
  if (poseActive) joints[index].positionRadius = point;
}
// With the motion cache on, only the characters whose bucket is not resident are posed here,
// listed by cache_classify.comp.
layout(std430, binding = kPoseBindingCharacterList) readonly buffer CharacterList { uint characterList[]; };
layout(std430, binding = kPoseBindingListCounts) readonly buffer ListCounts { uint listCounts[]; };
// Coverage LOD (the kUseMasks variant): the joints each character needs this frame.
layout(std430, binding = kPoseBindingMasks) readonly buffer Masks { u64vec2 masks[]; };  // the joint bits in .x
layout(push_constant) uniform Push { PosePush push; };

#include "pose_skeleton.glsl"

void main() {
  uint local = gl_GlobalInvocationID.x;
  bool listed = push.fromList != 0u;
  poseActive = local < (listed ? listCounts[push.countIndex] : push.characterCount);
  // An invocation past the count reads character 0's (or the list's first) inputs and stores nothing.
  local = poseActive ? local : 0u;
  local = listed ? characterList[push.listBase + local] : local;
  uint i = push.firstCharacter + local;
  vec4 place = fromWords(placement[i]);
  vec4 m = fromWords(motion[i]);
  float phase = cyclePhase(m), w = speedWeight(m), scale = characterScale(m);
  uint base = local * uint(kJointCount);
  uvec2 activeJoints = kUseMasks ? unpackUint2x32(masks[i].x) : uvec2(0xFFFFFFFFu);
  composePose(base, clipSample(phase, push.slowFrames), clipSample(phase, push.fastFrames), w, yawQuat(place.w),
              place.xyz, scale, activeJoints);
}
