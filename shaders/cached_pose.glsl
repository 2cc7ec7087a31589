// A cached character's joint point: M · p with p the character-space point from the motion cache
// and M = T(origin) · R_y(heading) · S(scale); the bone's radius scales with it. Shared by the
// materialize pass and the renderer; CPU twin: synth::placeCachedPoint.
#ifndef THRONG_CACHED_POSE_GLSL
#define THRONG_CACHED_POSE_GLSL
// M of one character, its heading's cosine and sine taken once for all its joints.
struct CachedPlacement {
  vec3 origin;
  vec2 heading;  // cos, sin
  float scale;
};

CachedPlacement cachedPlacement(vec4 place, float scale) {
  return CachedPlacement(place.xyz, vec2(cos(place.w), sin(place.w)), scale);
}

vec4 placeCachedPoint(vec4 p, CachedPlacement m) {
  float c = m.heading.x, s = m.heading.y;
  return vec4(m.scale * vec3(c * p.x + s * p.z, p.y, c * p.z - s * p.x) + m.origin, m.scale * p.w);
}
#endif
