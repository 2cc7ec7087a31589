#include "scene_file_options.h"

#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "scene_storyboard.h"

namespace throng::tools {

namespace {

// The flags a scene file replaces: giving one with a file is an error, not a silent override.
constexpr const char* kSceneFlags[] = {
    "--scene",        "--characters",   "--seed",   "--speed-min",       "--speed-max",
    "--density",      "--slow",         "--fast",   "--camera",          "--eye",
    "--target",       "--fov",          "--dt",     "--cache",           "--cache-budget",
    "--bucket-width", "--speed-period", "--lod",    "--storyboard",      "--trajectories",
    "--legend",       "--cell",         "--jitter", "--policy",          "--radius",
    "--step-time",    "--cloth",        "--menge",  "--corridor-length", "--walls"};

std::string vec3Text(const glm::vec3& v) {
  char text[96];
  std::snprintf(text, sizeof(text), "%.9g,%.9g,%.9g", v.x, v.y, v.z);
  return text;
}

void applyGroups(SceneOptions& o, const scene::SceneFile& f) {
  // The first group also sets the scenario: the camera presets and the ground follow its extent.
  const scene::GroupDescription& g = f.groups.front();
  o.scenario.name = g.placement;
  o.characters = 0;
  for (const scene::GroupDescription& group : f.groups) o.characters += group.count;
  o.scenario.density = g.density;
  o.scenario.minSpeedWeight = g.speedMin;
  o.scenario.maxSpeedWeight = g.speedMax;
  o.scenario.minScale = g.scaleMin;
  o.scenario.maxScale = g.scaleMax;
  o.groups = f.groups;
}

}  // namespace

void applySceneFile(SceneOptions& o) {
  if (o.sceneFile.empty()) return;
  for (const char* flag : kSceneFlags)
    if (o.given(flag))
      fail(flag, ": the scene file ", o.sceneFile, " describes the scene; drop ", flag,
           " or edit the file");
  const scene::SceneFile f = scene::readSceneFile(o.sceneFile);
  o.scenario.seed = f.seed;
  if (f.behaviour == "corridor") {
    o.scenario.name = "corridor";
    o.corridorLength = f.corridorLength;
    o.story.trajectories = f.corridorTrajectories;
  } else if (f.behaviour == "menge") {
    o.scenario.name = "menge";
    o.menge = f.menge;
  } else if (f.behaviour == "storyboard") {
    o.scenario.name = "storyboard";
    o.story.storyboard = f.storyboard.storyboard;
    o.story.trajectories = f.storyboard.trajectories;
    o.story.legend = f.storyboard.legend;
    o.story.cell = f.storyboard.cell;
    o.story.jitter = f.storyboard.jitter;
    o.story.stepTime = f.storyboard.stepTime;
  } else {
    applyGroups(o, f);
  }
  o.story.policy = f.policy;
  o.story.radius = f.radius;
  o.speedPeriod = f.speedPeriod;
  o.lod = f.lod;
  o.cache = f.cache;
  o.cacheBudgetMb = f.cacheBudgetMb;
  o.bucketWidth = f.bucketWidth;
  o.cloth = f.capes;
  o.walls = f.walls;
  o.cameraPreset = f.cameraPreset;
  o.eye = f.eye ? vec3Text(*f.eye) : "";
  o.target = f.target ? vec3Text(*f.target) : "";
  o.fovY = f.fovYDegrees;
  o.cameraPath = f.cameraPath;
  if (!o.given("--size")) o.size = f.size;  // an output option
  o.dt = 1.0f / f.fps;
  o.sceneSeconds = f.seconds;
}

scene::SceneFile sceneFileOf(const SceneOptions& o, float seconds) {
  scene::SceneFile f;
  f.seed = o.scenario.seed;
  if (o.corridor()) {
    f.behaviour = "corridor";
    f.corridorLength = o.corridorLength;
    f.corridorTrajectories = o.story.trajectories;
  } else if (o.mengeScene()) {
    f.behaviour = "menge";
    f.menge = o.menge;
  } else if (o.storyboard()) {
    f.behaviour = "storyboard";
    f.storyboard = storyboardDescription(o, nullptr);
  } else {
    f.behaviour = steersCircle(o) ? "circle" : "plain";
    if (!o.groups.empty()) {
      f.groups = o.groups;
    } else {
      scene::GroupDescription g;
      g.count = o.scenario.characters;
      g.slow = o.slowClip;
      g.fast = o.fastClip;
      g.placement = o.scenario.name;
      g.density = o.scenario.density;
      g.speedMin = o.scenario.minSpeedWeight;
      g.speedMax = o.scenario.maxSpeedWeight;
      g.scaleMin = o.scenario.minScale;
      g.scaleMax = o.scenario.maxScale;
      f.groups.push_back(g);
    }
  }
  f.policy = o.story.policy;
  f.radius = o.story.radius;
  f.speedPeriod = o.speedPeriod;
  f.lod = o.lod;
  f.cache = o.cache;
  f.cacheBudgetMb = o.cacheBudgetMb;
  f.bucketWidth = o.bucketWidth;
  f.capes = o.cloth;
  f.walls = o.walls;
  f.cameraPreset = o.cameraPreset;
  if (!o.eye.empty()) f.eye = render::parseVec3(o.eye, "--eye");
  if (!o.target.empty()) f.target = render::parseVec3(o.target, "--target");
  f.fovYDegrees = o.fovY;
  f.cameraPath = o.cameraPath;
  f.size = o.size;
  f.fps = std::round(1000.0f / o.dt) / 1000.0f;  // 1 / (1 / 30) is 29.999998 in floats
  f.seconds = seconds;
  return f;
}

}  // namespace throng::tools
