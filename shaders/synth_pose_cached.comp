#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Materializes the joint points of cached characters into the joints buffer (M · p for the
// entry cache_classify.comp chose). The frame path does not need it (the renderer places the
// same points itself); consumers that want every joint in one buffer (tests, exports) do. CPU twin: synth::MotionCacheCpu::pose.
#include "shared_types.h"
#include "synth_bindings.h"
#include "cached_pose.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = kPoseCachedBindingPlacement) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = kPoseCachedBindingMotion) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = kPoseCachedBindingJoints) writeonly buffer Joints { JointPoint joints[]; };
layout(std430, binding = kPoseCachedBindingPoseSource) readonly buffer PoseSource { uint poseSource[]; };
layout(std430, binding = kPoseCachedBindingCacheData) readonly buffer CacheData { JointPoint cacheData[]; };
layout(std430, binding = kPoseCachedBindingMasks) readonly buffer Masks { uvec4 masks[]; };
layout(push_constant) uniform Push { PosePush push; };

layout(constant_id = kPoseCachedConstantJointCount) const int kJointCount = 1;

void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= push.characterCount) return;
  uint i = push.firstCharacter + local;
  uint source = poseSource[i];
  if (source == kPoseInJoints) return;
  CachedPlacement placed = cachedPlacement(placement[i], characterScale(motion[i]));
  uint base = local * uint(kJointCount);
  uvec2 activeJoints = (push.flags & kPoseUseMasks) != 0u ? masks[i].xy : uvec2(0xFFFFFFFFu);
  [[unroll]] for (int j = 0; j < kJointCount; ++j) {
    bool jointNeeded = ((j < 32 ? activeJoints.x >> uint(j) : activeJoints.y >> uint(j - 32)) & 1u) != 0u;
    if (jointNeeded)
      joints[base + uint(j)].positionRadius = placeCachedPoint(cacheData[source + uint(j)].positionRadius, placed);
  }
}
