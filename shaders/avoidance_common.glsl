// Hashes of the crowd steering passes. CPU twin: crowd/avoidance_math.h (same integer math).
#ifndef THRONG_AVOIDANCE_COMMON_GLSL
#define THRONG_AVOIDANCE_COMMON_GLSL

// PCG hash (Jarzynski & Olano 2020): one 32-bit word in, one well-mixed word out.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

ivec2 cellCoord(vec2 p, float invCellSize) { return ivec2(floor(p * invCellSize)); }

// Cells are hashed into a power-of-two table, so the grid needs no bounds; a bucket may
// hold several cells, which the neighbour scan tells apart by recomputing cellCoord.
uint cellHash(ivec2 c, uint cellCount) {
  return pcgHash(uint(c.x) * 73856093u ^ uint(c.y) * 19349663u) & (cellCount - 1u);
}

// Uniform in [0, 1) from (agent, step, seed): the rule's random turn, reproducible on the CPU.
float steerRandom(uint agent, uint step, uint seed) {
  uint h = pcgHash(agent ^ pcgHash(step ^ pcgHash(seed)));
  return float(h >> 8u) * (1.0 / 16777216.0);
}

#endif
