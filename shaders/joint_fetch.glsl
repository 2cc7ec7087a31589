// The joint matrix the renderer draws: from the joints buffer (synthesized this frame), or,
// for a character whose speed bucket is in the motion cache, composed here from its cache
// entry and its own root transform (the synthesis passes write nothing per joint for it).
// Needs a `joints` buffer declared by the includer and push.flags.
#ifndef THRONG_JOINT_FETCH_GLSL
#define THRONG_JOINT_FETCH_GLSL
#include "cached_pose.glsl"
#include "render_bindings.h"

layout(std430, binding = kRenderBindingPlacement) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = kRenderBindingMotion) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = kRenderBindingPoseSource) readonly buffer PoseSource { uint poseSource[]; };
layout(std430, binding = kRenderBindingCacheData) readonly buffer CacheData { JointMatrix cacheData[]; };

// chunkJoint indexes the chunk's joints binding; character is global.
JointMatrix fetchJoint(uint chunkJoint, uint character, uint joint, uint flags) {
  if ((flags & kDrawCachedPoses) != 0u) {
    uint source = poseSource[character];
    if (source != kPoseInJoints)
      return placeCachedJoint(cacheData[source + joint], placement[character], characterScale(motion[character]));
  }
  return joints[chunkJoint];
}
#endif
