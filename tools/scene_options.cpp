#include "scene_options.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli_errors.h"
#include "core/error.h"
#include "crowd/trajectory_writer.h"
#include "limit_option.h"
#include "render/offscreen_target.h"
#include "scene_file_options.h"
#include "scene_storyboard.h"

namespace throng::tools {

namespace {
void addStoryboardSceneOptions(CLI::App& command, StoryboardSceneOptions& o) {
  command.add_option("--storyboard", o.storyboard,
                     "Storyboard PNG: its agents make the crowd (the storyboard scene)");
  command.add_option("--trajectories", o.trajectories,
                     "Tracked people ('frame ped x y' text or ETH obsmat.txt) whose path vectors "
                     "the agents follow (storyboard and corridor scenes)");
  command.add_option(
      "--legend", o.legend,
      "Storyboard colour legend JSON (default: the default colours of docs/formats.md)");
  command.add_option("--cell", o.cell, "Storyboard: metres per storyboard pixel")
      ->capture_default_str();
  command.add_option("--jitter", o.jitter, "Storyboard: random offset of each agent, +- metres")
      ->capture_default_str();
  command
      .add_option("--policy", o.policy,
                  "Avoidance of the storyboard and circle scenes: anticipatory (time to "
                  "collision), published (the rule) or none; ttc and rule are accepted as "
                  "aliases")
      ->capture_default_str()
      ->check(oneOf("policy", {"anticipatory", "published", "none", "ttc", "rule"}));
  command
      .add_option("--radius", o.radius,
                  "Storyboard and circle scenes: safe radius of each agent in metres")
      ->capture_default_str()
      ->check(inRange(0.01, 10, "metres"));
  command.add_option(
      "--step-time", o.stepTime,
      "Storyboard: seconds per annotation step of the trajectories (default: by dataset)");
}

// An option that changes nothing in the chosen scene is an error, not silently ignored.
void checkUsedOptions(const SceneOptions& o) {
  const std::string& scene = o.scenario.name;
  const bool steered = o.storyboard() || steersCircle(o) || o.mengeScene() || o.corridor();
  for (const char* name : {"--policy", "--radius"})
    if (o.given(name) && !steered)
      fail(name, ": steers the storyboard and circle scenes (without --speed-period), not '", scene,
           "'");
  if (o.storyboard() && o.given("--characters"))
    fail("-n/--characters: the storyboard's glyphs make the crowd; drop -n with --storyboard");
  if (o.mengeScene() && o.given("--characters"))
    fail("-n/--characters: the Menge scenario's generators make the crowd; drop -n with --menge");
  if (o.mengeScene() && o.given("--radius"))
    fail("--radius: a Menge scenario gives each agent profile its radius");
  if (!o.mengeScene() && !o.menge.empty()) fail("--menge makes the menge scene, not '", scene, "'");
  if (o.mengeScene() && o.menge.empty()) fail("--scene menge needs --menge PROJECT.xml");
  if (o.corridor() && o.given("--characters"))
    fail("-n/--characters: the corridor's storyboard makes the crowd; use --corridor-length");
  if (!o.corridor() && o.given("--corridor-length"))
    fail("--corridor-length: belongs to the corridor scene, not '", scene, "'");
  if (!o.walls.empty() && !steered)
    fail("--walls: walls need a steered scene (circle, storyboard, menge or corridor), not '",
         scene, "'");
  if (o.corridor() && o.speedPeriod != 0.0f)
    fail("--speed-period: corridor walkers take their speeds from the storyboard");
  if (o.mengeScene() && o.speedPeriod != 0.0f)
    fail("--speed-period: Menge agents walk at their profiles' preferred speeds");
  for (const char* name : {"--cell", "--jitter", "--step-time", "--legend"})
    if (o.given(name) && !o.storyboard())
      fail(name, ": belongs to the storyboard scene (--storyboard FILE), not '", scene, "'");
  if (o.given("--density") && scene != "random")
    fail("--density: spaces the random scene, not '", scene, "'");
  for (const char* name : {"--cache-budget", "--bucket-width"})
    if (o.given(name) && !o.cache) fail(name, ": needs the motion cache (drop --no-cache)");
  for (const char* name : {"--lod-mid-pixels", "--lod-near-pixels", "--lod-update-lag"})
    if (o.given(name) && !o.lod) fail(name, ": needs the coverage LOD (drop --no-lod)");
}
}  // namespace

void addSceneOptions(CLI::App& command, SceneOptions& o) {
  o.command = &command;
  command.add_option("scene", o.sceneFile,
                     "Scene file (JSON, docs/formats.md): the whole scene in one file, instead of "
                     "the scene flags");
  command
      .add_option(
          "--scene", o.scenario.name,
          "Scenario: random, circle, storyboard (with --storyboard), menge (with --menge) or "
          "corridor")
      ->capture_default_str()
      ->check(oneOf("scene", {"random", "circle", "storyboard", "menge", "corridor"}));
  command.add_option("--walls", o.walls,
                     "Walls file (docs/formats.md): static walls every steered scene (circle, "
                     "storyboard, menge, corridor) avoids and never crosses");
  command
      .add_option("--corridor-length", o.corridorLength,
                  "The corridor scene: its length in metres (15 m wide; about 8 people per metre)")
      ->capture_default_str()
      ->check(inRange(10, 2000, "metres"));
  command.add_option("--menge", o.menge,
                     "A Menge scenario's project file (XML): its agents, obstacles, goals and "
                     "behaviour (the menge scene)");
  command.add_option("--characters,-n", o.characters, "Number of characters")
      ->capture_default_str()
      ->check(inRange(1, 4000000));
  command.add_option("--seed", o.scenario.seed, "Random seed of the scenario")
      ->capture_default_str();
  command.add_option("--speed-min", o.scenario.minSpeedWeight, "Lowest speed weight w in [0,1]")
      ->capture_default_str()
      ->check(inRange(0, 1));
  command.add_option("--speed-max", o.scenario.maxSpeedWeight, "Highest speed weight w in [0,1]")
      ->capture_default_str()
      ->check(inRange(0, 1));
  command.add_option("--density", o.scenario.density, "Characters per square metre (random scene)")
      ->capture_default_str();
  command.add_option("--slow", o.slowClip, "Slow cycle BVH (default: built-in run)");
  command.add_option("--fast", o.fastClip, "Fast cycle BVH (default: built-in run)");
  command.add_option("--camera", o.cameraPreset, "Camera preset: wide, top, street, closeup")
      ->capture_default_str()
      ->check(oneOf("camera preset", {"wide", "top", "street", "closeup"}));
  command.add_option("--eye", o.eye, "Camera position x,y,z (overrides the preset)");
  command.add_option("--target", o.target, "Camera target x,y,z (overrides the preset)");
  command
      .add_option("--fov", o.fovY,
                  "Vertical field of view in degrees, 1..170 (default: the preset's)")
      ->check(inRange(1, 170, "degrees"));
  command.add_option("--size", o.size, "Image size WxH")->capture_default_str();
  command.add_option("--device", o.device, "Vulkan device by index or name (also $THRONG_DEVICE)");
  command.add_option("--dt", o.dt, "Simulated seconds per frame")
      ->capture_default_str()
      ->check(inInterval(End::kOpen, 0, 1, End::kClosed, "seconds"));
  command
      .add_flag("--cache,!--no-cache", o.cache,
                "Motion cache: characters share synthesized clips per speed bucket")
      ->capture_default_str();
  command.add_option("--cache-budget", o.cacheBudgetMb, "Motion cache budget in MB per clip set")
      ->capture_default_str()
      ->check(inRange(0, 65536, "MB"));
  command
      .add_option("--bucket-width", o.bucketWidth,
                  "Motion cache speed-weight bucket width, 1/4095..1 (at most 4096 buckets)")
      ->capture_default_str()
      ->check(inInterval(End::kOpen, 0, 1, End::kClosed));
  command
      .add_option("--speed-period", o.speedPeriod,
                  "Seconds between speed changes (0: never; paper: 5)")
      ->capture_default_str()
      ->check(inRange(0, 1e9, "seconds"));
  command
      .add_flag("--lod,!--no-lod", o.lod,
                "Coverage LOD: characters small on screen synthesize and draw fewer joints")
      ->capture_default_str();
  command.add_flag("--lod-tint", o.lodTint,
                   "With --lod, colour characters by level (green near, yellow mid, red far)");
  command
      .add_option("--lod-mid-pixels", o.lodMidPixels,
                  "Coverage LOD: projected standing height in pixels from which a character "
                  "gets the mid level (torso, head, upper limbs)")
      ->capture_default_str()
      ->check(inRange(0, 1e9, "pixels"));
  command
      .add_option("--lod-near-pixels", o.lodNearPixels,
                  "Coverage LOD: projected standing height in pixels from which a character "
                  "gets every joint")
      ->capture_default_str()
      ->check(inRange(0, 1e9, "pixels"));
  command
      .add_option("--lod-update-lag", o.lodUpdateLag,
                  "Update-rate LOD (the random crowd): characters far from the "
                  "camera move every 2 to 8 frames, no joint drawn more than this many pixels "
                  "from where moving every frame would draw it (0: every frame)")
      ->capture_default_str()
      ->check(inRange(0, 1e9, "pixels"));
  addStoryboardSceneOptions(command, o.story);
  command.add_option("--trajectories-out", o.trajectoriesOut,
                     "Every agent's position per frame: FILE.txt in PedPy's 'id frame x y z' "
                     "(metres, x y = engine x z) or FILE.csv with time, heading, speed, group "
                     "and state");
  command.add_option(
      "--cloth", o.cloth,
      "Compressed cloth database (.tsc from `throng cloth compress`): capes on every character");
  command.add_flag(
      "--cloth-tint", o.clothTint,
      "With --cloth, colour capes by garment level (green full, yellow mid, red coarse)");
  command.add_flag("--cloth-full", o.clothFull,
                   "With --cloth, draw every visible cape at full detail (no garment LOD)");
}

Size parseSize(const std::string& text) {
  unsigned w = 0, h = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%ux%u%c", &w, &h, &tail) != 2 || w == 0 || h == 0 || w > 16384 ||
      h > 16384)
    fail("--size: expected WxH with 1..16384 pixels per side, got '", text, "'");
  return {w, h};
}

void validateSceneOptions(SceneOptions& o) {
  applySceneFile(o);
  if (o.characters < 1 || o.characters > 4000000)
    fail("--characters: expected 1..4000000, got ", o.characters);
  o.scenario.characters = static_cast<uint32_t>(o.characters);
  if (o.slowClip.empty() != o.fastClip.empty()) fail("--slow and --fast must be given together");
  if (!(o.dt > 0.0f && o.dt <= 1.0f)) fail("--dt: expected seconds in (0, 1], got ", o.dt);
  if (o.fovY && !(*o.fovY >= 1.0f && *o.fovY <= 170.0f))
    fail("--fov: expected 1..170 degrees, got ", *o.fovY);
  parseSize(o.size);
  if (!(o.lodMidPixels >= 0.0f && o.lodNearPixels >= 0.0f))
    fail("--lod-mid-pixels and --lod-near-pixels must be >= 0 pixels");
  if (o.lodTint && !o.lod) fail("--lod-tint: needs the coverage LOD (drop --no-lod)");
  if (!(o.speedPeriod >= 0.0f)) fail("--speed-period: expected seconds >= 0, got ", o.speedPeriod);
  if ((o.clothTint || o.clothFull) && o.cloth.empty())
    fail("--cloth-tint and --cloth-full need --cloth");
  validateSceneCacheOptions(o);
  if (!o.trajectoriesOut.empty()) crowd::checkTrajectoryOutput(o.trajectoriesOut, 0, 0);
  // --storyboard alone picks the storyboard scene, --menge the menge scene (--scene defaults to
  // random).
  if (!o.story.storyboard.empty() && o.scenario.name == "random") o.scenario.name = "storyboard";
  if (!o.menge.empty() && o.scenario.name == "random") o.scenario.name = "menge";
  // Steered scenes steer every character from every other's place, trajectories record every
  // frame's places: both need every character moved every frame.
  if (o.lodUpdateLag > 0.0f &&
      (o.scenario.name != "random" || o.groups.size() > 1 || !o.trajectoriesOut.empty()))
    fail(
        "--lod-update-lag: only for the random crowd of one clip set without "
        "--trajectories-out (steered scenes and trajectories need every character every frame)");
  checkUsedOptions(o);
  if (o.mengeScene()) {
    validateMengeScene(o);
  } else if (o.storyboard()) {
    validateStoryboardScene(o);
  } else if (o.corridor()) {
    scenePolicy(o.story.policy);
    if (!o.story.storyboard.empty()) fail("--storyboard: the corridor quilts its own storyboard");
    if (!o.story.trajectories.empty() && !std::filesystem::exists(o.story.trajectories))
      fail("--trajectories: no such file: ", o.story.trajectories);
  } else {
    if (!o.story.storyboard.empty() || !o.story.trajectories.empty())
      fail("--storyboard and --trajectories make the storyboard scene, not '", o.scenario.name,
           "'");
    crowd::makeScenario([&] {  // validates the scenario options on a one-character crowd
      crowd::ScenarioOptions probe = o.scenario;
      probe.characters = 1;
      return probe;
    }());
  }
  sceneCamera(o);
}

void validateSceneCacheOptions(const SceneOptions& o) {
  if (!(o.cacheBudgetMb >= 0.0f && o.cacheBudgetMb <= 65536.0f))
    fail("--cache-budget: expected 0..65536 MB, got ", o.cacheBudgetMb);
  // 1/w rounds to the last bucket's index: at most kMaxSpeedBuckets - 1 (checked before the
  // division can overflow).
  const double lastBucket = o.bucketWidth > 0.0f ? 1.0 / double(o.bucketWidth) : 0.0;
  if (!(o.bucketWidth > 0.0f && o.bucketWidth <= 1.0f) || lastBucket >= kMaxSpeedBuckets - 0.5)
    fail("--bucket-width: expected a speed-weight width in 1/", kMaxSpeedBuckets - 1,
         "..1 (at most ", kMaxSpeedBuckets, " speed buckets), got ", o.bucketWidth);
  synth::validateCacheOptions(sceneCacheOptions(o));
}

void checkSceneForDevice(const SceneOptions& o, const gpu::Context& context) {
  const Size size = parseSize(o.size);
  namingOption(concat("--size ", o.size), [&] {
    render::checkTargetSize(context, size.width, size.height, concat("a ", o.size, " image"));
  });
  if (!o.cache) return;
  const synth::MotionCacheOptions cache = sceneCacheOptions(o);
  namingOption(concat("--cache-budget ", o.cacheBudgetMb), [&] {
    gpu::checkLimit(context, "the motion cache's data (one storage binding)",
                    "maxStorageBufferRange", cache.budgetBytes,
                    context.info().maxStorageBufferRange);
  });
}

std::string charactersOption(const SceneOptions& o) {
  if (o.storyboard()) return concat("--storyboard ", o.story.storyboard);
  return concat("-n ", o.scenario.characters);
}

anim::ClipPair loadSceneClips(const SceneOptions& o) {
  if (!o.groups.empty()) return scene::groupClips(o.groups.front());
  // Menge's pedestrians walk (1.34 m/s by default): the walk pair unless --slow/--fast.
  if (o.mengeScene() && o.slowClip.empty()) return anim::defaultWalkPair();
  if (o.slowClip.empty()) return anim::defaultRunPair();
  return anim::loadClipPair(o.slowClip, o.fastClip);
}

synth::MotionCacheOptions sceneCacheOptions(const SceneOptions& o) {
  return {o.cache, o.bucketWidth, static_cast<uint64_t>(double(o.cacheBudgetMb) * 1024.0 * 1024.0)};
}

crowd::Crowd makeSceneCrowd(const SceneOptions& o) {
  crowd::Crowd crowd = crowd::makeScenario(o.scenario);
  if (o.cache) {
    anim::quantizeSpeeds(crowd.motion, o.bucketWidth);
  }
  return crowd;
}

synth::SpeedSchedule sceneSpeedSchedule(const SceneOptions& o) {
  synth::SpeedSchedule schedule;
  schedule.period = o.speedPeriod;
  schedule.seed = static_cast<uint32_t>(o.scenario.seed);
  schedule.lo = o.scenario.minSpeedWeight;
  schedule.hi = o.scenario.maxSpeedWeight;
  schedule.bucketWidth = o.cache ? o.bucketWidth : 0.0f;
  return schedule;
}

synth::LodOptions sceneLodOptions(const SceneOptions& o, const anim::Skeleton& skeleton) {
  // The viewer can switch the coverage LOD off; the update-rate LOD, which needs it, goes with it.
  return {o.lod, synth::CoverageThresholds::levels(o.lodMidPixels, o.lodNearPixels), &skeleton,
          o.lod ? o.lodUpdateLag : 0.0f};
}

float sceneExtent(const SceneOptions& o) {
  if (o.storyboard()) return o.story.extent;
  if (o.mengeScene()) return o.mengeExtent;
  if (o.corridor()) return 0.5f * o.corridorLength;
  float extent = crowd::scenarioExtent(o.scenario);
  for (const scene::GroupDescription& g : o.groups) {
    crowd::ScenarioOptions s = o.scenario;
    s.name = g.placement;
    s.characters = g.count;
    s.density = g.density;
    extent = std::max(extent, glm::length(g.centre) + crowd::scenarioExtent(s));
  }
  return extent;
}

float sceneGroundExtent(const SceneOptions& o) {
  return 1.6f * sceneExtent(o) + 40.0f;
}

render::Camera scenePreset(const SceneOptions& o, const std::string& preset) {
  render::Camera camera = render::cameraPreset(preset, sceneExtent(o));
  // Presets look at the origin; a Menge scene lies wherever its file puts it.
  const glm::vec3 centre(o.mengeCentre.x, 0.0f, o.mengeCentre.y);
  camera.eye += centre;
  camera.target += centre;
  return camera;
}

render::Camera sceneCamera(const SceneOptions& o) {
  render::Camera camera = scenePreset(o, o.cameraPreset);
  if (!o.eye.empty()) camera.eye = render::parseVec3(o.eye, "--eye");
  if (!o.target.empty()) camera.target = render::parseVec3(o.target, "--target");
  if (o.fovY) camera.fovYDegrees = *o.fovY;
  if (glm::length(camera.eye - camera.target) < 1e-3f) fail("--eye and --target must differ");
  return camera;
}

secondary::ClothLayerOptions sceneClothOptions(const SceneOptions& o) {
  secondary::ClothLayerOptions options;
  options.lod.enabled = !o.clothFull;
  options.tintLevels = o.clothTint;
  return options;
}

bool SceneOptions::given(const char* flag) const {
  return command && command->count(flag) > 0;
}

}  // namespace throng::tools
