// A cached character's joint matrix: A = M · P with P the character-space pose from the motion
// cache and M = T(origin) · R_y(heading) · S(scale). Shared by the materialize pass and the
// renderer; CPU twin: synth::MotionCacheCpu::pose.
#ifndef THRONG_CACHED_POSE_GLSL
#define THRONG_CACHED_POSE_GLSL
JointMatrix placeCachedJoint(JointMatrix p, vec4 place, float scale) {
  float c = cos(place.w), s = sin(place.w);
  JointMatrix a;
  a.row0 = scale * (c * p.row0 + s * p.row2) + vec4(0.0, 0.0, 0.0, place.x);
  a.row1 = scale * p.row1 + vec4(0.0, 0.0, 0.0, place.y);
  a.row2 = scale * (c * p.row2 - s * p.row0) + vec4(0.0, 0.0, 0.0, place.z);
  return a;
}
#endif
