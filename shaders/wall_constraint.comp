#version 450
#extension GL_GOOGLE_include_directive : require
// The hard guarantee of static walls: no agent crosses a segment or ends within its radius of
// one, whatever the forces did. Each agent's move, from its placement before the step (saved by
// the caller) to its placement now, stops at the first contact with a wall (kept at radius +
// kWallSkin), and the rest of the move is projected onto the wall's tangent (sliding along it);
// a slide that meets another wall (a corner) slides again, and after kWallContacts contacts the
// agent stays at the last one, a safe point. Thin walls need no thickness: the capsule of radius
// r around the segment is what the move may not enter. CPU twin: crowd::constrainMove.
// The moving form (kAdvance = 1) is the kinematic advance and the constraint in one pass: the
// move is from placement to placement + steer · dt (twin: advanceCpu, then constrainMove), which
// spares the saved copy of placement, a pass and two barriers per step.
#include "crowd_types.h"
#include "crowd_bindings.h"
#include "avoidance_walls.glsl"

layout(local_size_x = 64) in;
layout(constant_id = kWallConstantAdvance) const uint kAdvance = 0u;
layout(std430, binding = kWallBindingPlacement) buffer Placement { vec4 placement[]; };
layout(binding = kWallBindingPrevious) uniform samplerBuffer previousTexels;
layout(std140, binding = kWallBindingInfo) uniform WallInfo { WallGridInfo wallInfo; };
layout(binding = kWallBindingEntries) uniform samplerBuffer wallEntries;
layout(binding = kWallBindingStarts) uniform usamplerBuffer wallStarts;
layout(binding = kWallBindingSteer) uniform samplerBuffer steerTexels;
layout(binding = kWallBindingGoals) uniform samplerBuffer goalTexels;
layout(binding = kWallBindingClearance) uniform samplerBuffer clearanceTexels;
layout(push_constant) uniform Push { WallPush push; };

// Where the move from `from` to `to` ends.
vec2 constrainMove(vec2 from, vec2 to, WallPush pc, WallGridInfo info) {
  vec2 m = to - from;
  float len = length(m);
  bool shortened = len > pc.maxMove;
  if (shortened) m *= pc.maxMove / len;
  uint cell = wallCell(from, info);
  if (cell == 0xFFFFFFFFu) return shortened ? from + m : to;
  float r = pc.radius + kWallSkin;
  // Segments farther than r + |m| from the start cannot be touched by any slide of this move;
  // where the whole cell is that far from every wall (most agents), none is read at all.
  float screen = r + length(m);
  bool clear = texelFetch(clearanceTexels, int(cell)).x > screen;
  uint begin = clear ? 0u : texelFetch(wallStarts, int(cell)).x;
  uint end = clear ? 0u : texelFetch(wallStarts, int(cell + 1u)).x;
  vec2 p = from;
  for (uint contact = 0u; contact < kWallContacts; ++contact) {
    float first = kNoWallHit;
    vec2 normal = vec2(0.0);
    for (uint k = begin; k < end; ++k) {
      vec4 s = texelFetch(wallEntries, int(k));
      vec2 off = from - closestOnSegment(from, s.xy, s.zw);
      if (dot(off, off) > screen * screen) continue;
      vec2 n;
      float t = segmentHit(p, m, s.xy, s.zw, r, n);
      if (t < first) {
        first = t;
        normal = n;
      }
    }
    if (first > 1.0) return contact == 0u && !shortened ? to : p + m;
    if (normal == vec2(0.0)) return p;  // on the segment itself: no tangent to slide on
    p += first * m;
    vec2 rest = (1.0 - first) * m;
    m = rest - dot(rest, normal) * normal;
  }
  return p;
}

void main() {
  WallPush pc = push;
  WallGridInfo info = wallInfo;
  uint n = gl_GlobalInvocationID.x;
  if (n >= pc.count) return;
  uint i = pc.first + n;
  vec4 place = placement[i];
  vec2 from = place.xz, to = place.xz;
  if (kAdvance != 0u) {
    if (texelFetch(goalTexels, int(i)).w == 0.0) return;  // inactive: stays
    vec2 v = texelFetch(steerTexels, int(i)).xy;
    to = vec2(place.x + v.x * pc.dt, place.z + v.y * pc.dt);  // as avoidance_advance.comp
  } else {
    from = texelFetch(previousTexels, int(i)).xz;
  }
  vec2 end = constrainMove(from, to, pc, info);
  if (kAdvance != 0u || end != place.xz) placement[i] = vec4(end.x, place.y, end.y, place.w);
}
