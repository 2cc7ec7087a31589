#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Pixel-coverage pass (DESIGN eqs. 1–9), one invocation per character: the screen area of the
// five part spheres decides which joints the pose pass synthesizes and the renderer draws.
// CPU twin: synth::coverageCharacter (engine/synth/coverage.cpp), mirrored operation for
// operation; the case analysis of sphereCoverage is documented there.
#include "coverage_types.h"

layout(local_size_x = 64) in;
layout(std140, binding = 0) uniform Parts { CoverageParts parts; };
layout(std430, binding = 1) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = 2) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = 3) readonly buffer Joints { JointMatrix joints[]; };  // the chunk's characters
layout(std430, binding = 4) buffer Masks { CoverageMask masks[]; };           // global index, in/out
layout(std430, binding = 5) writeonly buffer Areas { float areas[]; };        // global index × 5
layout(push_constant) uniform Push { CoveragePush push; };

const float kPi = 3.14159265358979323846;

float sphereCoverage(vec3 worldCentre, float radius) {
  vec4 v = push.view * vec4(worldCentre, 1.0);
  vec3 o = vec3(v.x, v.y, -v.z);  // camera space looking down +z
  float f = push.viewport.z;
  float nearPlane = push.viewport.w;
  float screen = push.viewport.x * push.viewport.y;
  float l2 = dot(o, o);
  float r2 = radius * radius;
  if (l2 <= r2) return screen;                        // the camera is inside
  if (o.z + radius <= nearPlane) return 0.0;          // wholly clipped (or behind the camera)
  if (abs(o.x) * push.frustum.x - o.z * push.frustum.y > radius) return 0.0;  // off a side
  if (abs(o.y) * push.frustum.z - o.z * push.frustum.w > radius) return 0.0;
  if (o.z <= radius) return screen;                   // straddles the camera plane: unbounded
  float d = o.z * o.z - r2;
  float area = kPi * f * f * r2 * sqrt(l2 - r2) / (d * sqrt(d));
  return min(area, screen);                           // the full ellipse, even partly off screen
}

void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= push.characterCount) return;
  uint i = push.firstCharacter + local;
  vec4 place = placement[i];
  float scale = motion[i].w;
  CoverageMask previous = masks[i];
  bool readJoints = (push.flags & kCoverageReadJoints) != 0u;
  float c = cos(place.w);
  float s = sin(place.w);
  uint lo = parts.baseLo;
  uint hi = parts.baseHi;
  uint activeParts = 0u;
  [[unroll]] for (uint k = 0u; k < kCoveragePartCount; ++k) {
    CoveragePart part = parts.parts[k];
    uint word = part.joint < 32u ? previous.lo : previous.hi;
    vec3 centre;
    if (readJoints && ((word >> (part.joint & 31u)) & 1u) != 0u) {
      JointMatrix a = joints[local * push.jointCount + part.joint];
      centre = vec3(a.row0.y * part.bonePoint + a.row0.w, a.row1.y * part.bonePoint + a.row1.w,
                    a.row2.y * part.bonePoint + a.row2.w);
    } else {
      vec3 m = part.centre.xyz * scale;
      centre = place.xyz + vec3(m.x * c + m.z * s, m.y, -m.x * s + m.z * c);
    }
    float area = sphereCoverage(centre, part.centre.w * scale);
    if ((push.flags & kCoverageWriteAreas) != 0u) areas[i * kCoveragePartCount + k] = area;
    if (area >= part.threshold) {
      lo |= part.maskLo;
      hi |= part.maskHi;
      activeParts |= 1u << k;
    }
  }
  uint level = (lo == parts.allLo && hi == parts.allHi) ? kLevelNear
               : ((lo == parts.baseLo && hi == parts.baseHi) ? kLevelFar : kLevelMid);
  masks[i] = CoverageMask(lo, hi, level, activeParts);
}
