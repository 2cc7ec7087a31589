#include "scene_storyboard.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "core/error.h"
#include "core/log.h"
#include "crowd/circle_paths.h"
#include "crowd/trajectories.h"
#include "storyboard/codec.h"
#include "storyboard/legend.h"
#include "storyboard/storyboard_placement.h"

namespace throng::tools {
namespace sb = throng::storyboard;

namespace {

sb::Storyboard readSceneStoryboard(const StoryboardSceneOptions& s) {
  const sb::Legend legend = s.legend.empty() ? sb::Legend{} : sb::loadLegend(s.legend);
  sb::Storyboard board = sb::readStoryboard(s.storyboard, legend, false);
  if (board.glyphs.empty()) fail(s.storyboard, ": no valid glyph, so no agent to animate");
  return board;
}

void requireFile(const std::string& path, const char* option) {
  if (!std::filesystem::is_regular_file(path)) fail(option, " ", path, ": no such file");
}

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

}  // namespace

crowd::SteerPolicy scenePolicy(const std::string& name) {
  if (name == "published" || name == "rule") return crowd::SteerPolicy::Rule;
  if (name == "anticipatory" || name == "ttc") return crowd::SteerPolicy::Ttc;
  if (name == "none") return crowd::SteerPolicy::None;
  fail("--policy '", name, "': expected anticipatory, published or none");
}

std::string_view policyName(crowd::SteerPolicy policy) {
  switch (policy) {
    case crowd::SteerPolicy::Rule:
      return "published";
    case crowd::SteerPolicy::Ttc:
      return "anticipatory";
    case crowd::SteerPolicy::None:
      break;
  }
  return "none";
}

void validateStoryboardScene(SceneOptions& o) {
  StoryboardSceneOptions& s = o.story;
  if (s.storyboard.empty() || s.trajectories.empty())
    fail("the storyboard scene needs --storyboard FILE.png and --trajectories FILE");
  if (!(s.cell > 0.0f) || !std::isfinite(s.cell)) fail("--cell: expected metres > 0, got ", s.cell);
  if (!(s.jitter >= 0.0f) || !std::isfinite(s.jitter))
    fail("--jitter: expected metres >= 0, got ", s.jitter);
  if (!(s.radius > 0.0f) || !std::isfinite(s.radius))
    fail("--radius: expected metres > 0, got ", s.radius);
  if (!(s.stepTime >= 0.0f)) fail("--step-time: expected seconds >= 0, got ", s.stepTime);
  scenePolicy(s.policy);
  if (o.speedPeriod != 0.0f)
    fail("--speed-period: storyboard agents take their speeds from their path vectors");
  requireFile(s.storyboard, "--storyboard");
  requireFile(s.trajectories, "--trajectories");
  if (!s.legend.empty()) requireFile(s.legend, "--legend");
  const sb::Storyboard board = readSceneStoryboard(s);  // a bad file fails before the GPU starts
  s.extent = 0.5f * float(std::max(board.width, board.height)) * s.cell;
}

scene::SceneSetup makeStoryboardSetup(const SceneOptions& o,
                                              const anim::ClipPair* userClips) {
  const StoryboardSceneOptions& s = o.story;
  const sb::Storyboard board = readSceneStoryboard(s);
  crowd::TrajectoryOptions trajectoryOptions;
  trajectoryOptions.secondsPerStep = s.stepTime;
  const crowd::Trajectories tracks = crowd::loadTrajectories(s.trajectories, trajectoryOptions);
  const std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(tracks);

  // One motion pair per action (walk, run, talk, jump), or the user's pair for all of them.
  std::vector<anim::ClipPair> clips;
  if (userClips)
    clips.push_back(*userClips);
  else
    clips = anim::defaultClipSets();
  std::vector<anim::MotionPair> motion;
  std::vector<sb::RootSpeeds> speeds;
  for (const anim::ClipPair& c : clips) {
    motion.push_back(anim::makeMotionPair(c.slow, c.fast));
    speeds.push_back(
        {crowd::clipRootSpeed(motion.back().slow), crowd::clipRootSpeed(motion.back().fast)});
  }
  sb::PlacementOptions placeOptions;
  placeOptions.cellSize = s.cell;
  placeOptions.jitter = s.jitter;
  placeOptions.seed = o.scenario.seed;
  if (userClips) {
    placeOptions.slowSpeed = speeds[0].slow;
    placeOptions.fastSpeed = speeds[0].fast;
  } else {
    placeOptions.actionSpeeds.emplace();
    std::copy_n(speeds.begin(), sb::kActionCount, placeOptions.actionSpeeds->begin());
  }
  const sb::Placement placed = sb::placeStoryboard(board, placeOptions);
  const size_t n = placed.crowd.size();

  const std::vector<uint32_t> assigned =
      crowd::assignSources(sources, placed.speedRange, o.scenario.seed, s.trajectories);
  scene::SceneSetup setup;
  setup.steering.emplace();
  crowd::AgentPaths& paths = setup.steering->paths;
  paths = crowd::followSources(placed.crowd, sources, assigned, std::vector<float>(n, 1.0f));
  std::vector<uint32_t> pairOf(n, 0);
  if (!userClips) pairOf = placed.crowd.clipSet;
  fitPathsToClips(paths, sources, assigned, pairOf, speeds);
  setup.crowd = placed.crowd;
  setup.tints = placed.tint;
  setup.labels = placed.tint;  // the storyboard's groups
  setup.groupFirst.push_back(0);
  for (size_t k = 0; k < motion.size(); ++k) {
    const uint32_t end = userClips ? uint32_t(n) : placed.setBegin[k + 1];
    if (end == setup.groupFirst.back()) continue;  // no agent does this action
    setup.pairs.push_back(std::move(motion[k]));
    setup.groupFirst.push_back(end);
  }
  setup.steering->avoidance.policy = scenePolicy(s.policy);
  setup.steering->avoidance.radius = s.radius;
  setup.steering->avoidance.seed = uint32_t(o.scenario.seed);
  logInfo(concat("storyboard ", s.storyboard, ": ", n, " agents (walk ", placed.setBegin[1],
                 ", run ", placed.setBegin[2] - placed.setBegin[1], ", talk ",
                 placed.setBegin[3] - placed.setBegin[2], ", jump ",
                 placed.setBegin[4] - placed.setBegin[3], "; ", board.invalid.size(),
                 " invalid glyphs skipped) following ", sources.size(), " tracked people of ",
                 s.trajectories, ", avoidance ", policyName(setup.steering->avoidance.policy)));
  return setup;
}

scene::SceneSetup makeCircleSetup(const SceneOptions& o, anim::MotionPair pair) {
  scene::SceneSetup setup;
  setup.crowd = makeSceneCrowd(o);
  setup.crowd.steering = anim::Steering::KeepHeading;  // the avoidance pass sets the heading
  setup.steering.emplace();
  setup.steering->paths = crowd::circlePaths(setup.crowd, crowd::clipRootSpeed(pair.slow),
                                             crowd::clipRootSpeed(pair.fast));
  const uint32_t n = uint32_t(setup.crowd.size());
  setup.tints.resize(n);
  std::iota(setup.tints.begin(), setup.tints.end(), 0u);  // a hue per runner
  setup.pairs.push_back(std::move(pair));
  setup.groupFirst = {0, n};
  setup.steering->avoidance.policy = scenePolicy(o.story.policy);
  setup.steering->avoidance.radius = o.story.radius;
  setup.steering->avoidance.seed = uint32_t(o.scenario.seed);
  return setup;
}

bool steersCircle(const SceneOptions& o) {
  // A speed schedule changes w behind the waypoints' back: such runs keep tangent steering.
  return o.scenario.name == "circle" && o.speedPeriod == 0.0f;
}

scene::SceneSetup makeSceneSetup(const SceneOptions& o, const anim::ClipPair& clips) {
  if (o.storyboard()) return makeStoryboardSetup(o, o.slowClip.empty() ? nullptr : &clips);
  if (steersCircle(o)) return makeCircleSetup(o, anim::makeMotionPair(clips.slow, clips.fast));
  scene::SceneSetup setup;
  setup.crowd = makeSceneCrowd(o);
  setup.pairs.push_back(anim::makeMotionPair(clips.slow, clips.fast));
  setup.groupFirst = {0, uint32_t(setup.crowd.size())};
  setup.speeds = sceneSpeedSchedule(o);
  return setup;
}

std::unique_ptr<scene::Scene> makeScene(const gpu::Context& context, const SceneOptions& o,
                                        const anim::ClipPair& clips) {
  return std::make_unique<scene::Scene>(context, makeSceneSetup(o, clips), sceneCacheOptions(o),
                                        sceneLodOptions(o, clips.slow.skeleton));
}

}  // namespace throng::tools
