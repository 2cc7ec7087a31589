#include "crowd/path_goals.h"

#include <cstring>

#include "core/error.h"
#include "crowd/avoidance_types.h"
#include "shaders/crowd_bindings.h"

namespace throng::crowd {

PathBuffers uploadPaths(const gpu::Context& context, const AgentPaths& paths) {
  const size_t n = paths.size();
  std::vector<glm::uvec2> ranges;
  std::vector<glm::vec2> cumulative;
  if (!paths.holdsEnd.empty() && paths.holdsEnd.size() != paths.cumulative.size())
    fail("paths: ", paths.holdsEnd.size(), " hold flags for ", paths.cumulative.size(), " sources");
  for (size_t k = 0; k < paths.cumulative.size(); ++k) {
    const std::vector<glm::vec2>& c = paths.cumulative[k];
    if (c.size() < 2) fail("a path source has no path vector");
    if (c.size() - 1 >= gpu_types::kPathHoldsEnd) fail("a path source has too many vectors");
    const uint32_t hold = paths.holds(uint32_t(k)) ? gpu_types::kPathHoldsEnd : 0u;
    ranges.push_back({uint32_t(cumulative.size()), uint32_t(c.size() - 1) | hold});
    cumulative.insert(cumulative.end(), c.begin(), c.end());
  }
  std::vector<glm::vec4> start(n);
  std::vector<glm::uvec4> info(n);
  for (size_t i = 0; i < n; ++i) {
    if (paths.source[i] >= ranges.size())
      fail("agent ", i, " follows source ", paths.source[i], " of ", ranges.size());
    start[i] = glm::vec4(paths.start[i], paths.rotation[i]);
    uint32_t speedBits = 0;
    std::memcpy(&speedBits, &paths.maxSpeed[i], 4);
    info[i] = glm::uvec4(paths.source[i], paths.firstSecond[i], paths.lastSecond[i], speedBits);
  }
  PathBuffers b;
  b.count = uint32_t(n);
  b.agentStart = gpu::makeStorageBuffer<glm::vec4>(context, start);
  b.agentInfo = gpu::makeStorageBuffer<glm::uvec4>(context, info);
  b.sourceRange = gpu::makeStorageBuffer<glm::uvec2>(context, ranges);
  b.cumulative = gpu::makeStorageBuffer<glm::vec2>(context, cumulative);
  return b;
}

std::vector<std::string> GoalJob::validate() const {
  std::vector<std::string> problems;
  if (!paths) problems.push_back("input 'paths' buffers are missing");
  if (!agents) problems.push_back("output 'agents' (goal buffer) is missing");
  if (!paths || !agents) return problems;
  if (paths->count != agents->count)
    problems.push_back(concat("the paths describe ", paths->count,
                              " agents but the steering buffers ", agents->count));
  if (!paths->agentStart || !paths->agentInfo || !paths->sourceRange || !paths->cumulative)
    problems.push_back("a path buffer is not allocated");
  if (!agents->goals || agents->goals.size() < VkDeviceSize(agents->count) * sizeof(glm::vec4))
    problems.push_back(concat("buffer 'goals' is smaller than ", agents->count, " goals"));
  return problems;
}

void GoalJob::record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const {
  std::vector<std::string> problems = validate();
  if (!problems.empty()) {
    std::string message = "GoalJob is invalid:";
    for (const std::string& p : problems) message += "\n  - " + p;
    throw Error(message);
  }
  GoalPush push{};
  push.agentCount = agents->count;
  push.second = second;
  const gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kGoalsBindingAgentStart, paths->agentStart),
      gpu::storageBinding(gpu_types::kGoalsBindingAgentInfo, paths->agentInfo),
      gpu::storageBinding(gpu_types::kGoalsBindingSourceRange, paths->sourceRange),
      gpu::storageBinding(gpu_types::kGoalsBindingCumulative, paths->cumulative),
      gpu::storageBinding(gpu_types::kGoalsBindingGoals, agents->goals)};
  gpu::dispatch(cmd, programs.goals, bindings, push, agents->count);
}

}  // namespace throng::crowd
