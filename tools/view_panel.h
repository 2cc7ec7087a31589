#pragma once
// The Dear ImGui panel of `throng view`: scene controls (count, scenario, speeds), playback,
// camera presets, coverage LOD and motion cache, and live statistics. Edits land in
// PanelControls; the frame loop applies them.
#include <iterator>
#include <string>
#include <string_view>

#include "render/camera.h"
#include "synth/motion_cache.h"
#include "view_lod.h"
#include "view_stats.h"

namespace throng::tools {

// Where the panel first appears; it sizes itself to its contents.
constexpr float kPanelX = 8.0f, kPanelY = 8.0f;

struct PanelControls {
  int characters = 0;
  int scenario = 0;  // index into kScenarioNames
  bool storyboardAvailable = false;  // --storyboard was given: a respawn may rebuild it
  int seed = 1;
  float speedMin = 0.0f, speedMax = 1.0f;
  float density = 0.5f;
  float speedPeriod = 0.0f;  // seconds; 0: speeds never change
  bool cache = false;        // the motion cache (applied on respawn)
  float cacheBudgetMb = 20.0f;
  float bucketWidth = 0.05f;
  bool lod = false;      // the coverage LOD (switching respawns the crowd)
  bool lodTint = false;  // colour characters by level
  float lodMidPixels = synth::kDefaultMidPixels;    // live thresholds
  float lodNearPixels = synth::kDefaultNearPixels;
  float timeScale = 1.0f;
  bool paused = false;
  bool vsync = true;
  // One-shot requests, cleared by the loop once handled.
  bool respawn = false, step = false, screenshot = false, resetCamera = false;
  int preset = -1;      // index into kPresetNames
  std::string message;  // the last error or saved screenshot, shown in the panel
};

// "storyboard" is offered only when the viewer was given a storyboard (kStoryboardScenario).
inline constexpr const char* kScenarioNames[] = {"random", "circle", "storyboard"};
inline constexpr int kStoryboardScenario = 2;

// The index of a scenario name in kScenarioNames, or -1.
inline int scenarioIndex(std::string_view name) {
  for (int i = 0; i < int(std::size(kScenarioNames)); ++i)
    if (name == kScenarioNames[i]) return i;
  return -1;
}
inline constexpr const char* kPresetNames[] = {"wide", "top", "street", "closeup"};

struct PanelInfo {
  std::string device;
  std::string presentMode;
  std::string clock;
  std::string clips;
  uint32_t width = 0, height = 0;
  uint32_t characters = 0, jointsPerCharacter = 0;
  bool lodEnabled = false;  // in the running crowd
  LodStats lod;             // active joints and levels (every joint without the LOD)
  bool cacheEnabled = false;  // in the running crowd
  synth::MotionCacheStats cache;
  bool clothEnabled = false;  // --cloth: stats->cloth() holds the newest frame's capes
  bool clothSplat = false;    // far capes splatted (else drawn as the coarse mesh)
  std::string clothFile;
  const ViewStats* stats = nullptr;
  const render::Camera* camera = nullptr;
};

struct PanelRect {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
};

// Returns where the panel was drawn (tests compare the rest of the window with `throng render`).
PanelRect drawPanel(PanelControls& controls, const PanelInfo& info);

}  // namespace throng::tools
