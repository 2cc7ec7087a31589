// The ground's colour at a world position on y = 0: 1 m and 10 m grid lines, anti-aliased with
// screen-space derivatives (call in uniform control flow) and faded with distance. Shared by
// the ground draw (ground.frag) and the splat resolve, which shades the ground itself.
#ifndef THRONG_GROUND_GLSL
#define THRONG_GROUND_GLSL

float gridLine(vec2 p, float spacing) {
  vec2 g = abs(fract(p / spacing - 0.5) - 0.5) / (fwidth(p / spacing) + 1e-6);
  return 1.0 - clamp(min(g.x, g.y), 0.0, 1.0);
}

vec4 groundColour(vec3 worldPosition, vec3 eye) {
  vec2 p = worldPosition.xz;
  float fine = gridLine(p, 1.0);
  float coarse = gridLine(p, 10.0);
  float fade = exp(-length(worldPosition - eye) * 0.004);
  vec3 base = vec3(0.34, 0.36, 0.33);
  vec3 c = base + fade * (0.05 * fine + 0.12 * coarse);
  return vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}

#endif
