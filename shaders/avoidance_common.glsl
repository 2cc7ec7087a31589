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

// A neighbour's weight in the local density ahead (crowd_types.h): (1 − d²/R²)² in fixed point
// for a neighbour in the half disc ahead (x · dir < 0, x = own position − its position, dir the
// preferred velocity), 0 at and beyond R, behind and for an agent at the very same place.
uint densityWeight(vec2 x, float dist2, vec2 dir, float invRadius2) {
  float t = max(1.0 - dist2 * invRadius2, 0.0);
  return dist2 > 0.0 && dot(x, dir) < 0.0 ? uint(t * t * kDensityScale + 0.5) : 0u;
}

// Weidmann's speed fraction at the density of the summed weights (1 when the rule is off), in
// steps of 1/1024: exp differs by an ulp between lavapipe and the C library, and unrounded that
// ulp would grow into different courses of the rule on the GPU and in the CPU twin.
float densitySpeedFactor(uint weights, float norm) {
  float rho = float(weights) * (norm / kDensityScale);
  float f = rho > 0.0 ? 1.0 - exp(-kWeidmannGamma * (1.0 / rho - 1.0 / kWeidmannMaxDensity)) : 1.0;
  return clamp(floor(f * 1024.0 + 0.5) * (1.0 / 1024.0), kDensityMinSpeed, 1.0);
}

#endif
