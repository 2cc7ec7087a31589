#include "crowd/crowd_sim.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "core/error.h"
#include "crowd/avoidance_jobs.h"
#include "gpu/commands.h"

namespace throng::crowd {
namespace {

// Agents not active yet (or any more) wait far away, each in its own cell, so they meet nobody.
glm::vec4 parked(size_t i, float heading) {
  return glm::vec4(1.0e5f + 8.0f * float(i % 4096), 0.0f, 1.0e5f + 8.0f * float(i / 4096), heading);
}

glm::vec2 capped(glm::vec2 v, float maxLength) {
  float l = glm::length(v);
  return l > maxLength && l > 0.0f ? v * (maxLength / l) : v;
}

// The GPU side of a run: the crowd and steering buffers stay resident; the CPU copy of the
// placement is refreshed every step (the metrics need it), the rest only when agents come or go.
struct GpuRun {
  const gpu::Context& context;
  AvoidancePrograms programs;
  CrowdBuffers crowd;
  SteerBuffers agents;
  GridBuffers grid;

  std::unique_ptr<WallBuffers> walls;  // with walls: the segments

  GpuRun(const gpu::Context& ctx, const Crowd& c, std::span<const glm::vec4> goals,
         std::span<const glm::vec4> steer, glm::vec2 cellSize, const WallGrid* wallGrid)
      : context(ctx),
        programs(ctx),
        crowd(uploadCrowd(ctx, c)),
        agents(uploadSteer(ctx, goals, steer)),
        grid(makeGridBuffers(ctx, uint32_t(c.size()), cellSize)) {
    if (!wallGrid) return;
    walls = std::make_unique<WallBuffers>(uploadWalls(ctx, *wallGrid));
  }

  // Grid, steering and the advance (with walls, constrained in the same pass) of one step.
  void record(VkCommandBuffer cmd, const AvoidanceParams& avoidance, const SteerFrame& frame,
              float radius) {
    GridJob gridJob{&crowd, &agents, &grid};
    AvoidanceJob avoid{&crowd, &agents, &grid, avoidance, frame, walls.get()};
    AdvanceJob advance{&crowd, &agents, frame.dt, walls.get(), radius};
    gridJob.record(cmd, programs);
    gpu::computeToComputeBarrier(cmd);
    avoid.record(cmd, programs);
    gpu::computeToComputeBarrier(cmd);
    advance.record(cmd, programs);
  }

  template <typename T>
  void upload(const gpu::Buffer& buffer, std::span<const T> data) {
    gpu::uploadBytes(context, buffer,
                     {reinterpret_cast<const uint8_t*>(data.data()), data.size_bytes()});
  }
};

// The first second at or after `s` in which some agent is active (UINT32_MAX: none).
uint32_t nextArrival(const AgentPaths& paths, uint32_t s) {
  uint32_t next = std::numeric_limits<uint32_t>::max();
  for (size_t i = 0; i < paths.size(); ++i)
    if (paths.lastSecond[i] > s && paths.lastSecond[i] > paths.firstSecond[i])
      next = std::min(next, std::max(s, paths.firstSecond[i]));
  return next;
}

}  // namespace

WallGrid binWallsFor(const Obstacles& walls, const AvoidanceParams& avoidance) {
  // Cells of half the sensing distance: an agent's list then holds the segments within about
  // 1.5 sensing distances instead of 2.4 with cells as large as the reach (fewer segments read
  // per agent and step), for about three times the entries.
  const float cell = 0.5f * avoidance.sensing;
  return binObstacles(walls, cell, std::max(avoidance.sensing, 2.0f * avoidance.radius));
}

std::vector<float> expectedSpeeds(const AgentPaths& paths, uint32_t seconds) {
  std::vector<float> speeds;
  for (size_t i = 0; i < paths.size(); ++i)
    for (uint32_t s = paths.firstSecond[i]; s < std::min(seconds, paths.lastSecond[i]); ++s) {
      uint32_t j = s - paths.firstSecond[i] + 1;
      speeds.push_back(glm::length(paths.waypoint(i, j) - paths.waypoint(i, j - 1)));
    }
  return speeds;
}

SimulationSetup replaySetup(std::span<const PathSource> sources, std::string_view origin) {
  if (sources.empty())
    fail(origin, ": no tracked person spans two whole seconds (expected at least one track of ",
         "two or more annotations two seconds apart): nothing to replay");
  glm::vec2 centre(0.0f);
  for (const PathSource& s : sources) centre += s.start;
  centre /= float(sources.size());
  SimulationSetup setup;
  setup.paths = replaySources(sources, centre, 2.5f);
  setup.crowd.resize(sources.size());
  for (size_t i = 0; i < sources.size(); ++i) {
    glm::vec2 first = sources[i].vectors.front();
    setup.crowd.placement[i] = glm::vec4(0.0f, 0.0f, 0.0f, std::atan2(first.x, first.y));
  }
  return setup;
}

SimulationResult simulateCrowd(const gpu::Context* context, const SimulationSetup& setup,
                               const SimulationOptions& options) {
  const std::vector<std::string> problems = validateParams(options.avoidance);
  if (!problems.empty()) fail("avoidance parameters: ", problems.front());
  const int stepsPerSecond = int(std::lround(1.0 / double(options.dt)));
  if (!(options.dt > 0.0f) || stepsPerSecond < 1 || stepsPerSecond > 1000 ||
      std::abs(double(stepsPerSecond) * options.dt - 1.0) > 1e-3)
    fail("step ", options.dt, " s: expected 1/n of a second (e.g. 0.05) with n in 1..1000");
  if (setup.paths.size() != setup.crowd.size())
    fail("simulation setup: ", setup.crowd.size(), " agents but ", setup.paths.size(), " paths");
  const float dt = 1.0f / float(stepsPerSecond);
  const uint32_t seconds = std::max(1u, uint32_t(options.seconds));
  const size_t n = setup.crowd.size();
  const AgentPaths& paths = setup.paths;

  SimulationResult result;
  Crowd& crowd = result.crowd;
  crowd = setup.crowd;
  std::vector<glm::vec4>& steer = result.steer;
  steer.assign(n, glm::vec4(0.0f));
  std::vector<glm::vec4> goals(n, glm::vec4(0.0f));
  std::vector<uint8_t> active(n, 0);
  std::vector<glm::vec2> secondStart(n);
  std::vector<float> speeds, pathErrors;
  if (!(options.bodyRadius > 0.0f && options.bodyRadius <= 10.0f))
    fail("body radius ", options.bodyRadius, " m: expected 0 < radius <= 10 m");
  CollisionCounter collisions(options.bodyRadius), intrusions(options.avoidance.radius);
  std::unique_ptr<GpuRun> gpuRun;
  std::optional<WallGrid> walls;
  if (options.walls) walls = binWallsFor(*options.walls, options.avoidance);
  const WallGrid* wallGrid = walls ? &*walls : nullptr;
  std::vector<glm::vec4> previous;
  const auto started = std::chrono::steady_clock::now();

  for (uint32_t s = 0; s < seconds; ++s) {
    // Nobody on the scene and nobody due: skip to the next arrival (a file may have long gaps).
    if (s > 0 && std::none_of(active.begin(), active.end(), [](uint8_t a) { return a != 0; })) {
      s = std::min(seconds, nextArrival(paths, s));
      if (s == seconds) break;
    }
    // Agents appear at their start heading for their first waypoint, and leave when done.
    bool changed = s == 0;
    for (size_t i = 0; i < n; ++i) {
      bool now = paths.active(i, s);
      if (s == 0 && !now) crowd.placement[i] = parked(i, crowd.placement[i].w);
      if (now && s == paths.firstSecond[i]) {
        if (!changed && gpuRun) {
          crowd.motion = gpu::readback<glm::vec4>(*context, gpuRun->crowd.motion, n);
          steer = gpu::readback<glm::vec4>(*context, gpuRun->agents.steer, n);
        }
        changed = true;
        glm::vec2 start = paths.waypoint(i, 0);
        crowd.placement[i] = glm::vec4(start.x, 0.0f, start.y, crowd.placement[i].w);
        glm::vec2 v = capped(paths.waypoint(i, 1) - start, paths.maxSpeed[i]);
        steer[i] = glm::vec4(v, glm::length(v), 0.0f);
      } else if (!now && active[i]) {
        if (!changed && gpuRun) {
          crowd.motion = gpu::readback<glm::vec4>(*context, gpuRun->crowd.motion, n);
          steer = gpu::readback<glm::vec4>(*context, gpuRun->agents.steer, n);
        }
        changed = true;
        crowd.placement[i] = parked(i, crowd.placement[i].w);
        steer[i] = glm::vec4(0.0f);
      }
      active[i] = now;
      secondStart[i] = glm::vec2(crowd.placement[i].x, crowd.placement[i].z);
    }
    writeGoals(paths, s, goals);
    if (context) {
      if (!gpuRun) {
        gpuRun = std::make_unique<GpuRun>(*context, crowd, goals, steer, options.avoidance.cellSize,
                                          wallGrid);
      } else {
        gpuRun->upload<glm::vec4>(gpuRun->agents.goals, goals);
        if (changed) {
          gpuRun->upload<glm::vec4>(gpuRun->crowd.placement, crowd.placement);
          gpuRun->upload<glm::vec4>(gpuRun->crowd.motion, crowd.motion);
          gpuRun->upload<glm::vec4>(gpuRun->agents.steer, steer);
        }
      }
    }
    if (options.observer && s == 0) options.observer->observe(0, crowd.placement, active);
    for (int k = 0; k < stepsPerSecond; ++k) {
      SteerFrame frame;
      frame.dt = dt;
      frame.secondsLeft = 1.0f - float(k) * dt;
      frame.step = s * uint32_t(stepsPerSecond) + uint32_t(k);
      frame.slowSpeed = options.slowSpeed;
      frame.fastSpeed = options.fastSpeed;
      if (gpuRun) {
        gpu::submitAndWait(*context, [&](VkCommandBuffer cmd) {
          gpuRun->record(cmd, options.avoidance, frame, options.avoidance.radius);
        });
        crowd.placement = gpu::readback<glm::vec4>(*context, gpuRun->crowd.placement, n);
      } else {
        Grid grid = buildGridCpu(crowd.placement, steer, options.avoidance.cellSize,
                                 gridTable(uint32_t(n)));
        steerCpu(grid, options.avoidance, frame, crowd.placement, crowd.motion, goals, steer,
                 wallGrid);
        if (wallGrid) previous = crowd.placement;
        advanceCpu(crowd.placement, steer, goals, dt);
        if (wallGrid)
          wallConstraintCpu(*wallGrid, options.avoidance.radius, previous, crowd.placement, 0,
                            uint32_t(n));
      }
      collisions.addStep(crowd.placement, active, dt);
      intrusions.addStep(crowd.placement, active, dt);
      ++result.steps;
      if (options.observer)
        options.observer->observe(uint64_t(frame.step) + 1, crowd.placement, active);
    }
    for (size_t i = 0; i < n; ++i) {
      if (!active[i]) continue;
      glm::vec2 p(crowd.placement[i].x, crowd.placement[i].z);
      speeds.push_back(glm::length(p - secondStart[i]));
      pathErrors.push_back(glm::length(p - paths.waypoint(i, s - paths.firstSecond[i] + 1)));
    }
  }
  if (gpuRun) {
    crowd.motion = gpu::readback<glm::vec4>(*context, gpuRun->crowd.motion, n);
    steer = gpu::readback<glm::vec4>(*context, gpuRun->agents.steer, n);
  }
  result.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  CrowdMetrics& m = result.metrics;
  m.seconds = seconds;
  m.agents = n;
  setContactMetrics(m, collisions, options.bodyRadius, intrusions, options.avoidance.radius);
  const std::vector<float> reference = expectedSpeeds(paths, seconds);
  m.speedKs = ksDistance(speeds, reference);
  m.speedSamples = speeds.size();
  auto mean = [](const std::vector<float>& v) {
    double sum = 0.0;
    for (float x : v) sum += x;
    return v.empty() ? 0.0 : sum / double(v.size());
  };
  m.meanSpeed = mean(speeds);
  m.sourceMeanSpeed = mean(reference);
  if (!pathErrors.empty()) {
    m.meanPathError = mean(pathErrors);
    std::sort(pathErrors.begin(), pathErrors.end());
    m.p95PathError =
        pathErrors[std::min(pathErrors.size() - 1, size_t(0.95 * double(pathErrors.size())))];
    m.maxPathError = pathErrors.back();
  }
  return result;
}

}  // namespace throng::crowd
