#version 450
#extension GL_GOOGLE_include_directive : require
// Pose pass, one invocation per character: per joint slerp of the slow and fast motion textures
// by w (shortest arc), hierarchy composition down the parent array, and the joint draw matrices
// A = M·O·F (DESIGN eq. 11). CPU twin: anim::poseCharacter.
#include "shared_types.h"
#include "motion_common.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D slowMotion;
layout(binding = 1) uniform sampler2D fastMotion;
layout(std430, binding = 2) readonly buffer Parents { int parents[]; };
layout(std430, binding = 3) readonly buffer Radius { float jointRadius[]; };
layout(std430, binding = 4) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = 5) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = 6) writeonly buffer Joints { JointMatrix joints[]; };
layout(push_constant) uniform Push { PosePush push; };

const uint kMaxJoints = 64;
vec3 globalPosition[kMaxJoints];
vec4 globalRotation[kMaxJoints];

void writeRows(uint index, vec4 q, vec3 scale, vec3 t) {
  float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  joints[index].row0 = vec4((1.0 - 2.0 * (yy + zz)) * scale.x, 2.0 * (xy - wz) * scale.y, 2.0 * (xz + wy) * scale.z, t.x);
  joints[index].row1 = vec4(2.0 * (xy + wz) * scale.x, (1.0 - 2.0 * (xx + zz)) * scale.y, 2.0 * (yz - wx) * scale.z, t.y);
  joints[index].row2 = vec4(2.0 * (xz - wy) * scale.x, 2.0 * (yz + wx) * scale.y, (1.0 - 2.0 * (xx + yy)) * scale.z, t.z);
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
  vec4 yaw = yawQuat(place.w);
  vec3 origin = place.xyz;
  uint base = local * push.jointCount;
  for (uint j = 0; j < push.jointCount; ++j) {
    vec4 q = slerpFast(texelFetch(slowMotion, ivec2(2 * j, fs), 0), texelFetch(fastMotion, ivec2(2 * j, ff), 0), w);
    vec3 o = texelFetch(slowMotion, ivec2(2 * j + 1, fs), 0).xyz * (1.0 - w) +
             texelFetch(fastMotion, ivec2(2 * j + 1, ff), 0).xyz * w;
    int p = parents[j];
    float radius = jointRadius[j];
    vec3 start;
    vec4 orientation;
    float len;
    if (p < 0) {
      globalPosition[j] = vec3(0.0, o.y, 0.0);
      globalRotation[j] = q;
      start = globalPosition[j] + quatRotate(q, vec3(0.0, -radius, 0.0));
      orientation = q;
      len = 2.0 * radius;
    } else {
      vec4 parentRotation = globalRotation[p];
      vec3 parentPosition = globalPosition[p];
      globalPosition[j] = parentPosition + quatRotate(parentRotation, o);
      globalRotation[j] = quatMul(parentRotation, q);
      len = length(o);
      vec3 dir = len > 1e-6 ? o / len : vec3(0.0, 1.0, 0.0);
      start = parentPosition;
      orientation = quatMul(parentRotation, alignYTo(dir));
      if (len <= 1e-6) radius = 0.0;
    }
    vec4 world = quatMul(yaw, orientation);
    vec3 t = origin + quatRotate(yaw, scale * start);
    writeRows(base + j, world, scale * vec3(radius, len, radius), t);
  }
}
