#include "crowd/nav_jobs.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"
#include "shaders/nav_bindings.h"

namespace throng::crowd {
namespace {

uint32_t floatBits(float f) {
  uint32_t bits = 0;
  std::memcpy(&bits, &f, 4);
  return bits;
}

float bitsFloat(uint32_t bits) {
  float f = 0.0f;
  std::memcpy(&f, &bits, 4);
  return f;
}

template <typename T>
std::span<const uint8_t> bytesOf(const std::vector<T>& v) {
  return {reinterpret_cast<const uint8_t*>(v.data()), v.size() * sizeof(T)};
}

glm::vec2 unitOr0(glm::vec2 v) {
  const float len = glm::length(v);
  return len > 1e-6f ? v / len : glm::vec2(0.0f);
}

// As nav_follow.comp: the agent at p has rounded waypoint c (reached from a, leaving for b).
bool rounded(glm::vec2 p, glm::vec2 a, glm::vec2 c, glm::vec2 b) {
  const glm::vec2 n = unitOr0(c - a) + unitOr0(b - c);
  return glm::dot(n, n) > 1e-4f && glm::dot(p - c, n) > 0.0f;
}

gpu::Buffer waypointBuffer(const gpu::Context& context, const std::vector<glm::vec2>& waypoints,
                           size_t capacity) {
  gpu::Buffer b(context, std::max<VkDeviceSize>(capacity * sizeof(glm::vec2), 16),
                gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  if (!waypoints.empty()) gpu::uploadBytes(context, b, bytesOf(waypoints));
  return b;
}

}  // namespace

NavPaths packPaths(const std::vector<std::vector<glm::vec2>>& paths,
                   std::span<const float> maxSpeed) {
  if (paths.size() != maxSpeed.size())
    fail("navigation: ", paths.size(), " paths but ", maxSpeed.size(), " max speeds");
  NavPaths packed;
  packed.agentPath.resize(paths.size());
  for (size_t i = 0; i < paths.size(); ++i) {
    if (paths[i].size() == 1) fail("navigation: the path of agent ", i, " has a single point");
    packed.agentPath[i] = glm::uvec4(uint32_t(packed.waypoints.size()), uint32_t(paths[i].size()),
                                     floatBits(maxSpeed[i]), 0u);
    packed.waypoints.insert(packed.waypoints.end(), paths[i].begin(), paths[i].end());
  }
  return packed;
}

NavBuffers uploadNav(const gpu::Context& context, const NavPaths& paths) {
  NavBuffers b;
  b.count = uint32_t(paths.agentPath.size());
  b.waypointCount = uint32_t(paths.waypoints.size());
  b.agentPath = gpu::makeStorageBuffer<glm::uvec4>(context, paths.agentPath);
  b.waypoints = waypointBuffer(context, paths.waypoints, paths.waypoints.size());
  const std::vector<uint32_t> progress(b.count, 1u);
  b.progress = gpu::makeStorageBuffer<uint32_t>(context, progress);
  return b;
}

void updateNav(const gpu::Context& context, NavBuffers& buffers, const NavPaths& paths,
               std::span<const uint32_t> changed) {
  if (paths.agentPath.size() != buffers.count)
    fail("navigation: ", paths.agentPath.size(), " paths for buffers of ", buffers.count);
  std::vector<uint32_t> progress =
      gpu::readback<uint32_t>(context, buffers.progress, buffers.count);
  for (uint32_t i : changed) progress.at(i) = 1u;
  gpu::uploadBytes(context, buffers.progress, bytesOf(progress));
  gpu::uploadBytes(context, buffers.agentPath, bytesOf(paths.agentPath));
  // Grown by half again, so agents replanning one after another do not reallocate each time.
  if (paths.waypoints.size() * sizeof(glm::vec2) > buffers.waypoints.size())
    buffers.waypoints = waypointBuffer(context, paths.waypoints, paths.waypoints.size() * 3 / 2);
  else if (!paths.waypoints.empty())
    gpu::uploadBytes(context, buffers.waypoints, bytesOf(paths.waypoints));
  buffers.waypointCount = uint32_t(paths.waypoints.size());
}

NavPrograms::NavPrograms(const gpu::Context& context) : follow(context, "nav_follow.comp") {}

std::vector<std::string> NavFollowJob::validate() const {
  std::vector<std::string> problems;
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (!nav) problems.push_back("input 'nav' (path) buffers are missing");
  if (!agents) problems.push_back("output 'agents' (goal buffer) is missing");
  if (!crowd || !nav || !agents) return problems;
  if (nav->count != crowd->count || agents->count != crowd->count)
    problems.push_back(concat("the crowd has ", crowd->count, " agents, the paths ", nav->count,
                              " and the steering buffers ", agents->count));
  const VkDeviceSize vec4s = VkDeviceSize(crowd->count) * sizeof(glm::vec4);
  if (!crowd->placement || crowd->placement.size() < vec4s)
    problems.push_back(concat("buffer 'placement' is smaller than ", crowd->count, " agents"));
  if (!agents->goals || agents->goals.size() < vec4s)
    problems.push_back(concat("buffer 'goals' is smaller than ", crowd->count, " goals"));
  if (!nav->agentPath || nav->agentPath.size() < VkDeviceSize(nav->count) * sizeof(glm::uvec4) ||
      !nav->progress || nav->progress.size() < VkDeviceSize(nav->count) * 4 || !nav->waypoints ||
      nav->waypoints.size() < VkDeviceSize(nav->waypointCount) * sizeof(glm::vec2))
    problems.push_back("a path buffer is not allocated or too small (make them with uploadNav)");
  if (!(reach > 0.0f) || !(secondsLeft > 0.0f))
    problems.push_back(
        concat("reach (", reach, ") and seconds left (", secondsLeft, ") must be > 0"));
  return problems;
}

void NavFollowJob::record(VkCommandBuffer cmd, const NavPrograms& programs) const {
  gpu::throwIfInvalid("NavFollowJob", validate());
  NavFollowPush push{};
  push.agentCount = crowd->count;
  push.reach = reach;
  push.secondsLeft = secondsLeft;
  const gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kNavFollowBindingPlacement, crowd->placement),
      gpu::storageBinding(gpu_types::kNavFollowBindingPath, nav->agentPath),
      gpu::storageBinding(gpu_types::kNavFollowBindingWaypoints, nav->waypoints),
      gpu::storageBinding(gpu_types::kNavFollowBindingProgress, nav->progress),
      gpu::storageBinding(gpu_types::kNavFollowBindingGoals, agents->goals)};
  gpu::dispatch(cmd, programs.follow, bindings, push, crowd->count);
}

void navFollowCpu(std::span<const glm::vec4> placement, const NavPaths& paths,
                  std::span<uint32_t> progress, float reach, float secondsLeft,
                  std::span<glm::vec4> goals) {
  const size_t n = paths.agentPath.size();
  if (placement.size() < n || progress.size() < n || goals.size() < n)
    fail("navFollowCpu: arrays shorter than the ", n, " paths");
  for (size_t i = 0; i < n; ++i) {
    const glm::uvec4 path = paths.agentPath[i];
    if (path.y < 2u) {
      goals[i] = glm::vec4(0.0f);
      continue;
    }
    const glm::vec2 p(placement[i].x, placement[i].z);
    const glm::vec2* w = paths.waypoints.data() + path.x;
    const uint32_t last = path.y - 1u;
    uint32_t k = std::clamp(progress[i], 1u, last);
    while (k < last && (glm::distance(p, w[k]) < reach || rounded(p, w[k - 1], w[k], w[k + 1])))
      ++k;
    progress[i] = k;
    const float maxSpeed = bitsFloat(path.z);
    glm::vec2 target = w[k];
    if (k < last) {
      const glm::vec2 d = target - p;
      const float len = glm::length(d), ahead = maxSpeed * secondsLeft;
      if (len > 1e-6f && len < ahead) target = p + d * (ahead / len);
    }
    goals[i] = glm::vec4(target, maxSpeed, 1.0f);
  }
}

GoalSteering::GoalSteering(const gpu::Context& context, GoalScene scene,
                           std::span<const glm::vec4> placement)
    : machine_(std::move(scene), placement.size()), programs_(context) {
  if (placement.empty()) fail("goal steering needs at least one agent");
  const GoalScene& s = machine_.scene();
  maxSpeed_.resize(placement.size(), 0.0f);
  for (size_t i = 0; i < placement.size(); ++i)
    if (s.agentGroup[i] != kNoState) maxSpeed_[i] = s.groups[s.agentGroup[i]].maxSpeed;
  std::vector<glm::vec2> positions(placement.size());
  for (size_t i = 0; i < placement.size(); ++i) positions[i] = {placement[i].x, placement[i].z};
  machine_.evaluate(positions, 0.0);
  nav_ = uploadNav(context, packPaths(machine_.paths(), maxSpeed_));
}

void GoalSteering::update(const gpu::Context& context, const CrowdBuffers& crowd, double seconds) {
  if (crowd.count != count())
    fail("goal steering: ", count(), " agents but the crowd has ", crowd.count);
  const std::vector<glm::vec4> placement =
      gpu::readback<glm::vec4>(context, crowd.placement, crowd.count);
  std::vector<glm::vec2> positions(placement.size());
  for (size_t i = 0; i < placement.size(); ++i) positions[i] = {placement[i].x, placement[i].z};
  // The waypoint each agent heads for, for the stuck rule (GoalScene::stuckSeconds).
  const std::vector<uint32_t> progress =
      gpu::readback<uint32_t>(context, nav_.progress, nav_.count);
  const std::vector<uint32_t> changed = machine_.evaluate(positions, seconds, progress);
  if (!changed.empty()) updateNav(context, nav_, packPaths(machine_.paths(), maxSpeed_), changed);
}

void GoalSteering::record(VkCommandBuffer cmd, const CrowdBuffers& crowd, const SteerBuffers& steer,
                          const SteerFrame& frame) const {
  // The previous frame's passes moved the agents this pass reads.
  gpu::computeToComputeBarrier(cmd);
  NavFollowJob job{&crowd, &nav_, &steer, machine_.scene().waypointReach, frame.secondsLeft};
  job.record(cmd, programs_);
  gpu::computeToComputeBarrier(cmd);
}

}  // namespace throng::crowd
