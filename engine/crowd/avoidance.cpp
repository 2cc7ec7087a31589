#include "crowd/avoidance.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "crowd/avoidance_types.h"

namespace throng::crowd {

std::optional<SteerPolicy> parseSteerPolicy(std::string_view name) {
  if (name == "none") return SteerPolicy::None;
  if (name == "rule") return SteerPolicy::Rule;
  if (name == "ttc") return SteerPolicy::Ttc;
  return std::nullopt;
}

std::string_view steerPolicyName(SteerPolicy policy) {
  switch (policy) {
    case SteerPolicy::None: return "none";
    case SteerPolicy::Rule: return "rule";
    case SteerPolicy::Ttc: return "ttc";
  }
  return "?";
}

std::vector<std::string> validateParams(const AvoidanceParams& p) {
  std::vector<std::string> problems;
  auto positive = [&](float v, const char* name) {
    if (!(v > 0.0f) || !std::isfinite(v)) problems.push_back(concat(name, " must be positive, got ", v));
  };
  if (uint32_t(p.policy) > 2u) problems.push_back(concat("unknown policy ", uint32_t(p.policy)));
  positive(p.cellSize, "cell size");
  positive(p.radius, "safe radius");
  positive(p.sensing, "sensing distance");
  positive(p.lookahead, "lookahead");
  positive(p.ttcTau0, "TTC tau0");
  positive(p.ttcXi, "TTC relaxation time xi");
  positive(p.ttcMaxForce, "TTC force cap");
  if (!(p.ttcK >= 0.0f)) problems.push_back(concat("TTC k must be >= 0, got ", p.ttcK));
  if (!(p.gazeAngle >= 0.0f && p.gazeAngle <= 6.2832f))
    problems.push_back(concat("gaze angle must lie in [0, 2 pi] radians, got ", p.gazeAngle));
  if (p.cellSize > 0.0f && p.sensing > 0.0f && p.sensing > 8.0f * p.cellSize)
    problems.push_back(concat("sensing distance ", p.sensing, " m spans more than 8 cells of ", p.cellSize,
                              " m: use larger cells"));
  return problems;
}

int cellRange(const AvoidanceParams& p) { return std::max(1, int(std::ceil(p.sensing / p.cellSize))); }

uint32_t gridCellCount(uint32_t agents) {
  uint32_t cells = 1024;
  while (cells < kMaxGridCells && cells < agents) cells <<= 1;
  return cells;
}

uint32_t pcgHash(uint32_t v) {
  uint32_t state = v * 747796405u + 2891336453u;
  uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

glm::ivec2 cellCoord(glm::vec2 p, float invCellSize) {
  return {int(std::floor(p.x * invCellSize)), int(std::floor(p.y * invCellSize))};
}

uint32_t cellHash(glm::ivec2 c, uint32_t cellCount) {
  return pcgHash((uint32_t(c.x) * 73856093u) ^ (uint32_t(c.y) * 19349663u)) & (cellCount - 1u);
}

float steerRandom(uint32_t agent, uint32_t step, uint32_t seed) {
  uint32_t h = pcgHash(agent ^ pcgHash(step ^ pcgHash(seed)));
  return float(h >> 8u) * (1.0f / 16777216.0f);
}

Grid buildGridCpu(std::span<const glm::vec4> placement, std::span<const glm::vec4> steer, float cellSize,
                  uint32_t cellCount) {
  THRONG_CHECK(cellCount && (cellCount & (cellCount - 1)) == 0, "cell count ", cellCount, " is not a power of two");
  THRONG_CHECK(steer.size() >= placement.size(), "steer smaller than placement");
  const size_t n = placement.size();
  Grid g;
  g.cellCount = cellCount;
  g.invCellSize = 1.0f / cellSize;
  g.cellOf.resize(n);
  g.counts.assign(cellCount, 0);
  g.starts.assign(cellCount, 0);
  for (size_t i = 0; i < n; ++i) {
    g.cellOf[i] = cellHash(cellCoord({placement[i].x, placement[i].z}, g.invCellSize), cellCount);
    ++g.counts[g.cellOf[i]];
  }
  uint32_t sum = 0;
  for (uint32_t c = 0; c < cellCount; ++c) g.starts[c] = sum, sum += g.counts[c];
  // Scattering in index order leaves each cell sorted by index, as the GPU's cell-sort pass does.
  std::vector<uint32_t> cursor(g.starts);
  g.sortedIndex.resize(n);
  g.sorted.resize(n);
  for (size_t i = 0; i < n; ++i) {
    uint32_t slot = cursor[g.cellOf[i]]++;
    g.sortedIndex[slot] = uint32_t(i);
    g.sorted[slot] = glm::vec4(placement[i].x, placement[i].z, steer[i].x, steer[i].y);
  }
  return g;
}

namespace {

// Mirrors ttcForce in shaders/avoidance_steer.comp (floors of τ and √D explained there).
glm::vec2 ttcForce(const AvoidanceParams& p, glm::vec2 x, glm::vec2 v, float dist2) {
  float diameter = 2.0f * p.radius;
  float c = dist2 - diameter * diameter;
  if (c < 0.0f) {
    float d = std::sqrt(dist2);
    return d > 1e-4f ? x * (p.ttcMaxForce * (diameter - d) / (diameter * d)) : glm::vec2(0.0f);
  }
  float a = glm::dot(v, v);
  float b = glm::dot(x, v);
  if (b >= 0.0f || a < 1e-6f) return glm::vec2(0.0f);
  float disc = b * b - a * c;
  if (disc <= 0.0f) return glm::vec2(0.0f);
  float s = std::sqrt(disc);
  float tau = c / (s - b);
  float t = std::max(tau, 0.1f);
  float magnitude =
      p.ttcK * std::exp(-t / p.ttcTau0) / (t * t) * (2.0f / t + 1.0f / p.ttcTau0) / std::max(s, 0.05f * a);
  return (x + tau * v) * magnitude;
}

// Mirrors collides() in shaders/avoidance_steer.comp.
bool collides(glm::vec2 x, glm::vec2 v, float horizon, float diameter2) {
  float xv = glm::dot(x, v);
  if (xv >= 0.0f) return false;
  glm::vec2 d = x + v * std::min(-xv / glm::dot(v, v), horizon);
  return glm::dot(d, d) < diameter2;
}

}  // namespace

void steerCpu(const Grid& grid, const AvoidanceParams& p, const SteerFrame& frame, std::span<glm::vec4> placement,
              std::span<glm::vec4> motion, std::span<const glm::vec4> goals, std::span<glm::vec4> steer) {
  const size_t n = placement.size();
  THRONG_CHECK(motion.size() >= n && goals.size() >= n && steer.size() >= n && grid.cellOf.size() == n,
               "steerCpu: arrays of ", n, " agents expected");
  const float invSecondsLeft = 1.0f / frame.secondsLeft;
  const int range = cellRange(p);
  const float diameter2 = 4.0f * p.radius * p.radius;
  const float sensing2 = p.sensing * p.sensing;
  const float cosHalfGaze = std::cos(0.5f * p.gazeAngle);
  // Every agent reads only the grid's copies of the others, so the order of updates is free.
  for (size_t i = 0; i < n; ++i) {
    const glm::vec4 goal = goals[i];
    if (goal.w == 0.0f) {
      steer[i] = glm::vec4(0.0f);
      continue;
    }
    glm::vec4 place = placement[i];
    glm::vec2 pos(place.x, place.z);
    glm::vec2 vPref = (glm::vec2(goal) - pos) * invSecondsLeft;
    float prefSpeed = glm::length(vPref);
    if (prefSpeed > goal.z) {
      vPref *= goal.z / prefSpeed;
      prefSpeed = goal.z;
    }
    glm::vec2 vCur(steer[i]);
    const bool rule = p.policy == SteerPolicy::Rule;
    float goalHeading = prefSpeed > 1e-4f ? std::atan2(vPref.x, vPref.y) : place.w;
    glm::vec2 keep = prefSpeed * glm::vec2(std::sin(place.w), std::cos(place.w));
    glm::vec2 draws[gpu_types::kRuleDraws] = {};
    for (uint32_t d = 0; rule && d < gpu_types::kRuleDraws; ++d) {
      float u = steerRandom(uint32_t(i), frame.step * gpu_types::kRuleDraws + d, p.seed);
      float heading = goalHeading + (u - 0.5f) * p.gazeAngle;
      draws[d] = prefSpeed * glm::vec2(std::sin(heading), std::cos(heading));
    }
    bool blocked = false, keepBlocked = false;
    uint32_t drawBlocked = 0;
    glm::vec2 avoid(0.0f);
    if (p.policy != SteerPolicy::None) {
      glm::ivec2 home = cellCoord(pos, grid.invCellSize);
      for (int dz = -range; dz <= range; ++dz) {
        for (int dx = -range; dx <= range; ++dx) {
          glm::ivec2 cell = home + glm::ivec2(dx, dz);
          uint32_t h = cellHash(cell, grid.cellCount);
          for (uint32_t k = grid.starts[h], end = k + grid.counts[h]; k < end; ++k) {
            const glm::vec4 other = grid.sorted[k];
            if (grid.sortedIndex[k] == i || cellCoord({other.x, other.y}, grid.invCellSize) != cell) continue;
            glm::vec2 x = pos - glm::vec2(other.x, other.y);
            float dist2 = glm::dot(x, x);
            if (dist2 >= sensing2) continue;
            if (rule) {
              glm::vec2 theirs(other.z, other.w);
              if (collides(x, vPref - theirs, p.lookahead, diameter2)) blocked = true;
              if (collides(x, keep - theirs, p.lookahead, diameter2)) keepBlocked = true;
              for (uint32_t d = 0; d < gpu_types::kRuleDraws; ++d)
                if (collides(x, draws[d] - theirs, p.lookahead, diameter2)) drawBlocked |= 1u << d;
            } else {
              avoid += ttcForce(p, x, vCur - glm::vec2(other.z, other.w), dist2);
            }
          }
        }
      }
    }
    glm::vec2 v = vPref;
    uint32_t flags = 0;
    if (rule && blocked) {
      bool inGaze = prefSpeed > 1e-4f && glm::dot(keep, vPref) >= cosHalfGaze * prefSpeed * prefSpeed;
      float waited = std::max(-steer[i].w, 0.0f) * frame.dt;
      if (!keepBlocked && inGaze) {
        v = keep;
        flags = gpu_types::kSteerFlagKept;
      } else {
        v = waited < gpu_types::kRuleMaxWait ? glm::vec2(0.0f) : draws[0];
        flags = waited < gpu_types::kRuleMaxWait ? gpu_types::kSteerFlagWaiting : gpu_types::kSteerFlagForced;
        for (uint32_t d = 0; d < gpu_types::kRuleDraws; ++d) {
          if ((drawBlocked & (1u << d)) == 0) {
            v = draws[d];
            flags = gpu_types::kSteerFlagTurned;
            break;
          }
        }
      }
    } else if (p.policy == SteerPolicy::Ttc) {
      float avoidLength = glm::length(avoid);
      if (avoidLength > p.ttcMaxForce) avoid *= p.ttcMaxForce / avoidLength;
      v = vCur + ((vPref - vCur) / p.ttcXi + avoid) * frame.dt;
      float speed = glm::length(v);
      if (speed > goal.z) v *= goal.z / speed;
    }
    float speed = glm::length(v);
    if (speed > 1e-3f) place.w = std::atan2(v.x, v.y);
    placement[i] = place;
    float state = flags == gpu_types::kSteerFlagWaiting ? std::min(steer[i].w, 0.0f) - 1.0f : float(flags);
    steer[i] = glm::vec4(v, speed, state);
    if (frame.fastSpeed > frame.slowSpeed)
      motion[i].z = std::clamp((speed - frame.slowSpeed) / (frame.fastSpeed - frame.slowSpeed), 0.0f, 1.0f);
  }
}

void advanceCpu(std::span<glm::vec4> placement, std::span<const glm::vec4> steer, std::span<const glm::vec4> goals,
                float dt) {
  for (size_t i = 0; i < placement.size(); ++i) {
    if (goals[i].w == 0.0f) continue;
    placement[i].x += steer[i].x * dt;
    placement[i].z += steer[i].y * dt;
  }
}

}  // namespace throng::crowd
