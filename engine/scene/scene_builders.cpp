#include "scene/scene_builders.h"

#include <algorithm>
#include <numeric>

#include "anim/speed_buckets.h"
#include "core/error.h"
#include "core/log.h"
#include "crowd/avoidance_types.h"
#include "crowd/circle_paths.h"
#include "crowd/scenario.h"
#include "crowd/spatial_order.h"
#include "crowd/trajectories.h"
#include "storyboard/codec.h"
#include "storyboard/legend.h"
#include "storyboard/storyboard_placement.h"

namespace throng::scene {
namespace sb = throng::storyboard;

namespace {

// Path vectors scaled to the speeds the agent's clip pair can produce (root motion moves a
// character at least as fast as the slow clip): the agent keeps its source's path shape, turns
// and pauses aside. A pair that does not travel (talk) stands: its path is never active.
void fitPathsToClips(crowd::AgentPaths& paths, std::span<const crowd::PathSource> sources,
                     std::span<const uint32_t> assigned, std::span<const uint32_t> pairOf,
                     std::span<const sb::RootSpeeds> speeds) {
  for (size_t i = 0; i < paths.size(); ++i) {
    const sb::RootSpeeds r = speeds[pairOf[i]];
    if (!(r.fast > 0.0f)) {
      paths.lastSecond[i] = 0;
      paths.maxSpeed[i] = 0.0f;
      continue;
    }
    const float mean = sources[assigned[i]].meanSpeed();
    const float scale = mean > 0.05f ? std::clamp(mean, r.slow, r.fast) / mean : 1.0f;
    paths.rotation[i] *= scale;
    paths.maxSpeed[i] = 1.25f * r.fast;
  }
}

// One motion pair per action (walk, run, talk, jump), or the user's pair for all of them.
std::vector<anim::MotionPair> storyboardPairs(const StoryboardSceneDescription& d,
                                              std::vector<sb::RootSpeeds>& speeds) {
  std::vector<anim::ClipPair> clips;
  if (d.clips)
    clips.push_back(*d.clips);
  else
    clips = anim::defaultClipSets();
  std::vector<anim::MotionPair> motion;
  for (const anim::ClipPair& c : clips) {
    motion.push_back(anim::makeMotionPair(c.slow, c.fast));
    speeds.push_back(
        {anim::clipRootSpeed(motion.back().slow), anim::clipRootSpeed(motion.back().fast)});
  }
  return motion;
}

sb::Placement placeAgents(const StoryboardSceneDescription& d, const sb::Storyboard& board,
                          std::span<const sb::RootSpeeds> speeds) {
  sb::PlacementOptions options;
  options.cellSize = d.cell;
  options.jitter = d.jitter;
  options.seed = d.seed;
  if (d.clips) {
    options.slowSpeed = speeds[0].slow;
    options.fastSpeed = speeds[0].fast;
  } else {
    options.actionSpeeds.emplace();
    std::copy_n(speeds.begin(), sb::kActionCount, options.actionSpeeds->begin());
  }
  return sb::placeStoryboard(board, options);
}

}  // namespace

void numberInSpace(SceneSetup& setup) {
  if (setup.groupFirst.size() > 2)
    fail("numbering in space needs a scene of one group, this one has ",
         setup.groupFirst.size() - 1);
  const std::vector<uint32_t> order = crowd::spatialOrder(setup.crowd);
  setup.crowd = crowd::permuted(setup.crowd, order);
  setup.tints = crowd::permuted(setup.tints, order);
  setup.labels = crowd::permuted(setup.labels, order);
}

SceneSetup plainScene(crowd::Crowd crowd, anim::MotionPair pair,
                      const synth::SpeedSchedule& speeds) {
  SceneSetup setup;
  setup.groupFirst = {0, uint32_t(crowd.size())};
  setup.crowd = std::move(crowd);
  setup.pairs.push_back(std::move(pair));
  setup.speeds = speeds;
  return setup;
}

anim::ClipPair groupClips(const GroupDescription& group) {
  if (!group.slow.empty()) return anim::loadClipPair(group.slow, group.fast);
  if (group.clips == "walk") return anim::defaultWalkPair();
  if (group.clips == "talk") return anim::defaultTalkPair();
  if (group.clips == "hop") return anim::defaultJumpPair();
  if (group.clips == "run") return anim::defaultRunPair();
  fail("unknown built-in clip set '", group.clips, "': expected run, walk, talk or hop");
}

crowd::Crowd groupCrowd(const GroupDescription& group, uint64_t seed, size_t index,
                        float bucketWidth) {
  crowd::ScenarioOptions options;
  options.name = group.placement;
  options.characters = group.count;
  options.seed = seed + 7919u * index;  // each group its own draw
  options.density = group.density;
  options.minSpeedWeight = group.speedMin;
  options.maxSpeedWeight = group.speedMax;
  options.minScale = group.scaleMin;
  options.maxScale = group.scaleMax;
  crowd::Crowd crowd = crowd::makeScenario(options);
  for (glm::vec4& p : crowd.placement) {
    p.x += group.centre.x;
    p.z += group.centre.y;
  }
  if (bucketWidth > 0.0f) anim::quantizeSpeeds(crowd.motion, bucketWidth);
  return crowd;
}

SceneSetup groupsScene(std::span<const GroupDescription> groups, uint64_t seed, float bucketWidth,
                       const synth::SpeedSchedule& speeds) {
  if (groups.empty() || groups.size() > gpu_types::kMaxClipSets)
    fail("a scene has 1 to ", gpu_types::kMaxClipSets, " groups, got ", groups.size());
  SceneSetup setup;
  setup.groupFirst = {0};
  for (size_t k = 0; k < groups.size(); ++k) {
    const crowd::Crowd part = groupCrowd(groups[k], seed, k, bucketWidth);
    if (k == 0) setup.crowd.steering = part.steering;
    setup.crowd.placement.insert(setup.crowd.placement.end(), part.placement.begin(),
                                 part.placement.end());
    setup.crowd.motion.insert(setup.crowd.motion.end(), part.motion.begin(), part.motion.end());
    setup.crowd.clipSet.insert(setup.crowd.clipSet.end(), part.size(), uint32_t(k));
    const anim::ClipPair clips = groupClips(groups[k]);
    setup.pairs.push_back(anim::makeMotionPair(clips.slow, clips.fast));
    setup.groupFirst.push_back(uint32_t(setup.crowd.size()));
    setup.labels.insert(setup.labels.end(), part.size(), uint32_t(k));
  }
  if (groups.size() > 1) setup.tints = setup.labels;  // one colour per group
  setup.speeds = speeds;
  return setup;
}

SceneSetup circleScene(crowd::Crowd crowd, anim::MotionPair pair,
                       const crowd::AvoidanceParams& avoidance) {
  SceneSetup setup;
  setup.crowd = std::move(crowd);
  setup.crowd.steering = anim::Steering::KeepHeading;  // the avoidance pass sets the heading
  setup.steering.emplace();
  setup.steering->paths = crowd::circlePaths(setup.crowd, anim::clipRootSpeed(pair.slow),
                                             anim::clipRootSpeed(pair.fast));
  setup.steering->avoidance = avoidance;
  const uint32_t n = uint32_t(setup.crowd.size());
  setup.tints.resize(n);
  std::iota(setup.tints.begin(), setup.tints.end(), 0u);  // a hue per runner
  setup.pairs.push_back(std::move(pair));
  setup.groupFirst = {0, n};
  return setup;
}

sb::Storyboard readSceneStoryboard(const StoryboardSceneDescription& d) {
  const sb::Legend legend = d.legend.empty() ? sb::Legend{} : sb::loadLegend(d.legend);
  sb::Storyboard board = sb::readStoryboard(d.storyboard, legend, false);
  if (board.glyphs.empty()) fail(d.storyboard, ": no valid glyph, so no agent to animate");
  return board;
}

SceneSetup storyboardScene(const StoryboardSceneDescription& d) {
  const sb::Storyboard board = readSceneStoryboard(d);
  crowd::TrajectoryOptions trajectoryOptions;
  trajectoryOptions.secondsPerStep = d.stepTime;
  const crowd::Trajectories tracks = crowd::loadTrajectories(d.trajectories, trajectoryOptions);
  const std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(tracks);
  std::vector<sb::RootSpeeds> speeds;
  std::vector<anim::MotionPair> motion = storyboardPairs(d, speeds);
  const sb::Placement placed = placeAgents(d, board, speeds);
  const size_t n = placed.crowd.size();
  const std::vector<uint32_t> assigned =
      crowd::assignSources(sources, placed.speedRange, d.seed, d.trajectories);
  SceneSetup setup;
  setup.steering.emplace();
  crowd::AgentPaths& paths = setup.steering->paths;
  paths = crowd::followSources(placed.crowd, sources, assigned, std::vector<float>(n, 1.0f));
  std::vector<uint32_t> pairOf(n, 0);
  if (!d.clips) pairOf = placed.crowd.clipSet;
  fitPathsToClips(paths, sources, assigned, pairOf, speeds);
  setup.steering->avoidance = d.avoidance;
  setup.crowd = placed.crowd;
  setup.tints = placed.tint;
  setup.labels = placed.tint;  // the storyboard's groups
  setup.groupFirst.push_back(0);
  for (size_t k = 0; k < motion.size(); ++k) {
    const uint32_t end = d.clips ? uint32_t(n) : placed.setBegin[k + 1];
    if (end == setup.groupFirst.back()) continue;  // no agent does this action
    setup.pairs.push_back(std::move(motion[k]));
    setup.groupFirst.push_back(end);
  }
  logInfo(concat("storyboard ", d.storyboard, ": ", n, " agents (walk ", placed.setBegin[1],
                 ", run ", placed.setBegin[2] - placed.setBegin[1], ", talk ",
                 placed.setBegin[3] - placed.setBegin[2], ", jump ",
                 placed.setBegin[4] - placed.setBegin[3], "; ", board.invalid.size(),
                 " invalid glyphs skipped) following ", sources.size(), " tracked people of ",
                 d.trajectories, ", avoidance ", crowd::steerPolicyName(d.avoidance.policy)));
  return setup;
}

}  // namespace throng::scene
