#include "secondary/offline/cloth_refine.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <vector>

#include "secondary/cloth_decoder.h"
#include "secondary/offline/worker_pool.h"

namespace throng::secondary {
namespace {

struct Candidate {
  uint32_t basis;
  int sign;
  float gain;
};

// A state's residual in one pass: its largest vertex error, where, and the sum over vertices of
// how far their squared error exceeds the target's (a step that keeps the largest error but
// lowers this still makes progress: two vertices tied at the top, say).
struct Spread {
  float largest = 0.0f;
  uint32_t worst = 0;
  double excess = 0.0;
};

Spread spread(const std::vector<glm::vec3>& residual, float target) {
  Spread s;
  float best = -1.0f;
  for (uint32_t v = 0; v < residual.size(); ++v) {
    const float e = glm::dot(residual[v], residual[v]);
    s.excess += std::max(0.0f, e - target * target);
    if (e > best) {
      best = e;
      s.worst = v;
    }
  }
  s.largest = std::sqrt(best);
  return s;
}

// One state: residual = truth − decoded, refined in place; returns the steps taken.
uint64_t refineState(const DecodedBases& d, ClothDatabase& db, uint32_t state,
                     std::vector<glm::vec3>& residual, float target, uint32_t maxSteps) {
  const uint32_t V = d.vertexCount, b = d.basisCount;
  std::vector<glm::vec3> trial(V);
  std::vector<Candidate> candidates(b);
  Spread current = spread(residual, target);
  uint64_t steps = 0;
  while (current.largest > target && steps < maxSteps) {
    // Moving coefficient i by one step moves vertex v by B_i(v) · step_i / 32767.
    for (uint32_t i = 0; i < b; ++i) {
      const float* basis = d.bases.data() + size_t(i) * 3 * V + 3 * size_t(current.worst);
      const float unit = float(db.coefficientSteps[i]) / kCoefficientScale;
      const glm::vec3 move(basis[0] * unit, basis[1] * unit, basis[2] * unit);
      const float toward = glm::dot(residual[current.worst], move);
      candidates[i] = {i, toward >= 0.0f ? 1 : -1, std::abs(toward) - 0.5f * glm::dot(move, move)};
    }
    // Every basis is a candidate, best first: on the damped cape trying only the best 8 or 64
    // left 2.81 or 2.11 mm where all of them reach 1.96 mm.
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& x, const Candidate& y) { return x.gain > y.gain; });
    bool stepped = false;
    for (uint32_t k = 0; k < b && candidates[k].gain > 0.0f; ++k) {
      const Candidate& c = candidates[k];
      int16_t& q = db.coefficients[size_t(state) * b + c.basis];
      const int32_t step = db.coefficientSteps[c.basis];
      const int32_t limit = int32_t(kCoefficientScale) / step * step;
      const int32_t next = int32_t(q) + c.sign * step;
      if (next < -limit || next > limit) continue;
      const float unit = float(c.sign * step) / kCoefficientScale;
      const float* basis = d.bases.data() + size_t(c.basis) * 3 * V;
      for (uint32_t v = 0; v < V; ++v)
        trial[v] = residual[v] - unit * glm::vec3(basis[3 * v], basis[3 * v + 1], basis[3 * v + 2]);
      const Spread after = spread(trial, target);
      if (after.largest < current.largest ||
          (after.largest <= current.largest && after.excess < current.excess)) {
        q = int16_t(next);
        residual.swap(trial);
        current = after;
        ++steps;
        stepped = true;
        break;
      }
    }
    if (!stepped) break;
  }
  return steps;
}

}  // namespace

RefineReport refineCoefficients(const ClothFrames& frames, ClothDatabase& db, float target,
                                uint32_t maxSteps, unsigned threads) {
  RefineReport report;
  const DecodedBases d = dequantize(db);
  std::atomic<uint32_t> above{0}, refined{0};
  std::atomic<uint64_t> steps{0};
  std::mutex mutex;
  double errorSum = 0.0;
  float errorMax = 0.0f;
  constexpr uint32_t kStatesPerJob = 64;
  WorkerPool pool(threads);
  pool.run((frames.stateCount + kStatesPerJob - 1) / kStatesPerJob, [&](size_t job) {
    std::vector<glm::vec3> truth(d.vertexCount), decoded(d.vertexCount), residual(d.vertexCount);
    const uint32_t first = uint32_t(job) * kStatesPerJob;
    double partSum = 0.0;
    float partMax = 0.0f;
    for (uint32_t s = first; s < std::min(frames.stateCount, first + kStatesPerJob); ++s) {
      frames.positions(s, truth);
      decodeState(d, s, decoded);
      for (uint32_t v = 0; v < d.vertexCount; ++v) residual[v] = truth[v] - decoded[v];
      if (spread(residual, target).largest > target) {
        ++above;
        const uint64_t taken = refineState(d, db, s, residual, target, maxSteps);
        if (taken) ++refined;
        steps += taken;
      }
      for (const glm::vec3& r : residual) {
        const float e = glm::length(r);
        partSum += e;
        partMax = std::max(partMax, e);
      }
    }
    std::lock_guard<std::mutex> lock(mutex);
    errorSum += partSum;
    errorMax = std::max(errorMax, partMax);
  });
  report.statesAboveTarget = above;
  report.statesRefined = refined;
  report.steps = steps;
  report.after = {errorMax, float(errorSum / (double(frames.stateCount) * d.vertexCount))};
  return report;
}

}  // namespace throng::secondary
