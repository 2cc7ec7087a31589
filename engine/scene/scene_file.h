#pragma once
// The scene file (docs/formats.md, "Scene files"): one JSON document that describes a whole
// scene — its groups of characters (count, placement, clip set, speeds, sizes), the behaviour
// (plain, circle lanes or a storyboard on tracked trajectories), avoidance, speed changes, the
// motion LOD and cache, capes, the camera (a preset, a fixed view or a keyframed path) and the
// output (size, frame rate, seconds). `throng render SCENE.json` and `throng view SCENE.json`
// take it; `throng render … --save-scene FILE` writes the file of a scene given by flags.
// Errors name the file, the line and the key path: `scene.json:7: groups[1].count: …`.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "render/camera_path.h"
#include "scene/scene_builders.h"

namespace throng::scene {

struct SceneFile {
  uint64_t seed = 1;
  std::string behaviour = "plain";   // plain, circle, storyboard, menge or corridor
  std::string menge;                 // the menge behaviour's project file (XML)
  float corridorLength = 60.0f;      // the corridor behaviour's length (metres)
  std::string corridorTrajectories;  // its walkers' tracked set; empty: the built-in default
  std::string walls;                 // a walls file (docs/formats.md "Walls"; steered scenes)
  std::vector<GroupDescription> groups;
  StoryboardSceneDescription storyboard;  // the storyboard behaviour's files and options
  std::string policy = "anticipatory";    // avoidance (circle and storyboard)
  float radius = 0.3f;                    // safe radius (m)
  float speedPeriod = 0.0f;               // plain: seconds between speed changes (0: never)
  bool lod = true, cache = true;
  float cacheBudgetMb = 20.0f, bucketWidth = 0.05f;
  std::string capes;  // a .tsc cloth database every character wears (empty: none)
  std::string cameraPreset = "wide";
  std::optional<glm::vec3> eye, target;
  std::optional<float> fovYDegrees;
  std::vector<render::CameraKey> cameraPath;  // in time order; empty: a fixed camera
  std::string size = "1280x720";
  float fps = 30.0f;
  float seconds = 3.0f;
};

// Throws Error `FILE:LINE: key: what was expected` for anything not valid (unknown keys too).
SceneFile readSceneFile(const std::filesystem::path& path);
// The same from text; relative file names are resolved against `baseDir`.
SceneFile parseSceneFile(std::string_view text, const std::string& source,
                         const std::filesystem::path& baseDir);
// The file's JSON text (schema throng.scene, version 1); parseSceneFile reads it back.
std::string writeSceneFile(const SceneFile& scene);

}  // namespace throng::scene
