#include "scene/example_scenes.h"

#include <cmath>

namespace throng::scene {

namespace {

GroupDescription group(uint32_t count, const char* clips, glm::vec2 centre, float speedMin,
                       float speedMax) {
  GroupDescription g;
  g.count = count;
  g.clips = clips;
  g.centre = centre;
  g.speedMin = speedMin;
  g.speedMax = speedMax;
  return g;
}

// A plaza of four groups, one per built-in clip set, each on its own patch of ground.
SceneFile plazaGroups() {
  SceneFile s;
  s.seed = 3;
  s.groups = {group(1500, "walk", {-45.0f, 0.0f}, 0.0f, 1.0f),
              group(800, "run", {45.0f, 0.0f}, 0.2f, 1.0f),
              group(300, "talk", {0.0f, -45.0f}, 0.0f, 1.0f),
              group(400, "hop", {0.0f, 45.0f}, 0.0f, 1.0f)};
  s.speedPeriod = 5.0f;
  s.cameraPreset = "wide";
  s.seconds = 6.0f;
  return s;
}

// The circle's runners on their lanes with avoidance, the camera orbiting once over 8 s.
SceneFile circleOrbit() {
  SceneFile s;
  s.behaviour = "circle";
  GroupDescription g;
  g.count = 1000;
  g.placement = "circle";
  s.groups = {g};
  s.policy = "anticipatory";
  s.cameraPreset = "top";
  constexpr int kKeys = 9;
  for (int k = 0; k < kKeys; ++k) {
    const float angle = 2.0f * 3.14159265f * float(k) / float(kKeys - 1);
    render::CameraKey key;
    key.seconds = float(k);
    key.eye = {70.0f * std::sin(angle), 45.0f, -70.0f * std::cos(angle)};
    key.target = {0.0f, 0.0f, 0.0f};
    key.fovYDegrees = 45.0f;
    s.cameraPath.push_back(key);
  }
  s.seconds = 8.0f;
  return s;
}

}  // namespace

std::vector<std::pair<std::string, SceneFile>> exampleScenes() {
  return {{"plaza_groups.json", plazaGroups()}, {"circle_orbit.json", circleOrbit()}};
}

}  // namespace throng::scene
