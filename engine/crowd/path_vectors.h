#pragma once
// Path vectors (docs/design.md, "Storyboard crowds"): a tracked person i resampled once per second,
// P_ij = pos_i(j) − pos_i(j−1). An agent copies one source person's vectors in order from its
// own start: during second j it heads for start + R·Σ_{k≤j} P_ik, R turning the source's
// overall direction of travel onto the agent's heading (so a storyboard glyph still says where
// the agent goes). When the sequence ends it starts over from where the agent is.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "anim/motion_texture.h"
#include "crowd/crowd.h"
#include "crowd/trajectories.h"

namespace throng::crowd {

struct PathSource {
  int id = 0;                      // the tracked person
  uint32_t startSecond = 0;        // first sample: the file's start time + startSecond seconds
  glm::vec2 start{0};              // position at that second (data plane)
  std::vector<glm::vec2> vectors;  // P_i1 … P_in
  float meanSpeed() const;         // mean |P_ij| (m/s)
};

// Samples every track at the whole seconds (file start + k seconds) inside its time span,
// by linear interpolation between annotations, so sources share one clock (a replay keeps
// people's relative timing). Tracks spanning fewer than two such samples are dropped.
std::vector<PathSource> resamplePathVectors(const Trajectories& trajectories);

// |P_ij| of every vector of every source (the per-second speeds of the real people).
std::vector<float> pathSpeeds(std::span<const PathSource> sources);

struct SpeedRange {
  float min = 0.0f, max = 0.0f;  // m/s
};

// For each agent, a source whose mean speed lies in the agent's range (its storyboard state:
// strolling or hurried), chosen at random among them; when none does, the nearest in mean
// speed. Deterministic per seed. Throws Error naming `origin` (the trajectory file) when there
// is no source.
std::vector<uint32_t> assignSources(std::span<const PathSource> sources,
                                    std::span<const SpeedRange> agentRanges, uint64_t seed,
                                    std::string_view origin = "the trajectories");

// The speed weight w that makes the blended cycle move at `speed` (the clips' root speeds:
// anim::clipRootSpeed): slow speed → 0, fast speed → 1, clamped to [0, 1].
float speedWeight(float speed, float slowSpeed, float fastSpeed);

// Every agent's path, as cumulative sums so a waypoint costs O(1).
struct AgentPaths {
  std::vector<std::vector<glm::vec2>>
      cumulative;                     // per source: Σ_{k≤j} P_k, j = 0..n (entry 0 is 0)
  std::vector<uint32_t> source;       // per agent: index into cumulative
  std::vector<glm::vec2> start;       // per agent: world (x, z) at its first second
  std::vector<glm::vec2> rotation;    // per agent: (cos, sin) from the source's frame to world
  std::vector<float> maxSpeed;        // per agent: speed cap while catching up (m/s)
  std::vector<uint32_t> firstSecond;  // per agent: simulation second it appears at
  std::vector<uint32_t> lastSecond;   // per agent: second it leaves at (UINT32_MAX: never)
  // Per source: 1 when the path ends at its last waypoint instead of starting over (a walk to a
  // destination, such as the corridor's far end); empty: every path loops.
  std::vector<uint8_t> holdsEnd;

  size_t size() const { return source.size(); }
  bool active(size_t agent, uint32_t second) const {
    return second >= firstSecond[agent] && second < lastSecond[agent];
  }
  bool holds(uint32_t source) const { return source < holdsEnd.size() && holdsEnd[source] != 0; }
  // Where the agent is due at the end of its `j`-th second (j = 0: its start).
  glm::vec2 waypoint(size_t agent, uint32_t j) const;
};

// Storyboard agents: each starts where the crowd places it at second 0, follows source
// `source[i]` turned onto its heading (placement.w) and loops it forever.
AgentPaths followSources(const Crowd& crowd, std::span<const PathSource> sources,
                         std::span<const uint32_t> source, std::span<const float> maxSpeed);
// Replay of the data: agent i is source i at its own place and time, unturned, leaving when
// its vectors end. `origin` is subtracted from positions (data plane → world x, z).
AgentPaths replaySources(std::span<const PathSource> sources, glm::vec2 origin, float maxSpeed);

// goal[i] = (waypoint x, z, max speed, 1) for agents active during `second` (heading for
// waypoint(second − firstSecond + 1)), (0, 0, 0, 0) for the others.
void writeGoals(const AgentPaths& paths, uint32_t second, std::span<glm::vec4> goals);

}  // namespace throng::crowd
