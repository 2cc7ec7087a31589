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
  s.groups = {
      group(1500, "walk", {-45.0f, 0.0f}, 0.0f, 1.0f), group(800, "run", {45.0f, 0.0f}, 0.2f, 1.0f),
      group(300, "talk", {0.0f, -45.0f}, 0.0f, 1.0f), group(400, "hop", {0.0f, 45.0f}, 0.0f, 1.0f)};
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

// The storyboard paper's subway corridor (about 500 people, 60 × 15 m), seen from inside; and
// ten times as long (about 5,000 people).
SceneFile corridor(float length, glm::vec3 eye, glm::vec3 target, float seconds) {
  SceneFile s;
  s.behaviour = "corridor";
  s.corridorLength = length;
  s.policy = "anticipatory";
  s.eye = eye;
  s.target = target;
  s.seconds = seconds;
  return s;
}

}  // namespace

std::vector<std::pair<std::string, SceneFile>> exampleScenes() {
  return {{"plaza_groups.json", plazaGroups()},
          {"circle_orbit.json", circleOrbit()},
          // From above one open end, looking down the corridor.
          {"corridor.json", corridor(60.0f, {-40.0f, 9.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 30.0f)},
          {"corridor_long.json",
           corridor(600.0f, {-330.0f, 40.0f, 0.0f}, {-150.0f, 0.0f, 0.0f}, 30.0f)}};
}

}  // namespace throng::scene
