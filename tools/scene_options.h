#pragma once
// Options shared by `throng render`, `throng view` and `throng bench`: the scene, the clips and
// the camera. Everything is validated before any output is written.
#include <optional>
#include <string>
#include <vector>

#include "anim/default_clips.h"
#include "crowd/scenario.h"
#include "gpu/context.h"
#include "render/camera.h"
#include "render/camera_path.h"
#include "scene/scene_builders.h"
#include "secondary/cloth_gpu_layer.h"
#include "synth/crowd_synth.h"

// CLI11 takes seconds to parse: the files that only pass a command along see its name.
namespace CLI {
class App;
}

namespace throng::tools {

// The "storyboard" scene: a storyboard's agents follow path vectors of tracked people, with
// collision avoidance, one clip pair per clip set (scene_storyboard.h).
struct StoryboardSceneOptions {
  std::string storyboard, trajectories, legend;
  float cell = 0.5f;                    // metres per storyboard pixel
  float jitter = 0.1f;                  // ± metres
  std::string policy = "anticipatory";  // published (rule), anticipatory (ttc) or none
  float radius = 0.3f;                  // safe radius (m)
  float stepTime = 0.0f;                // seconds per annotation step; 0: by dataset
  float extent = 0.0f;                  // set by validation: half the storyboard's larger side (m)
};

struct SceneOptions {
  crowd::ScenarioOptions scenario;
  long long characters = 3000;  // signed so that a negative count is reported, not wrapped
  std::string slowClip, fastClip;
  std::string cameraPreset = "wide";
  std::string eye, target;
  std::optional<float> fovY;  // absent: the preset's
  std::string size = "1280x720";
  std::string device;
  float dt = 1.0f / 30.0f;
  bool cache = false;
  float cacheBudgetMb = 20.0f;
  float bucketWidth = 0.05f;
  float speedPeriod = 0.0f;  // seconds between speed changes (paper: 5); 0 = never
  bool lod = false;          // pixel-coverage joint LOD
  bool lodTint = false;      // colour characters by LOD level
  float lodMidPixels = synth::kDefaultMidPixels;    // torso sphere area for the mid level
  float lodNearPixels = synth::kDefaultNearPixels;  // limb sphere area for all joints
  float lodUpdateLag = 0.0f;  // pixels: update-rate LOD (synth/update_rate.h); 0 = off
  std::string cloth;       // compressed cloth database (.tsc): every character wears its cape
  bool clothTint = false;  // colour capes by garment level
  bool clothFull = false;  // every visible cape at full detail (no garment LOD)
  StoryboardSceneOptions story;
  // The Menge scene (--menge PROJECT.xml): its agents, walls, goals and behaviour. Validation
  // sets where it lies (the cameras look at its centre).
  std::string menge;
  float corridorLength = 60.0f;  // the corridor scene (metres; 15 m wide)
  std::string walls;             // --walls FILE: more walls for a steered scene
  glm::vec2 mengeCentre{0.0f};
  float mengeExtent = 0.0f;
  // From a scene file (SCENE.json, tools/scene_file_options.h): its groups (empty: the one
  // group the flags describe), its keyframed camera (empty: fixed) and its seconds of output.
  std::string sceneFile;
  std::vector<scene::GroupDescription> groups;
  std::vector<render::CameraKey> cameraPath;
  float sceneSeconds = 0.0f;
  std::string trajectoriesOut;  // every agent's position per frame (.txt PedPy or .csv)
  // The command the options were parsed by (null when built in code): which options were given,
  // so that one that does nothing in the chosen scene is an error.
  const CLI::App* command = nullptr;
  bool given(const char* flag) const;  // whether `command` was given `flag`
  bool storyboard() const { return scenario.name == "storyboard"; }
  bool mengeScene() const { return scenario.name == "menge"; }
  bool corridor() const { return scenario.name == "corridor"; }
};

// The motion cache keeps a few small per-bucket buffers: --bucket-width may not make more.
constexpr uint32_t kMaxSpeedBuckets = 4096;

// `options` holds the defaults shown in help (render and view turn the coverage LOD and the
// motion cache on before calling this; --no-lod and --no-cache turn them off).
void addSceneOptions(CLI::App& command, SceneOptions& options);

struct Size {
  uint32_t width = 0, height = 0;
};
// "WxH" → size; throws Error on anything else.
Size parseSize(const std::string& text);

// Checks everything that does not need a file or a GPU; throws Error on the first problem.
void validateSceneOptions(SceneOptions& options);
// The cache options alone (the viewer's respawn checks them too): --cache-budget and a
// --bucket-width that makes at most kMaxSpeedBuckets buckets.
void validateSceneCacheOptions(const SceneOptions& options);
// What needs the device's limits but no crowd: --size (the render target) and --cache-budget
// (the cache's data is one storage binding). Throws Error naming the option and the limit.
void checkSceneForDevice(const SceneOptions& options, const gpu::Context& context);
// "-n 3000" (or "--characters 3000"): how errors about the crowd's size name the option.
std::string charactersOption(const SceneOptions& options);
anim::ClipPair loadSceneClips(const SceneOptions& options);
// The scenario's crowd; with the cache on, speed weights sit on bucket speeds.
crowd::Crowd makeSceneCrowd(const SceneOptions& options);
synth::MotionCacheOptions sceneCacheOptions(const SceneOptions& options);
synth::SpeedSchedule sceneSpeedSchedule(const SceneOptions& options);
synth::LodOptions sceneLodOptions(const SceneOptions& options, const anim::Skeleton& skeleton);
// A named preset framed for the scene (around its centre); sceneCamera adds --eye/--target/--fov.
render::Camera scenePreset(const SceneOptions& options, const std::string& preset);
render::Camera sceneCamera(const SceneOptions& options);
// Half the side (or the radius) of the ground the crowd starts on, and the ground drawn.
float sceneExtent(const SceneOptions& options);
float sceneGroundExtent(const SceneOptions& options);
secondary::ClothLayerOptions sceneClothOptions(const SceneOptions& options);

}  // namespace throng::tools
