#include "scene_storyboard.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/log.h"
#include "crowd/walls_file.h"
#include "scene/corridor_scene.h"
#include "scene/menge_scene.h"

namespace throng::tools {

namespace {
void requireFile(const std::string& path, const char* option) {
  if (!std::filesystem::is_regular_file(path)) fail(option, " ", path, ": no such file");
}

crowd::AvoidanceParams sceneAvoidance(const SceneOptions& o) {
  crowd::AvoidanceParams avoidance;
  avoidance.policy = scenePolicy(o.story.policy);
  avoidance.radius = o.story.radius;
  avoidance.seed = uint32_t(o.scenario.seed);
  return avoidance;
}
}  // namespace

crowd::SteerPolicy scenePolicy(const std::string& name) {
  if (const std::optional<crowd::SteerPolicy> policy = crowd::parseSteerPolicy(name))
    return *policy;
  fail("--policy '", name, "': expected anticipatory, published or none");
}

std::string_view policyName(crowd::SteerPolicy policy) {
  return crowd::steerPolicyName(policy);
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
  // A bad file fails before the GPU starts.
  const storyboard::Storyboard board =
      scene::readSceneStoryboard(storyboardDescription(o, nullptr));
  s.extent = 0.5f * float(std::max(board.width, board.height)) * s.cell;
}

scene::StoryboardSceneDescription storyboardDescription(const SceneOptions& o,
                                                        const anim::ClipPair* userClips) {
  scene::StoryboardSceneDescription d;
  d.storyboard = o.story.storyboard;
  d.trajectories = o.story.trajectories;
  d.legend = o.story.legend;
  d.cell = o.story.cell;
  d.jitter = o.story.jitter;
  d.stepTime = o.story.stepTime;
  d.seed = o.scenario.seed;
  d.avoidance = sceneAvoidance(o);
  if (userClips) d.clips = *userClips;
  return d;
}

namespace {
scene::MengeSceneResult readMenge(const SceneOptions& o, const anim::ClipPair& clips) {
  const menge::MengeScenario scenario = menge::readMengeProject(o.menge);
  scene::MengeSceneResult r =
      scene::mengeScene(scenario, clips, o.scenario.seed, o.cache ? o.bucketWidth : 0.0f);
  r.setup.steering->avoidance.policy = scenePolicy(o.story.policy);
  return r;
}
}  // namespace

void validateMengeScene(SceneOptions& o) {
  if (!std::filesystem::is_regular_file(o.menge)) fail("--menge ", o.menge, ": no such file");
  const scene::MengeSceneResult r = readMenge(o, loadSceneClips(o));
  for (const std::string& warning : r.warnings) logWarning(warning);
  o.mengeCentre = 0.5f * (r.boundsMin + r.boundsMax);
  o.mengeExtent = std::max(1.0f, 0.5f * glm::length(r.boundsMax - r.boundsMin));
  logInfo(concat("menge ", o.menge, ": ", r.setup.crowd.size(), " agents, ",
                 r.setup.walls.segments.size(), " wall segments, ",
                 r.setup.steering->goals->goalSets.size(), " goal sets"));
}

bool steersCircle(const SceneOptions& o) {
  // A speed schedule changes w behind the waypoints' back: such runs keep tangent steering.
  return o.scenario.name == "circle" && o.speedPeriod == 0.0f;
}

namespace {
scene::SceneSetup makeSetupWithoutWalls(const SceneOptions& o, const anim::ClipPair& clips);
}

scene::SceneSetup makeSceneSetup(const SceneOptions& o, const anim::ClipPair& clips) {
  scene::SceneSetup setup = makeSetupWithoutWalls(o, clips);
  if (o.lodUpdateLag > 0.0f) scene::numberInSpace(setup);  // chunks as patches of ground
  if (!o.walls.empty()) {
    const crowd::Obstacles more = crowd::loadWalls(o.walls);
    setup.walls.segments.insert(setup.walls.segments.end(), more.segments.begin(),
                                more.segments.end());
  }
  return setup;
}

namespace {
scene::SceneSetup makeSetupWithoutWalls(const SceneOptions& o, const anim::ClipPair& clips) {
  if (o.mengeScene()) return readMenge(o, clips).setup;
  if (o.corridor()) {
    scene::CorridorDescription d;
    d.length = o.corridorLength;
    d.seed = o.scenario.seed;
    d.avoidance = sceneAvoidance(o);
    if (!o.story.trajectories.empty()) d.trajectories = o.story.trajectories;
    return scene::corridorScene(d);
  }
  if (o.storyboard())
    return scene::storyboardScene(storyboardDescription(o, o.slowClip.empty() ? nullptr : &clips));
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  const float bucketWidth = o.cache ? o.bucketWidth : 0.0f;
  // A scene file's groups (the circle: its one group on the lanes).
  if (!o.groups.empty() && steersCircle(o))
    return scene::circleScene(scene::groupCrowd(o.groups.front(), o.scenario.seed, 0, bucketWidth),
                              std::move(pair), sceneAvoidance(o));
  if (!o.groups.empty())
    return scene::groupsScene(o.groups, o.scenario.seed, bucketWidth, sceneSpeedSchedule(o));
  if (steersCircle(o))
    return scene::circleScene(makeSceneCrowd(o), std::move(pair), sceneAvoidance(o));
  return scene::plainScene(makeSceneCrowd(o), std::move(pair), sceneSpeedSchedule(o));
}

}  // namespace

std::unique_ptr<scene::Scene> makeScene(const gpu::Context& context, const SceneOptions& o,
                                        const anim::ClipPair& clips) {
  return std::make_unique<scene::Scene>(context, makeSceneSetup(o, clips), sceneCacheOptions(o),
                                        sceneLodOptions(o, clips.slow.skeleton));
}

}  // namespace throng::tools
