// Grid and random-number helpers of the crowd steering passes. CPU twin: crowd/avoidance.h
// (cellCoord, cellIndex, pcgHash, steerRandom: the same integer math).
#ifndef THRONG_AVOIDANCE_COMMON_GLSL
#define THRONG_AVOIDANCE_COMMON_GLSL

// PCG hash (Jarzynski & Olano 2020): one 32-bit word in, one well-mixed word out.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

ivec2 cellCoord(vec2 p, vec2 invCellSize) { return ivec2(floor(p * invCellSize)); }

// Row-major index in the grid table, coordinates modulo its size (two's complement & keeps
// negative coordinates in range): cells x and x + 1 of a row are adjacent unless x + 1 wraps.
uint cellIndex(ivec2 c, uint widthShift, uint rowMask) {
  uint columnMask = (1u << widthShift) - 1u;
  return ((uint(c.y) & rowMask) << widthShift) | (uint(c.x) & columnMask);
}

// Uniform in [0, 1) from (agent, step, seed): the rule's random turn, reproducible on the CPU.
float steerRandom(uint agent, uint step, uint seed) {
  uint h = pcgHash(agent ^ pcgHash(step ^ pcgHash(seed)));
  return float(h >> 8u) * (1.0 / 16777216.0);
}

// Whether two discs of diameter² `diameter2`, at relative position x moving at relative
// velocity v, come closer than touching within `horizon` seconds. Only while approaching:
// agents already too close may always move apart. Division-free (the closest approach
// |x|² − (x·v)²/|v|² is compared multiplied by |v|²), so GPU and CPU decide alike; the
// distance at the horizon is |x|² + h(2 x·v + h|v|²), from the dot products already taken
// (|x|² is the same for all of a candidate's courses, so it is computed once).
bool collides(vec2 x, vec2 v, float horizon, float diameter2) {
  float xv = dot(x, v);
  float vv = dot(v, v);
  float xx = dot(x, x);
  float horizonVv = horizon * vv;
  bool closestInside = -xv < horizonVv;
  bool hit = closestInside ? (xx - diameter2) * vv < xv * xv : xx + horizon * (xv + xv + horizonVv) < diameter2;
  return xv < 0.0 && hit;
}

#endif
