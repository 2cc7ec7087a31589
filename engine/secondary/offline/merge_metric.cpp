#include "secondary/offline/merge_metric.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace throng::secondary {

float linfDistance(FrameView a, FrameView b, float velocityScale, float bound) {
  THRONG_CHECK(
      a.positions.size() == b.positions.size() && a.velocities.size() == b.velocities.size(),
      "frames of ", a.positions.size(), " and ", b.positions.size(), " vertices");
  // Squared distances: one sqrt at the end, and the early exit compares squares.
  const float bound2 = std::isfinite(bound) ? bound * bound : INFINITY;
  const float s2 = velocityScale * velocityScale;
  float worst = 0.0f;
  for (size_t i = 0; i < a.positions.size(); ++i) {
    const glm::vec3 dx = a.positions[i] - b.positions[i];
    const glm::vec3 dv = a.velocities[i] - b.velocities[i];
    worst = std::max(worst, std::max(glm::dot(dx, dx), s2 * glm::dot(dv, dv)));
    if (!(worst <= bound2)) return std::isnan(worst) ? NAN : std::sqrt(worst);
  }
  return std::sqrt(worst);
}

float mergeError(const MergeMetric& metric, FrameView a, FrameView b, uint32_t node) {
  float e = linfDistance(a, b, metric.velocityScale);
  if (metric.garment) e += metric.garment(a, b, node);
  return e;
}

MergeTarget findMergeTarget(const SecondaryGraph& g, const MergeMetric& metric, uint32_t node,
                            FrameView cloth) {
  THRONG_CHECK(node < g.statesAtNode.size() && !g.statesAtNode[node].empty(),
               "no state at primary node ", node, " to merge into");
  MergeTarget best;
  for (uint32_t s : g.statesAtNode[node]) {
    const FrameView other = g.frame(s);
    // The garment term is ≥ 0, so a state whose L∞ part alone is not better cannot win.
    const float linf = linfDistance(cloth, other, metric.velocityScale, best.error);
    if (std::isnan(linf))
      fail("merge error is not a number at primary node ", node,
           ": the simulator produced a non-finite cloth state");
    if (!(linf < best.error)) continue;
    const float e = metric.garment ? linf + metric.garment(cloth, other, node) : linf;
    if (e < best.error) best = {s, e};
  }
  if (best.state == kNoState)
    fail("no finite merge error at primary node ", node,
         ": the simulator produced a non-finite cloth state");
  return best;
}

}  // namespace throng::secondary
