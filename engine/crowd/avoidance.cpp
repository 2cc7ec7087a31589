#include "crowd/avoidance.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "crowd/avoidance_types.h"
#include "crowd/obstacles.h"
#include "shaders/shared_types.h"

namespace throng::crowd {

std::optional<SteerPolicy> parseSteerPolicy(std::string_view name) {
  if (name == "none") return SteerPolicy::None;
  if (name == "published" || name == "rule") return SteerPolicy::Rule;
  if (name == "anticipatory" || name == "ttc") return SteerPolicy::Ttc;
  return std::nullopt;
}

std::string_view steerPolicyName(SteerPolicy policy) {
  switch (policy) {
    case SteerPolicy::None:
      return "none";
    case SteerPolicy::Rule:
      return "published";
    case SteerPolicy::Ttc:
      return "anticipatory";
  }
  return "?";
}

std::vector<std::string> validateParams(const AvoidanceParams& p) {
  std::vector<std::string> problems;
  auto positive = [&](float v, const char* name) {
    if (!(v > 0.0f) || !std::isfinite(v))
      problems.push_back(concat(name, " must be positive, got ", v));
  };
  if (uint32_t(p.policy) > 2u) problems.push_back(concat("unknown policy ", uint32_t(p.policy)));
  positive(p.cellSize.x, "cell width");
  positive(p.cellSize.y, "cell depth");
  positive(p.radius, "safe radius");
  positive(p.sensing, "sensing distance");
  positive(p.lookahead, "lookahead");
  positive(p.ttcTau0, "TTC tau0");
  positive(p.ttcXi, "TTC relaxation time xi");
  positive(p.ttcMaxForce, "TTC force cap");
  if (p.ttcMaxForce > 0.5f * gpu_types::kForceTermCap)
    problems.push_back(concat(
        "TTC force cap ", p.ttcMaxForce, " m/s^2 is above ", 0.5f * gpu_types::kForceTermCap,
        " (the fixed-point sum clamps each neighbour's term at ", gpu_types::kForceTermCap, ")"));
  if (!(p.densityRadius >= 0.0f && p.densityRadius <= p.sensing))
    problems.push_back(concat("density radius must lie in [0, sensing distance ", p.sensing,
                              "] m, got ", p.densityRadius));
  if (!(p.ttcK >= 0.0f)) problems.push_back(concat("TTC k must be >= 0, got ", p.ttcK));
  if (!(p.gazeAngle >= 0.0f && p.gazeAngle <= 6.2832f))
    problems.push_back(concat("gaze angle must lie in [0, 2 pi] radians, got ", p.gazeAngle));
  const float smallest = std::min(p.cellSize.x, p.cellSize.y);
  if (smallest > 0.0f && p.sensing > 0.0f && p.sensing > 8.0f * smallest)
    problems.push_back(concat("sensing distance ", p.sensing, " m spans more than 8 cells of ",
                              p.cellSize.x, " x ", p.cellSize.y, " m: use larger cells"));
  return problems;
}

glm::ivec2 cellRange(const AvoidanceParams& p) {
  return {std::max(1, int(std::ceil(p.sensing / p.cellSize.x))),
          std::max(1, int(std::ceil(p.sensing / p.cellSize.y)))};
}

GridTable gridTable(uint32_t agents) {
  GridTable t;
  t.cellCount = 1024;
  while (t.cellCount < kMaxGridCells && t.cellCount < agents) t.cellCount <<= 1;
  uint32_t log2Cells = 0;
  while ((1u << log2Cells) < t.cellCount) ++log2Cells;
  t.widthShift = (log2Cells + 1) / 2;  // at least as wide as tall
  t.rowMask = (t.cellCount >> t.widthShift) - 1u;
  return t;
}

std::array<ClipSpeeds, 4> clipSpeedTable(const SteerFrame& frame) {
  static_assert(gpu_types::kMaxClipSets == 4);
  std::array<ClipSpeeds, 4> table{};
  if (frame.sets.empty()) {
    table.fill({frame.slowSpeed, frame.fastSpeed, UINT32_MAX});
    return table;
  }
  if (frame.sets.size() > table.size())
    fail(frame.sets.size(), " clip sets: at most ", table.size(), " per steering pass");
  for (size_t k = 0; k < table.size(); ++k) {
    table[k] = frame.sets[std::min(k, frame.sets.size() - 1)];
    if (k > 0 && k < frame.sets.size() && table[k].end < table[k - 1].end)
      fail("clip set ", k, " ends at agent ", table[k].end, " before set ", k - 1, " (",
           table[k - 1].end, ")");
  }
  return table;
}

uint32_t pcgHash(uint32_t v) {
  uint32_t state = v * 747796405u + 2891336453u;
  uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

glm::ivec2 cellCoord(glm::vec2 p, glm::vec2 invCellSize) {
  return {int(std::floor(p.x * invCellSize.x)), int(std::floor(p.y * invCellSize.y))};
}

uint32_t cellIndex(glm::ivec2 c, const GridTable& table) {
  const uint32_t columnMask = (1u << table.widthShift) - 1u;
  return ((uint32_t(c.y) & table.rowMask) << table.widthShift) | (uint32_t(c.x) & columnMask);
}

float steerRandom(uint32_t agent, uint32_t step, uint32_t seed) {
  uint32_t h = pcgHash(agent ^ pcgHash(step ^ pcgHash(seed)));
  return float(h >> 8u) * (1.0f / 16777216.0f);
}

std::vector<uint32_t> gridOrder(std::span<const glm::vec4> placement, glm::vec2 cellSize,
                                GridTable table) {
  THRONG_CHECK(cellSize.x > 0.0f && cellSize.y > 0.0f, "grid cell size must be positive");
  // The CPU grid's own counting sort; the velocities it copies beside the positions are unused.
  const std::vector<glm::vec4> still(placement.size(), glm::vec4(0.0f));
  return buildGridCpu(placement, still, cellSize, table).sortedIndex;
}

Grid buildGridCpu(std::span<const glm::vec4> placement, std::span<const glm::vec4> steer,
                  glm::vec2 cellSize, GridTable table) {
  THRONG_CHECK(table.cellCount == (table.rowMask + 1u) << table.widthShift,
               "inconsistent grid table");
  THRONG_CHECK(steer.size() >= placement.size(), "steer smaller than placement");
  const size_t n = placement.size();
  Grid g;
  g.table = table;
  g.invCellSize = 1.0f / cellSize;
  g.cellOf.resize(n);
  g.counts.assign(table.cellCount, 0);
  g.starts.assign(table.cellCount + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    g.cellOf[i] = cellIndex(cellCoord({placement[i].x, placement[i].z}, g.invCellSize), table);
    ++g.counts[g.cellOf[i]];
  }
  uint32_t sum = 0;
  for (uint32_t c = 0; c < table.cellCount; ++c) g.starts[c] = sum, sum += g.counts[c];
  g.starts[table.cellCount] = sum;
  std::vector<uint32_t> cursor(g.starts.begin(), g.starts.end() - 1);
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

// Mirrors ttcForce in shaders/avoidance_steer.comp (floors of τ and √D explained there); the
// shader computes every branch and selects, which gives the values these branches return.
glm::vec2 ttcForce(const AvoidanceParams& p, glm::vec2 x, glm::vec2 v, float dist2) {
  const float diameter = 2.0f * p.radius;
  float c = dist2 - diameter * diameter;
  if (c < 0.0f)
    return dist2 > 1e-8f ? x * (p.ttcMaxForce * (1.0f / std::sqrt(dist2) - 0.5f / p.radius))
                         : glm::vec2(0.0f);
  float a = glm::dot(v, v);
  float b = glm::dot(x, v);
  float disc = b * b - a * c;
  if (b >= 0.0f || a < 1e-6f || disc <= 0.0f) return glm::vec2(0.0f);
  float s = std::sqrt(disc);
  float tau = c / (s - b);
  float t = std::max(tau, 0.1f);
  const float invTau0 = 1.0f / p.ttcTau0;
  float magnitude =
      p.ttcK * std::exp(-t * invTau0) * (2.0f + t * invTau0) / (t * t * t * std::max(s, 0.05f * a));
  return (x + tau * v) * magnitude;
}

// Mirrors wallTtcForce in shaders/avoidance_steer.comp: the TTC term of the first wall contact.
glm::vec2 wallTtcForce(const AvoidanceParams& p, glm::vec2 v, float tau, glm::vec2 n) {
  if (tau >= kNoWallHit) return glm::vec2(0.0f);
  const float t = std::max(tau, 0.1f);
  const float vn = std::max(-glm::dot(v, n), 0.025f * glm::dot(v, v) / p.radius);
  const float invTau0 = 1.0f / p.ttcTau0;
  return n * (p.ttcK * std::exp(-t * invTau0) * (2.0f + t * invTau0) / (t * t * t * vn));
}

// Mirrors toFixed in shaders/avoidance_steer.comp.
glm::ivec2 toFixed(glm::vec2 f) {
  auto one = [](float v) {
    return int(std::floor(std::clamp(v, -gpu_types::kForceTermCap, gpu_types::kForceTermCap) *
                              gpu_types::kForceScale +
                          0.5f));
  };
  return {one(f.x), one(f.y)};
}

// Mirrors collides() in shaders/avoidance_common.glsl (division-free).
bool collides(glm::vec2 x, glm::vec2 v, float horizon, float diameter2) {
  float xv = glm::dot(x, v);
  float vv = glm::dot(v, v);
  float xx = glm::dot(x, x);
  float horizonVv = horizon * vv;
  bool closestInside = -xv < horizonVv;
  bool hit = closestInside ? (xx - diameter2) * vv < xv * xv
                           : xx + horizon * (xv + xv + horizonVv) < diameter2;
  return xv < 0.0f && hit;
}

const ClipSpeeds& speedSet(const std::array<ClipSpeeds, 4>& table, uint32_t agent) {
  return agent < table[0].end   ? table[0]
         : agent < table[1].end ? table[1]
         : agent < table[2].end ? table[2]
                                : table[3];
}

}  // namespace

void steerCpu(const Grid& grid, const AvoidanceParams& p, const SteerFrame& frame,
              std::span<glm::vec4> placement, std::span<glm::vec4> motion,
              std::span<const glm::vec4> goals, std::span<glm::vec4> steer, const WallGrid* walls) {
  const size_t n = placement.size();
  THRONG_CHECK(!walls || walls->reach >= p.sensing, "steerCpu: walls binned to ",
               walls ? walls->reach : 0.0f, " m, the sensing distance is ", p.sensing, " m");
  THRONG_CHECK(
      motion.size() >= n && goals.size() >= n && steer.size() >= n && grid.cellOf.size() == n,
      "steerCpu: arrays of ", n, " agents expected");
  const float invSecondsLeft = 1.0f / frame.secondsLeft;
  const glm::ivec2 range = cellRange(p);
  const float diameter2 = 4.0f * p.radius * p.radius;
  const float sensing2 = p.sensing * p.sensing;
  const float cosHalfGaze = std::cos(0.5f * p.gazeAngle);
  const float densityInvRadius2 = densityPush(p).x, densityNorm = densityPush(p).y;
  const std::array<ClipSpeeds, 4> speeds = clipSpeedTable(frame);
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
    bool blocked = false, keepBlocked = false, agentBlocked = false;
    uint32_t drawBlocked = 0;
    glm::ivec2 force(0);
    uint32_t density = 0;
    if (p.policy != SteerPolicy::None) {
      glm::ivec2 home = cellCoord(pos, grid.invCellSize);
      for (int dz = -range.y; dz <= range.y; ++dz) {
        for (int dx = -range.x; dx <= range.x; ++dx) {
          uint32_t cell = cellIndex(home + glm::ivec2(dx, dz), grid.table);
          for (uint32_t k = grid.starts[cell], end = grid.starts[cell + 1]; k < end; ++k) {
            const glm::vec4 other = grid.sorted[k];
            if (grid.sortedIndex[k] == i) continue;
            glm::vec2 x = pos - glm::vec2(other.x, other.y);
            float dist2 = glm::dot(x, x);
            if (dist2 >= sensing2) continue;
            density += densityWeight(x, dist2, vPref, densityInvRadius2);
            if (rule) {
              glm::vec2 theirs(other.z, other.w);
              if (collides(x, vPref - theirs, p.lookahead, diameter2))
                blocked = agentBlocked = true;
              if (collides(x, keep - theirs, p.lookahead, diameter2)) keepBlocked = true;
              for (uint32_t d = 0; d < gpu_types::kRuleDraws; ++d)
                if (collides(x, draws[d] - theirs, p.lookahead, diameter2)) drawBlocked |= 1u << d;
            } else {
              force += toFixed(ttcForce(p, x, vCur - glm::vec2(other.z, other.w), dist2));
            }
          }
        }
      }
      const uint32_t wallCell = walls ? walls->cellOf(pos) : UINT32_MAX;
      float firstTau = kNoWallHit;
      glm::vec2 firstNormal(0.0f);
      for (uint32_t k = wallCell == UINT32_MAX ? 0 : walls->starts[wallCell],
                    end = wallCell == UINT32_MAX ? 0 : walls->starts[wallCell + 1];
           k < end; ++k) {
        const Segment& s = walls->segments[walls->indices[k]];
        if (!rule) {  // as scanWalls in the shader: overlaps pushed out, else the first contact
          const glm::vec2 off = pos - closestOnSegment(pos, s.a, s.b);
          const float d2 = glm::dot(off, off);
          if (d2 >= sensing2) continue;
          if (d2 < p.radius * p.radius) {
            if (d2 > 1e-8f)
              force += toFixed(off * (p.ttcMaxForce * (1.0f / std::sqrt(d2) - 1.0f / p.radius)));
            continue;
          }
          // Moving along or away from the closest point never touches the segment (the
          // shader's screen; segmentHit would find no contact either).
          if (!(glm::dot(vCur, off) < 0.0f)) continue;
          glm::vec2 normal;
          const float tau = segmentHit(pos, vCur, s.a, s.b, p.radius, normal);
          if (tau < firstTau) firstTau = tau, firstNormal = normal;
          continue;
        }
        // The rule: the closest point is a neighbour that never moves, of no size.
        const glm::vec2 x = pos - closestOnSegment(pos, s.a, s.b);
        const float ruleReach = p.radius + glm::length(vPref) * p.lookahead;  // screen as the GPU
        if (glm::dot(x, x) >= sensing2 || glm::dot(x, x) > ruleReach * ruleReach) continue;
        const float r2 = p.radius * p.radius;
        if (collides(x, vPref, p.lookahead, r2)) blocked = true;
        if (collides(x, keep, p.lookahead, r2)) keepBlocked = true;
        for (uint32_t d = 0; d < gpu_types::kRuleDraws; ++d)
          if (collides(x, draws[d], p.lookahead, r2)) drawBlocked |= 1u << d;
      }
      if (p.policy == SteerPolicy::Ttc)
        force += toFixed(wallTtcForce(p, vCur, firstTau, firstNormal));
    }
    const float cap = goal.z * densitySpeedFactor(density, densityNorm);
    glm::vec2 v = vPref;
    uint32_t flags = 0;
    if (rule && blocked) {
      bool inGaze =
          prefSpeed > 1e-4f && glm::dot(keep, vPref) >= cosHalfGaze * prefSpeed * prefSpeed;
      float waited = std::max(-steer[i].w, 0.0f) * frame.dt;
      if (!keepBlocked && inGaze) {
        v = keep;
        flags = gpu_types::kSteerFlagKept;
      } else {
        v = waited < gpu_types::kRuleMaxWait ? glm::vec2(0.0f) : draws[0];
        flags = waited < gpu_types::kRuleMaxWait ? gpu_types::kSteerFlagWaiting
                                                 : gpu_types::kSteerFlagForced;
        for (uint32_t d = 0; d < gpu_types::kRuleDraws; ++d) {
          if ((drawBlocked & (1u << d)) == 0) {
            v = draws[d];
            flags = gpu_types::kSteerFlagTurned;
            break;
          }
        }
        // Blocked by walls alone: the course, which the wall constraint slides along them.
        if (flags != gpu_types::kSteerFlagTurned && !agentBlocked) v = vPref, flags = 0;
      }
    } else if (p.policy == SteerPolicy::Ttc) {
      glm::vec2 avoid = glm::vec2(force) * (1.0f / gpu_types::kForceScale);
      float avoidLength = glm::length(avoid);
      if (avoidLength > p.ttcMaxForce) avoid *= p.ttcMaxForce / avoidLength;
      const glm::vec2 pref = prefSpeed > cap ? vPref * (cap / prefSpeed) : vPref;
      v = vCur + ((pref - vCur) / p.ttcXi + avoid) * frame.dt;
      const float fast = glm::length(v);
      if (fast > goal.z) v *= goal.z / fast;  // avoidance may still use the full speed
    }
    if (rule && prefSpeed > cap) v *= cap / prefSpeed;  // as the shader: the courses together
    float speed = glm::length(v);
    if (speed > 1e-3f) place.w = std::atan2(v.x, v.y);
    placement[i] = place;
    float state =
        flags == gpu_types::kSteerFlagWaiting ? std::min(steer[i].w, 0.0f) - 1.0f : float(flags);
    steer[i] = glm::vec4(v, speed, state);
    const ClipSpeeds& set = speedSet(speeds, uint32_t(i));
    if (set.fast > set.slow)
      motion[i] = gpu_types::withTargetSpeedWeight(
          motion[i], std::clamp((speed - set.slow) / (set.fast - set.slow), 0.0f, 1.0f));
  }
}

glm::vec2 densityPush(const AvoidanceParams& p) {
  if (!(p.densityRadius > 0.0f)) return glm::vec2(0.0f);
  const float r2 = p.densityRadius * p.densityRadius;
  return {1.0f / r2, 6.0f / (3.14159265f * r2)};  // the half disc ahead
}

uint32_t densityWeight(glm::vec2 x, float dist2, glm::vec2 dir, float invRadius2) {
  const float t = std::max(1.0f - dist2 * invRadius2, 0.0f);
  return dist2 > 0.0f && glm::dot(x, dir) < 0.0f ? uint32_t(t * t * gpu_types::kDensityScale + 0.5f)
                                                 : 0u;
}

float densitySpeedFactor(uint32_t weights, float norm) {
  const float rho = float(weights) * (norm / gpu_types::kDensityScale);
  const float f = rho > 0.0f ? 1.0f - std::exp(-gpu_types::kWeidmannGamma *
                                               (1.0f / rho - 1.0f / gpu_types::kWeidmannMaxDensity))
                             : 1.0f;
  return std::clamp(std::floor(f * 1024.0f + 0.5f) * (1.0f / 1024.0f), gpu_types::kDensityMinSpeed,
                    1.0f);  // as the shader: steps of 1/1024, so an ulp of exp changes nothing
}

void advanceCpu(std::span<glm::vec4> placement, std::span<const glm::vec4> steer,
                std::span<const glm::vec4> goals, float dt) {
  for (size_t i = 0; i < placement.size(); ++i) {
    if (goals[i].w == 0.0f) continue;
    placement[i].x += steer[i].x * dt;
    placement[i].z += steer[i].y * dt;
  }
}

}  // namespace throng::crowd
