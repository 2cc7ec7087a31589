#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Motion cache, step 3 (an indirect dispatch, one invocation per fresh slot × row): synthesize
// the character-space pose of every entry inserted this frame at its bucket's speed, once for
// all characters that share it; row r at phase r / R, sampled continuously like the pose pass.
// With far bodies drawn, each pose's FarBodyPose too (coverage_types.h).
// CPU twin: synth::MotionCacheCpu::update.
#include "shared_types.h"
#include "synth_bindings.h"
#include "motion_common.glsl"
#include "speed_buckets.glsl"
#include "coverage_types.h"

layout(local_size_x = 64) in;
#include "motion_texels.glsl"
layout(std430, binding = kCacheFillBindingRadius) readonly buffer Radius { float jointRadius[]; };
layout(std140, binding = kCacheFillBindingConstantOffsets) uniform ConstantOffsets { vec4 constantOffsets[128]; };
layout(std430, binding = kCacheFillBindingSlotBucket) readonly buffer SlotBucket { int slotBucket[]; };
layout(std430, binding = kCacheFillBindingFreshSlots) readonly buffer FreshSlots { uint freshSlots[]; };  // [0] count
layout(std430, binding = kCacheFillBindingCacheData) buffer CacheData { JointPoint joints[]; };
layout(std140, binding = kCacheFillBindingParts) uniform Parts { CoverageParts parts; };
layout(std430, binding = kCacheFillBindingFarBodyPoses) writeonly buffer FarBodyPoses { FarBodyPose farBodyPoses[]; };
void storeJoint(uint index, vec4 point) { joints[index].positionRadius = point; }
layout(push_constant) uniform Push { CachePush push; };

#include "pose_skeleton.glsl"

// A part's centre joint's point and its bone's start (partBoneStart), from the pose this
// invocation wrote at joints[base …].
vec4 partJoint(uint base, CoveragePart part) { return joints[base + part.joint].positionRadius; }
vec4 partParent(uint base, CoveragePart part) { return joints[base + partBoneStart(part)].positionRadius; }

void main() {
  uint id = gl_GlobalInvocationID.x;
  if (id >= freshSlots[0] * push.rowCount) return;
  uint slot = freshSlots[1u + id / push.rowCount], row = id % push.rowCount;
  float w = bucketSpeed(uint(slotBucket[slot]), push.bucketWidth);
  float phase = float(row) / float(push.rowCount);  // synth::cacheRowPhase
  uint base = push.dataBase + (slot * push.rowCount + row) * uint(kJointCount);
  composePose(base, clipSample(phase, push.slowFrames), clipSample(phase, push.fastFrames), w,
              vec4(0.0, 0.0, 0.0, 1.0), vec3(0.0), 1.0, uvec2(0xFFFFFFFFu));
  if (push.farBodies == 0u) return;
  // This invocation's own stores, read back: the joints the far body is placed from.
  CoveragePart torso = parts.parts[kPartTorso], left = parts.parts[kPartLeftLeg], right = parts.parts[kPartRightLeg];
  farBodyPoses[base / uint(kJointCount)] =
      FarBodyPose(partJoint(base, torso), partParent(base, torso), partJoint(base, left), partParent(base, left),
                  partJoint(base, right), partParent(base, right));
}
