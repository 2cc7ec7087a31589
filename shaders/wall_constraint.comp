#version 450
#extension GL_GOOGLE_include_directive : require
// The hard guarantee of static walls: no agent crosses a segment or ends within its radius of
// one, whatever the forces did. Each agent's move, from its placement before the step (saved by
// the caller) to its placement now, stops at the first contact with a wall (kept at radius +
// kWallSkin), and the rest of the move is projected onto the wall's tangent (sliding along it);
// a slide that meets another wall (a corner) slides again, and after kWallContacts contacts the
// agent stays at the last one, a safe point. Thin walls need no thickness: the capsule of radius
// r around the segment is what the move may not enter. CPU twin: crowd::constrainMove.
#include "crowd_types.h"
#include "crowd_bindings.h"
#include "avoidance_walls.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = kWallBindingPlacement) buffer Placement { vec4 placement[]; };
layout(binding = kWallBindingPrevious) uniform samplerBuffer previousTexels;
layout(std140, binding = kWallBindingInfo) uniform WallInfo { WallGridInfo wallInfo; };
layout(binding = kWallBindingSegments) uniform samplerBuffer wallSegments;
layout(binding = kWallBindingStarts) uniform usamplerBuffer wallStarts;
layout(binding = kWallBindingIndices) uniform usamplerBuffer wallIndices;
layout(push_constant) uniform Push { WallPush push; };

// Where the move from `from` to `to` ends.
vec2 constrainMove(vec2 from, vec2 to, WallPush pc, WallGridInfo info) {
  vec2 m = to - from;
  float len = length(m);
  bool shortened = len > pc.maxMove;
  if (shortened) m *= pc.maxMove / len;
  uint cell = wallCell(from, info);
  if (cell == 0xFFFFFFFFu) return shortened ? from + m : to;
  uint begin = texelFetch(wallStarts, int(cell)).x;
  uint end = texelFetch(wallStarts, int(cell + 1u)).x;
  float r = pc.radius + kWallSkin;
  // Segments farther than r + |m| from the start cannot be touched by any slide of this move.
  float screen = r + length(m);
  vec2 p = from;
  for (uint contact = 0u; contact < kWallContacts; ++contact) {
    float first = kNoWallHit;
    vec2 normal = vec2(0.0);
    for (uint k = begin; k < end; ++k) {
      vec4 s = texelFetch(wallSegments, int(texelFetch(wallIndices, int(k)).x));
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
  vec2 to = constrainMove(texelFetch(previousTexels, int(i)).xz, place.xz, pc, info);
  if (to != place.xz) placement[i] = vec4(to.x, place.y, to.y, place.w);
}
