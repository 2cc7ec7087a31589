#pragma once
// GPU time of one steering step (grid build + avoidance) on a random crowd, measured with
// timestamps (medians), for `throng crowd bench` and the README figures.
#include <cstdint>

#include "crowd/avoidance.h"
#include "crowd/obstacles.h"
#include "gpu/context.h"

namespace throng::crowd {

struct AvoidanceTiming {
  uint32_t agents = 0;
  double gridMs = 0.0;     // clear + count + scan + scatter
  double countMs = 0.0;    // its parts: clear + count,
  double scanMs = 0.0;     // prefix sum,
  double scatterMs = 0.0;  // scatter
  double steerMs = 0.0;    // the policy pass
  double totalMs = 0.0;    // both, plus the barriers between them
  // The move after it: advance, or with walls save + advance + wall constraint.
  double moveMs = 0.0;
  uint32_t wallSegments = 0;  // 0: run without walls
  // The CPU twin's grid + steering on one thread, the same steps from the same start.
  double cpuMs = 0.0;
  int steps = 0;
};

// How the bench crowd is numbered: in grid order, as a crowd is when it is spawned from a
// storyboard (scan order) or by gridOrder, or at random (every per-agent access a cache miss).
enum class BenchNumbering { Grid, Random };

// Agents uniform in a square at `density` per m², each heading for a waypoint 1.3 m away in a
// random direction; `steps` measured after 2 warm-up steps (positions advance between steps),
// then the same steps again by the CPU twin.
// With `walls`, the square holds a grid of 2 x 2 m boxes every 10 m (benchBoxes), no agent
// starts within 0.5 m of one, the steering pass sees them and the wall constraint runs.
AvoidanceTiming benchmarkAvoidance(const gpu::Context& context, uint32_t agents,
                                   const AvoidanceParams& params, int steps, float density = 0.5f,
                                   BenchNumbering numbering = BenchNumbering::Grid,
                                   bool walls = false);
// 2 x 2 m boxes centred every 10 m over the square [-half, half]².
Obstacles benchBoxes(float half);

}  // namespace throng::crowd
