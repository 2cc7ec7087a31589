// A cached character's joint point: M · p with p the character-space point from the motion cache
// and M = T(origin) · R_y(heading) · S(scale); the bone's radius scales with it. Shared by the
// materialize pass and the renderer; CPU twin: synth::placeCachedPoint.
#ifndef THRONG_CACHED_POSE_GLSL
#define THRONG_CACHED_POSE_GLSL
vec4 placeCachedPoint(vec4 p, vec4 place, float scale) {
  float c = cos(place.w), s = sin(place.w);
  return vec4(scale * vec3(c * p.x + s * p.z, p.y, c * p.z - s * p.x) + place.xyz, scale * p.w);
}
#endif
