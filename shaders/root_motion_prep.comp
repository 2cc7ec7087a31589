#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Before root motion, on the steps that need it (RootMotionJob and GroupRootMotionJob record it):
// circle steering aims each heading at the circle's tangent, and a speed epoch gives every
// character a new target speed weight. Root motion then moves the character along that heading
// and takes the target at the end of its cycle, the order anim::stepCharacter keeps (its
// displacement does not depend on the target). A pass of its own because lavapipe runs every
// line of root motion for every character on every step. CPU twin: anim::stepCharacter.
#include "shared_types.h"
#include "synth_bindings.h"
#include "motion_common.glsl"
#include "speed_buckets.glsl"
#include "words64.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = kRootMotionBindingPlacement) buffer Placement { u64vec2 placementWords[]; };
layout(std430, binding = kRootMotionBindingMotion) buffer Motion { u64vec2 motionWords[]; };
layout(push_constant) uniform Push { RootMotionPrepPush push; };

void main() {
  if (gl_GlobalInvocationID.x >= push.characterCount) return;
  uint i = push.firstCharacter + gl_GlobalInvocationID.x;
  if (push.steering == 1u) {
    vec4 place = fromWords(placementWords[i]);
    place.w = atan(-place.z, place.x);
    placementWords[i] = toWords(place);
  }
  if (push.retargetEpoch > 0u) {
    vec4 m = fromWords(motionWords[i]);
    float target = retargetSpeed(i, push.retargetEpoch, push.seed, push.minSpeedWeight, push.maxSpeedWeight);
    m = withTargetSpeedWeight(m, push.bucketWidth > 0.0 ? quantizeSpeed(target, push.bucketWidth) : target);
    motionWords[i] = toWords(m);
  }
}
