#pragma once
// One run of `throng view`: the window, the GPU objects, the crowd, the panel and the input,
// and the statistics it reports at exit.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crowd/trajectory_writer.h"
#include "gpu/context.h"
#include "gpu/limits.h"
#include "scene/frame.h"
#include "view_lod.h"
#include "view_options.h"
#include "view_panel.h"
#include "view_scene.h"
#include "view_stats.h"
#include "viewer/imgui_layer.h"
#include "viewer/input_script.h"
#include "viewer/view_controls.h"
#include "viewer/window_presenter.h"

namespace throng::tools {

class ViewSession {
 public:
  ViewSession(ViewOptions& o, Size size, render::InputScript script, anim::ClipPair clips);
  void run();
  void report();

 private:
  bool uiWantsMouse() const { return panelVisible_ && imgui_ && imgui_->wantsMouse(); }
  bool uiWantsKeyboard() const { return panelVisible_ && imgui_ && imgui_->wantsKeyboard(); }
  void applyScript(const std::vector<render::ScriptEvent>& events);
  void handle(render::ViewAction action);
  void applyPanel();
  void applyLodPanel();
  // `label` names the request in errors ("s.txt:3: respawn 4000000", "the panel's respawn").
  void respawn(const SceneOptions& next, const std::string& label);
  // --trajectories-out: the crowd's placement after a presented frame (waits for the GPU);
  // the crowd the viewer started with only (a respawn ends the record).
  void recordTrajectories();
  // Records the crowd's part of a frame. A device limit met by a respawned crowd brings back the
  // last crowd that recorded, and records that instead; the crowd the viewer started with
  // fails with an error naming -n.
  scene::FrameTimestamps recordCrowd(const render::PresentFrame& frame, float dt);
  scene::FrameTimestamps recordCrowdOnce(const render::PresentFrame& frame, float dt);
  void revertRespawn(const gpu::LimitError& error);
  float simulationStep(double wallSeconds);
  void collectTimes(uint32_t slot);
  void saveScreenshot(const std::filesystem::path& path);
  // With the coverage LOD: the masks of the newest frame read back; without it every joint.
  LodStats lodStats() const {
    return frameSynth(*scene_).lod
               ? lod_.latest()
               : fullDetailStats(characterCount(*scene_), frameSynth(*scene_).jointCount());
  }
  PanelInfo panelInfo() const;

  ViewOptions& o_;
  render::InputScript script_;
  render::Window window_;
  gpu::Context context_;
  bool fitsDevice_;  // --size and --cache-budget checked against the device, before the presenter
  render::WindowPresenter presenter_;
  render::CrowdRenderer renderer_;
  std::unique_ptr<ViewScene> scene_;
  LodReadback lod_;
  std::unique_ptr<render::ImGuiLayer> imgui_;
  render::ViewControls controls_;
  render::Camera camera_, initialCamera_;
  // A scene file's keyframed camera plays until the user moves the camera.
  bool followPath_ = true;
  void followCameraPath(const render::Camera& before);
  PanelControls panel_;
  PanelRect panelRect_;
  bool panelVisible_ = true;
  bool fixedClock_ = false;
  ViewStats stats_;
  scene::FrameTimestamps marks_[render::kPresenterFrames];
  uint32_t panelMarks_[render::kPresenterFrames] = {};
  bool pending_[render::kPresenterFrames] = {};
  std::string screenshotWritten_;
  uint64_t speedChanges_ = 0, respawns_ = 0;
  std::unique_ptr<crowd::TrajectoryWriter> trajectories_;
  std::optional<SceneOptions> recorded_;  // the options of the last crowd that recorded a frame
  bool respawned_ = false;                // the crowd has not recorded a frame since its respawn
  std::string respawnLabel_;              // names the latest respawn in errors
  std::string scriptRespawnLabel_;        // the script's respawn waiting for applyPanel
  double titleSeconds_ = 0.0;
};

}  // namespace throng::tools
