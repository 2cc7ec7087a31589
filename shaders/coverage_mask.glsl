// A character's coverage mask for this frame, shared by coverage.comp and the root motion pass
// that does the frame's coverage itself (root_motion_coverage.comp). The includer declares
// `parts` (uniform CoverageParts) and includes coverage_types.h and coverage_common.glsl first.
// CPU twin: synth::coverageCharacter.
#ifndef THRONG_COVERAGE_MASK_GLSL
#define THRONG_COVERAGE_MASK_GLSL

CoverageMask unpackMask(u64vec2 words) {
  uvec2 lohi = unpackUint2x32(words.x), levelState = unpackUint2x32(words.y);
  return CoverageMask(lohi.x, lohi.y, levelState.x, levelState.y);
}

// The level after this frame (projected height h, with hysteresis) and its joints when the body
// is on screen, the off-screen set when not; onScreen: the measured part bits (0 if none).
u64vec2 nextMaskWords(CoverageMask previous, vec4 m, float h, bool visible, uint onScreen) {
  uvec2 levelState = nextLevel(parts.body, levelHeights(parts.levels[1], parts.levels[2]), previous, m, h, visible);
  uvec2 synthesized = uvec2(parts.offScreenLo, parts.offScreenHi);
  if (visible && levelState.x == kLevelNear) synthesized = uvec2(parts.levels[2].synthLo, parts.levels[2].synthHi);
  if (visible && levelState.x == kLevelMid) synthesized = uvec2(parts.levels[1].synthLo, parts.levels[1].synthHi);
  if (visible && levelState.x == kLevelFar) synthesized = uvec2(parts.levels[0].synthLo, parts.levels[0].synthHi);
  return u64vec2(packUint2x32(synthesized), packUint2x32(uvec2(levelState.x, levelState.y | onScreen)));
}

// The camera-space middle of the body of a character at `place` with motion m, and its height.
vec3 bodyMiddle(mat4 view, vec4 place, vec4 m, out float height) {
  height = parts.body.x * characterScale(m);
  return cameraSpace(view, place.xyz + vec3(0.0, 0.5 * height, 0.0));
}

// Projected height and visibility of the body of a character at `place` with motion m.
void bodyOnScreenHeight(mat4 view, vec4 viewport, vec4 frustum, vec4 place, vec4 m, out float h, out bool visible) {
  float height;
  vec3 middle = bodyMiddle(view, place, m, height);
  h = projectedHeight(viewport, middle, height);
  visible = bodyOnScreen(viewport, frustum, middle, height);
}

// The mask words after this frame without the part areas (the frame's coverage).
u64vec2 frameMaskWords(mat4 view, vec4 viewport, vec4 frustum, vec4 place, vec4 m, u64vec2 words) {
  float h;
  bool visible;
  bodyOnScreenHeight(view, viewport, frustum, place, m, h, visible);
  return nextMaskWords(unpackMask(words), m, h, visible, 0u);
}

// The same, for the update-rate LOD's root motion: also the character's projected height h, and
// whether its body is within `reach` of the view (bodyWithinReach), from the one middle.
u64vec2 frameMaskWords(mat4 view, vec4 viewport, vec4 frustum, vec4 place, vec4 m, u64vec2 words,
                       float reach, out float h, out bool withinReach) {
  float height;
  vec3 middle = bodyMiddle(view, place, m, height);
  h = projectedHeight(viewport, middle, height);
  withinReach = bodyWithinReach(viewport, frustum, middle, height, reach);
  return nextMaskWords(unpackMask(words), m, h, bodyOnScreen(viewport, frustum, middle, height), 0u);
}

#endif
