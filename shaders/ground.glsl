// The ground's colour at a world position on y = 0: 1 m and 10 m grid lines, anti-aliased by
// their screen-space width and faded with distance. Shared by the ground draw (ground.frag),
// the fragment resolve (fwidth) and the compute resolve (differences to the neighbouring
// pixels' ground points, as a fragment quad's derivatives are).
#ifndef THRONG_GROUND_GLSL
#define THRONG_GROUND_GLSL

const vec3 kGroundBase = vec3(0.34, 0.36, 0.33);
const vec3 kGroundBaseEncoded = pow(kGroundBase, vec3(1.0 / 2.2));  // folded by the compiler

// `width`: the screen-space change of p per pixel (fwidth(p)).
float gridLine(vec2 p, vec2 width, float spacing) {
  vec2 g = abs(fract(p / spacing - 0.5) - 0.5) / (width / spacing + 1e-6);
  return 1.0 - clamp(min(g.x, g.y), 0.0, 1.0);
}

vec4 groundColour(vec3 worldPosition, vec2 width, vec3 eye) {
  vec2 p = worldPosition.xz;
  float fine = gridLine(p, width, 1.0);
  float coarse = gridLine(p, width, 10.0);
  // Most pixels lie between the lines: their colour is a constant, and the fade's exp and the
  // gamma's pow (most of this function's cost on lavapipe) are left out.
  if (fine + coarse == 0.0) return vec4(kGroundBaseEncoded, 1.0);
  float fade = exp(-length(worldPosition - eye) * 0.004);
  vec3 c = kGroundBase + fade * (0.05 * fine + 0.12 * coarse);
  return vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}

// Where the ray from `eye` along `dir` meets y = 0 (t < 0: it does not, looking up).
vec3 groundPoint(vec3 eye, vec3 dir, out float t) {
  t = dir.y < 0.0 ? -eye.y / dir.y : -1.0;
  return eye + t * dir;
}

#endif
