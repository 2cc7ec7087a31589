// The pixel-coverage math (the paper's eqs. 1–9, docs/design.md) as functions of explicit inputs, so any pass that
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

// A part's centre A·(0, bonePoint, 0, 1) of its joint's draw matrix, from the joint's point and its
// parent's (the root's own twice).
vec3 jointCentre(CoveragePart part, vec4 parent, vec4 joint) { return bonePoint(parent, joint, part.parent < 0, part.bonePoint); }

// World → camera space looking down +z.
vec3 cameraSpace(mat4 view, vec3 world) {
  vec4 v = view * vec4(world, 1.0);
  return vec3(v.x, v.y, -v.z);
}

// Whether a sphere at camera-space `o` meets the view frustum: the same case analysis as
// sphereCoverage without the area (its area is > 0 exactly when this holds).
bool sphereInFrustum(vec4 viewport, vec4 frustum, vec3 o, float radius) {
  if (dot(o, o) <= radius * radius) return true;
  if (o.z + radius <= viewport.w) return false;
  if (abs(o.x) * frustum.x - o.z * frustum.y > radius) return false;
  if (abs(o.y) * frustum.z - o.z * frustum.w > radius) return false;
  return true;
}

// The character's standing height on screen in pixels: f·H/z at the depth z of its middle
// (camera space); a character whose middle is nearer than half its height (or behind the
// camera) counts as huge.
float projectedHeight(vec4 viewport, vec3 middle, float height) {
  return middle.z > 0.5 * height ? viewport.z * height / middle.z : 1.0e9;
}

// Whether any of a character `height` tall whose middle is at camera-space `middle` can be on
// screen: a sphere around its middle reaching 0.8 of its height (raised arms, long strides)
// meets the frustum.
bool bodyOnScreen(vec4 viewport, vec4 frustum, vec3 middle, float height) {
  return sphereInFrustum(viewport, frustum, middle, 0.8 * height);
}

// bodyOnScreen's sphere grown by `reach` of the height: whether the body can be on screen once
// it has moved that far (the update-rate LOD's test, update_rate.h).
bool bodyWithinReach(vec4 viewport, vec4 frustum, vec3 middle, float height, float reach) {
  return sphereInFrustum(viewport, frustum, middle, (0.8 + reach) * height);
}

// The level for projected height h, starting from `level`: up while h reaches the next level's
// entry height, down while h is under the level's leaving height (hysteresis between them).
// heights: entry heights of levels 1 and 2, then their leaving heights (levelHeights). Written
// out for the three levels: a per-lane index into a uniform buffer (or a whole uniform struct
// passed by value) costs a gather per lane on lavapipe.
uint levelForHeight(vec4 heights, uint level, float h) {
  if (level == 0u && h >= heights.x) level = 1u;
  if (level == 1u && h >= heights.y) level = 2u;
  if (level == 2u && h < heights.w) level = 1u;
  if (level == 1u && h < heights.z) level = 0u;
  return level;
}

vec4 levelHeights(CoverageLevel mid, CoverageLevel near) {
  return vec4(mid.enterHeight, near.enterHeight, mid.leaveHeight, near.leaveHeight);
}

// Level, timer and phase from last frame's state: the level follows the height, but a visible
// character changes level only at the end of a walk cycle (the phase wraps) and at least
// body.y seconds after its last change; a character off screen changes at once (nothing
// pops), still at most once per body.y seconds. The time since the last change comes from the
// phase advance and the blended cycle duration. body: CoverageParts.body.
uvec2 nextLevel(vec4 body, vec4 heights, CoverageMask previous, vec4 motion, float h, bool visible) {
  uint state = previous.state;
  bool initialized = (state & kStateInitialized) != 0u;
  float previousPhase = float(state >> kStatePhaseShift) / 65535.0;
  float advance = cyclePhase(motion) - previousPhase;
  bool wrapped = advance < 0.0;
  if (wrapped) advance = advance + 1.0;
  float cycleSeconds = body.z * (1.0 - speedWeight(motion)) + body.w * speedWeight(motion);
  uint timer = min(((state >> kStateTimerShift) & kStateTimerMax) + uint(advance * cycleSeconds * kStateTimerUnits),
                   kStateTimerMax);
  uint level = initialized ? min(previous.level, kLevelCount - 1u) : kLevelFar;
  uint target = levelForHeight(heights, level, h);
  if (!initialized) {
    level = target;
    timer = 0u;
  } else if (target != level && float(timer) >= body.y * kStateTimerUnits && (wrapped || !visible)) {
    level = target;
    timer = 0u;
  }
  uint phaseBits = min(uint(cyclePhase(motion) * 65535.0), 65535u);
  return uvec2(level, kStateInitialized | (timer << kStateTimerShift) | (phaseBits << kStatePhaseShift));
}

#endif
