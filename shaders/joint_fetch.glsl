// The joint matrix the renderer draws, rebuilt from two joint points (the joint's and its
// parent's, shared_types.h JointPoint): from the joints buffer (synthesized this frame), or, for
// a character whose speed bucket is in the motion cache, placed here from its cache entry by its
// own root transform (the synthesis passes write nothing per joint for it).
// Needs a `joints` buffer of JointPoint and the `frame` uniforms declared by the includer, and
// push.flags.
#ifndef THRONG_JOINT_FETCH_GLSL
#define THRONG_JOINT_FETCH_GLSL
#include "cached_pose.glsl"
#include "render_bindings.h"

layout(std430, binding = kRenderBindingPlacement) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = kRenderBindingMotion) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = kRenderBindingPoseSource) readonly buffer PoseSource { uint poseSource[]; };
layout(std430, binding = kRenderBindingCacheData) readonly buffer CacheData { JointPoint cacheData[]; };

// What fetchJoint reads once per character rather than once per joint: where its pose comes
// from and, for a cached pose, its root transform.
struct CharacterPose {
  uint source;  // kPoseInJoints, or the character's first point in cacheData
  CachedPlacement placed;
};

CharacterPose characterPose(uint character, uint flags) {
  CharacterPose pose = CharacterPose(kPoseInJoints, CachedPlacement(vec3(0.0), vec2(1.0, 0.0), 1.0));
  if ((flags & kDrawCachedPoses) == 0u) return pose;
  pose.source = poseSource[character];
  if (pose.source != kPoseInJoints)
    pose.placed = cachedPlacement(placement[character], characterScale(motion[character]));
  return pose;
}

// Joint j's parent (FrameUniforms.jointParents), -1 for the root.
int jointParent(uint j) {
  uint parent = (frame.jointParents[j / 16u][(j / 4u) % 4u] >> (8u * (j % 4u))) & 255u;
  return parent == kNoParent ? -1 : int(parent);
}

// chunkJoint indexes the chunk's joints binding.
vec4 fetchPosePoint(CharacterPose pose, uint chunkJoint, uint joint) {
  if (pose.source != kPoseInJoints) return placeCachedPoint(cacheData[pose.source + joint].positionRadius, pose.placed);
  return joints[chunkJoint].positionRadius;
}

JointMatrix fetchPoseJoint(CharacterPose pose, uint chunkJoint, uint joint) {
  int parent = jointParent(joint);
  vec4 point = fetchPosePoint(pose, chunkJoint, joint);
  if (parent < 0) return boneMatrix(point, point, true);
  return boneMatrix(fetchPosePoint(pose, chunkJoint - joint + uint(parent), uint(parent)), point, false);
}

// chunkJoint indexes the chunk's joints binding; character is global.
JointMatrix fetchJoint(uint chunkJoint, uint character, uint joint, uint flags) {
  return fetchPoseJoint(characterPose(character, flags), chunkJoint, joint);
}
#endif
