// Static walls: the segment math of the steering pass and the wall constraint. CPU twin:
// crowd/obstacles.cpp (closestOnSegment, segmentHit, WallGrid::cellOf), the same operations in
// the same order. The including shader declares wallEntries and wallStarts
// (texels) and passes the WallGridInfo it read.
#ifndef THRONG_AVOIDANCE_WALLS_GLSL
#define THRONG_AVOIDANCE_WALLS_GLSL

const float kNoWallHit = 1.0e30;

// The wall grid's cell of p, or 0xFFFFFFFF outside it (farther than reach from every segment).
uint wallCell(vec2 p, WallGridInfo info) {
  vec2 f = floor((p - info.frame.xy) * info.frame.z);
  bool inside = f.x >= 0.0 && f.y >= 0.0 && f.x < float(info.size.x) && f.y < float(info.size.y);
  return inside ? uint(f.y) * info.size.x + uint(f.x) : 0xFFFFFFFFu;
}

vec2 closestOnSegment(vec2 p, vec2 a, vec2 b) {
  vec2 d = b - a;
  float dd = dot(d, d);
  float u = dd > 0.0 ? clamp(dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
  return a + u * d;
}

// The smaller root of |p − e + t m|² = r² (the first touch of end disc e), without cancellation.
float endHit(vec2 p, vec2 m, vec2 e, float r) {
  vec2 x = p - e;
  float b = dot(x, m), mm = dot(m, m), c = max(dot(x, x) - r * r, 0.0);  // < 0: rounding
  float disc = b * b - mm * c;
  if (!(b < 0.0 && disc >= 0.0 && mm > 0.0)) return kNoWallHit;
  return c / (sqrt(disc) - b);
}

// The first t >= 0 at which a disc of radius r at p moving by m per unit of t touches segment ab
// (a capsule of radius r around it: its two sides and two end discs), with the contact normal
// from the wall towards the disc. A disc already closer than r: t = 0 when it moves closer (the
// distance to a segment is convex along a line, so moving along or away never gets closer).
float segmentHit(vec2 p, vec2 m, vec2 a, vec2 b, float r, out vec2 normal) {
  normal = vec2(0.0);
  vec2 off = p - closestOnSegment(p, a, b);
  float d2 = dot(off, off);
  if (d2 < r * r) {
    if (d2 > 1e-12) normal = off / sqrt(d2);
    return dot(m, normal) < -1e-5 * length(m) || d2 <= 1e-12 ? 0.0 : kNoWallHit;
  }
  float t = kNoWallHit;
  vec2 d = b - a;
  float len2 = dot(d, d);
  vec2 side = normalize(vec2(-d.y, d.x));
  float s0 = dot(p - a, side);
  if (s0 < 0.0) {
    side = -side;
    s0 = -s0;
  }
  float sv = dot(m, side);
  if (sv < 0.0) {  // s0 < r only by rounding (the closest point said outside): a touch now
    float ts = max(s0 - r, 0.0) / -sv;
    float u = dot(p + ts * m - a, d);
    if (u >= 0.0 && u <= len2) {
      t = ts;
      normal = side;
    }
  }
  float ta = endHit(p, m, a, r);
  if (ta < t) {
    t = ta;
    normal = normalize(p + ta * m - a);
  }
  float tb = endHit(p, m, b, r);
  if (tb < t) {
    t = tb;
    normal = normalize(p + tb * m - b);
  }
  return t;
}

#endif
