// The pixel-coverage math (DESIGN eqs. 1–9) as functions of explicit inputs, so any pass that
// already walks the characters (e.g. root motion) can include it instead of a separate
// dispatch. Needs coverage_types.h first. Mirrors engine/synth/coverage.cpp operation for
// operation; the case analysis of sphereCoverage is documented there.
#ifndef THRONG_COVERAGE_COMMON_GLSL
#define THRONG_COVERAGE_COMMON_GLSL

const float kCoveragePi = 3.14159265358979323846;

// view: world → camera (looks down −z); viewport: W, H, f, near; frustum: CoveragePush.frustum.
float sphereCoverage(mat4 view, vec4 viewport, vec4 frustum, vec3 worldCentre, float radius) {
  vec4 v = view * vec4(worldCentre, 1.0);
  vec3 o = vec3(v.x, v.y, -v.z);  // camera space looking down +z
  float f = viewport.z;
  float nearPlane = viewport.w;
  float screen = viewport.x * viewport.y;
  float l2 = dot(o, o);
  float r2 = radius * radius;
  if (l2 <= r2) return screen;                                      // the camera is inside
  if (o.z + radius <= nearPlane) return 0.0;                        // wholly clipped or behind
  if (abs(o.x) * frustum.x - o.z * frustum.y > radius) return 0.0;  // off a side
  if (abs(o.y) * frustum.z - o.z * frustum.w > radius) return 0.0;
  if (o.z <= radius) return screen;                                 // straddles the camera plane
  float d = o.z * o.z - r2;
  float area = kCoveragePi * f * f * r2 * sqrt(l2 - r2) / (d * sqrt(d));
  return min(area, screen);  // the full ellipse, even partly off screen
}

// A centre joint the pose pass did not write: its mean character-space position placed like
// the root (c, s: cosine and sine of the heading).
vec3 estimatedCentre(CoveragePart part, vec3 origin, float c, float s, float scale) {
  vec3 m = part.centre.xyz * scale;
  return origin + vec3(m.x * c + m.z * s, m.y, -m.x * s + m.z * c);
}

// The joint position A·(0, bonePoint, 0, 1) of a joint draw matrix.
vec3 jointCentre(JointMatrix a, float bonePoint) {
  return vec3(a.row0.y * bonePoint + a.row0.w, a.row1.y * bonePoint + a.row1.w, a.row2.y * bonePoint + a.row2.w);
}

CoverageMask finishMask(CoverageParts parts, uint lo, uint hi, uint activeParts) {
  uint level = (lo == parts.allLo && hi == parts.allHi) ? kLevelNear
               : ((lo == parts.baseLo && hi == parts.baseHi) ? kLevelFar : kLevelMid);
  return CoverageMask(lo, hi, level, activeParts);
}

#endif
