#include "view_session.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file_io.h"
#include "core/log.h"
#include "limit_option.h"
#include "render/offscreen_target.h"
#include "stats.h"

namespace throng::tools {
namespace fs = std::filesystem;

namespace {

// Keys 1-4 and the panel's preset buttons: the named preset framed for the current crowd.
render::Camera presetCamera(int index, const SceneOptions& scene) {
  return scenePreset(scene, kPresetNames[index]);
}

gpu::ContextOptions contextOptionsFor(const ViewOptions& o, const render::Window& window) {
  gpu::ContextOptions options;
  options.device = o.scene.device;
  options.validation = o.validation;
  options.instanceExtensions = window.requiredInstanceExtensions();
  options.swapchain = true;
  return options;
}
}  // namespace

ViewSession::ViewSession(ViewOptions& o, Size size, render::InputScript script,
                         anim::ClipPair clips)
    : o_(o),
      script_(std::move(script)),
      window_({size.width, size.height, "throng view"}),
      context_(contextOptionsFor(o, window_)),
      fitsDevice_((checkSceneForDevice(o.scene, context_), true)),
      presenter_(context_, window_, o.vsync),
      renderer_(context_, presenter_.swapchain().format(), render::kDepthFormat),
      scene_(namingOption(charactersOption(o.scene),
                          [&] {
                            return makeViewScene(context_, o.scene, std::move(clips),
                                                 presenter_.swapchain().format());
                          })),
      lod_(context_),
      camera_(sceneCamera(o.scene)),
      initialCamera_(camera_),
      panelVisible_(o.panel),
      fixedClock_(o.clock == "fixed" || (o.clock.empty() && o.frames > 0)) {
  logInfo(concat("clips: ", scene_->clipDescription));
  if (!o.scene.trajectoriesOut.empty()) {
    crowd::checkTrajectoryOutput(o.scene.trajectoriesOut, characterCount(*scene_),
                                 uint64_t(std::max(o.frames, 0)));
    trajectories_ = std::make_unique<crowd::TrajectoryWriter>(
        o.scene.trajectoriesOut, 1.0 / double(o.scene.dt), std::vector<uint32_t>{});
  }
  window_.setCallbacks({
      [this](double x, double y) { controls_.cursor(x, y); },
      [this](int button, bool pressed) { controls_.button(button, pressed, uiWantsMouse()); },
      [this](double dy) { controls_.scroll(dy, uiWantsMouse()); },
      [this](int key, bool pressed, bool repeat) {
        controls_.key(key, pressed, repeat, uiWantsKeyboard());
      },
  });
  imgui_ = std::make_unique<render::ImGuiLayer>(context_, window_, presenter_.swapchain(),
                                                render::kPresenterFrames);
  const crowd::ScenarioOptions& s = o.scene.scenario;
  panel_.characters = static_cast<int>(s.characters);
  panel_.scenario = std::max(scenarioIndex(s.name), 0);
  panel_.storyboardAvailable = !o.scene.story.storyboard.empty();
  panel_.seed = static_cast<int>(s.seed);
  panel_.density = s.density;
  panel_.speedMin = s.minSpeedWeight;
  panel_.speedMax = s.maxSpeedWeight;
  panel_.speedPeriod = o.scene.speedPeriod;
  panel_.cache = o.scene.cache;
  panel_.cacheBudgetMb = o.scene.cacheBudgetMb;
  panel_.bucketWidth = o.scene.bucketWidth;
  panel_.lod = o.scene.lod;
  panel_.lodTint = o.scene.lodTint;
  panel_.lodMidPixels = o.scene.lodMidPixels;
  panel_.lodNearPixels = o.scene.lodNearPixels;
  panel_.vsync = o.vsync;
}

void ViewSession::applyScript(const std::vector<render::ScriptEvent>& events) {
  using Kind = render::ScriptEvent::Kind;
  for (const render::ScriptEvent& e : events) {
    switch (e.kind) {
      case Kind::Cursor:
        controls_.cursor(e.x, e.y);
        break;
      case Kind::Button:
        controls_.button(e.code, e.pressed, false);
        break;
      case Kind::Scroll:
        controls_.scroll(e.x, false);
        break;
      case Kind::Key:
        controls_.key(e.code, e.pressed, false, false);
        break;
      case Kind::Resize:
        namingOption(concat(e.where, ": resize ", long(e.x), " ", long(e.y)), [&] {
          render::checkTargetSize(context_, uint32_t(e.x), uint32_t(e.y),
                                  concat("a ", long(e.x), "x", long(e.y), " window"));
        });
        window_.resize(uint32_t(e.x), uint32_t(e.y));
        break;
      case Kind::Respawn:
        panel_.characters = static_cast<int>(e.x);
        if (!e.text.empty()) {
          int index = scenarioIndex(e.text);
          if (index < 0 || (index == kStoryboardScenario && !panel_.storyboardAvailable))
            fail("input script: unknown scenario '", e.text, "'",
                 index == kStoryboardScenario ? " (the viewer was started without --storyboard)"
                                              : "");
          panel_.scenario = index;
        }
        panel_.respawn = true;
        scriptRespawnLabel_ =
            concat(e.where, ": respawn ", long(e.x), e.text.empty() ? "" : " ", e.text);
        break;
      case Kind::Lod:  // as the checkbox: applyLodPanel respawns when it differs from the crowd
        panel_.lod = e.pressed;
        break;
      case Kind::Cache:  // as the checkbox: the next respawn builds the crowd with it or without
        panel_.cache = e.pressed;
        break;
      case Kind::Close:
        window_.requestClose();
        break;
    }
  }
}

void ViewSession::handle(render::ViewAction action) {
  using A = render::ViewAction;
  switch (action) {
    case A::ResetCamera:
      camera_ = initialCamera_;
      break;
    case A::PresetWide:
      panel_.preset = 0;
      break;
    case A::PresetTop:
      panel_.preset = 1;
      break;
    case A::PresetStreet:
      panel_.preset = 2;
      break;
    case A::PresetCloseup:
      panel_.preset = 3;
      break;
    case A::TogglePause:
      panel_.paused = !panel_.paused;
      break;
    case A::Step:
      panel_.paused = true;
      panel_.step = true;
      break;
    case A::TogglePanel:
      panelVisible_ = !panelVisible_;
      break;
    case A::ToggleVsync:
      panel_.vsync = !panel_.vsync;
      break;
    case A::Screenshot:
      panel_.screenshot = true;
      break;
    case A::Quit:
      window_.requestClose();
      break;
  }
}

void ViewSession::applyPanel() {
  if (panel_.resetCamera) camera_ = initialCamera_;
  if (panel_.preset >= 0) camera_ = presetCamera(panel_.preset, scene_->options);
  panel_.resetCamera = false;
  panel_.preset = -1;
  presenter_.setVsync(panel_.vsync);
  // The speed range and period apply live (from the next speed change) and to respawns.
  if (panel_.speedMin <= panel_.speedMax) {
    scene_->crowd->speeds().lo = panel_.speedMin;
    scene_->crowd->speeds().hi = panel_.speedMax;
  }
  scene_->crowd->speeds().period = panel_.speedPeriod;
  applyLodPanel();
  if (panel_.respawn) {
    panel_.respawn = false;
    SceneOptions next = scene_->options;
    next.scenario.characters = static_cast<uint32_t>(panel_.characters);
    next.scenario.name = kScenarioNames[panel_.scenario];
    next.scenario.seed = static_cast<uint64_t>(panel_.seed);
    next.scenario.density = panel_.density;
    next.scenario.minSpeedWeight = panel_.speedMin;
    next.scenario.maxSpeedWeight = panel_.speedMax;
    next.speedPeriod = panel_.speedPeriod;
    next.cache = panel_.cache;
    next.cacheBudgetMb = panel_.cacheBudgetMb;
    next.bucketWidth = panel_.bucketWidth;
    const std::string label = scriptRespawnLabel_.empty() ? concat("the panel's respawn of ",
                                                                   panel_.characters, " characters")
                                                          : scriptRespawnLabel_;
    scriptRespawnLabel_.clear();
    respawn(next, label);
  }
}

// The thresholds apply live (between frames); switching the LOD on or off rebuilds the crowd
// as it was spawned, as the masks and the parts' buffer exist only in a crowd built with it.
void ViewSession::applyLodPanel() {
  if (panel_.lodMidPixels != scene_->options.lodMidPixels ||
      panel_.lodNearPixels != scene_->options.lodNearPixels) {
    panel_.lodMidPixels = std::max(panel_.lodMidPixels, 0.0f);
    panel_.lodNearPixels = std::max(panel_.lodNearPixels, 0.0f);
    setLodThresholds(context_, *scene_, panel_.lodMidPixels, panel_.lodNearPixels);
  }
  if (panel_.lod != scene_->options.lod) {
    SceneOptions next = scene_->options;
    next.lod = panel_.lod;
    respawn(next, next.lod ? "switching the coverage LOD on" : "switching the coverage LOD off");
    panel_.lod = scene_->options.lod;  // unchanged if the respawn failed
  }
}

void ViewSession::respawn(const SceneOptions& next, const std::string& label) {
  try {
    respawnCrowd(context_, *scene_, next);
    lod_.reset();         // the GPU is idle: pending mask copies describe the old crowd
    stats_.resetCloth();  // a new cloth layer numbers its frames from 1
    ++respawns_;
    respawned_ = true;
    respawnLabel_ = label;
    panel_.message.clear();
  } catch (const Error& e) {
    panel_.message = concat("respawn failed: ", label, ": ", e.what());
    panel_.characters = static_cast<int>(scene_->options.scenario.characters);
    logWarning(panel_.message);
  }
}

void ViewSession::followCameraPath(const render::Camera& before) {
  if (o_.scene.cameraPath.empty() || !followPath_) return;
  const bool moved = camera_.eye != before.eye || camera_.target != before.target ||
                     camera_.fovYDegrees != before.fovYDegrees;
  if (moved) {
    followPath_ = false;
    logInfo("the camera path stops: the camera was moved");
    return;
  }
  camera_ = render::cameraAt(o_.scene.cameraPath, float(scene_->simulatedSeconds), camera_);
}

scene::FrameTimestamps ViewSession::recordCrowdOnce(const render::PresentFrame& frame, float dt) {
  const scene::SceneStep step = scene_->crowd->advance(dt);
  if (step.retarget.epoch != 0) ++speedChanges_;
  scene::FrameSettings settings;
  settings.camera = camera_;
  settings.targets = frame.targets;
  settings.groundExtent = scene_->groundExtent;
  settings.frameSlot = frame.slot;
  settings.tintLevels = panel_.lodTint && frameSynth(*scene_).lod;
  return scene::recordFrame(frame.cmd, context_, *scene_->crowd, step, renderer_,
                            scene_->cloth.get(), settings, *frame.timestamps);
}

scene::FrameTimestamps ViewSession::recordCrowd(const render::PresentFrame& frame, float dt) {
  try {
    scene::FrameTimestamps marks = recordCrowdOnce(frame, dt);
    if (respawned_ || !recorded_) recorded_ = scene_->options;
    respawned_ = false;
    return marks;
  } catch (const gpu::LimitError& e) {
    if (!recorded_)
      fail(charactersOption(scene_->options), ": ", e.what());  // the crowd it started with
    presenter_.restartFrame(frame);  // drops the commands that refer to the crowd's buffers
    revertRespawn(e);
    return recordCrowdOnce(frame, dt);
  }
}

void ViewSession::recordTrajectories() {
  if (!trajectories_ || respawns_ > 0) return;
  context_.waitIdle();
  const crowd::CrowdBuffers& buffers = scene_->crowd->crowd();
  trajectories_->addFrame(gpu::readback<glm::vec4>(context_, buffers.placement, buffers.count));
}

void ViewSession::revertRespawn(const gpu::LimitError& error) {
  const std::string message = concat("respawn failed: ", respawnLabel_, ": ", error.what());
  respawnCrowd(context_, *scene_, *recorded_);  // waits for the GPU first
  // The renderer's per-character lists grew for the refused crowd and are bound whole: a fresh
  // renderer sizes them for the crowd brought back.
  renderer_ =
      render::CrowdRenderer(context_, presenter_.swapchain().format(), render::kDepthFormat);
  lod_.reset();
  stats_.resetCloth();
  --respawns_;
  respawned_ = false;
  panel_.characters = static_cast<int>(scene_->options.scenario.characters);
  panel_.lod = scene_->options.lod;
  panel_.message = message;
  logWarning(message);
}

float ViewSession::simulationStep(double wallSeconds) {
  float step = fixedClock_ ? o_.scene.dt : static_cast<float>(std::min(wallSeconds, 0.1));
  if (panel_.paused) {
    step = panel_.step ? o_.scene.dt : 0.0f;
    panel_.step = false;
  }
  return step * panel_.timeScale;
}

void ViewSession::collectTimes(uint32_t slot) {
  if (!pending_[slot]) return;
  pending_[slot] = false;
  gpu::TimestampPool& pool = presenter_.timestamps(slot);
  scene::FrameTimings t = scene::readFrameTimings(pool, marks_[slot]);
  std::vector<uint64_t> ticks = pool.fetch();
  stats_.passTimes({t.steerMs + t.synthesisMs, t.renderMs,
                    pool.millisecondsBetween(ticks, marks_[slot].rendered, panelMarks_[slot])});
  if (scene_->cloth && scene_->cloth->frameNumber(slot) > 0)
    stats_.clothFrame({scene_->cloth->frameNumber(slot), scene_->cloth->stats(slot),
                       scene_->cloth->timings(slot)});
}

void ViewSession::saveScreenshot(const fs::path& path) {
  writePngAtomic(path, presenter_.capturedImage());
  screenshotWritten_ = path.string();
  panel_.message = concat("saved ", path.string());
  logInfo(concat("screenshot: ", path.string()));
}

PanelInfo ViewSession::panelInfo() const {
  PanelInfo info;
  info.device = context_.info().name;
  info.presentMode = render::presentModeName(presenter_.swapchain().presentMode());
  info.clock = fixedClock_ ? "fixed" : "real";
  info.clips = scene_->clipDescription;
  info.width = presenter_.swapchain().extent().width;
  info.height = presenter_.swapchain().extent().height;
  info.characters = characterCount(*scene_);
  info.jointsPerCharacter = frameSynth(*scene_).jointCount();
  info.lod = lodStats();
  info.lodEnabled = frameSynth(*scene_).lod;
  info.cacheEnabled = frameSynth(*scene_).cached();
  if (info.cacheEnabled) info.cache = synth::readCacheStats(frameSynth(*scene_));
  info.clothEnabled = scene_->cloth != nullptr;
  if (scene_->cloth) {
    info.clothSplat = secondary::clothSplattable(scene_->cloth->gpuData());
    info.clothFile = scene_->options.cloth;
  }
  info.stats = &stats_;
  info.camera = &camera_;
  return info;
}

void ViewSession::report() {
  uint32_t messages = context_.validationEnabled() ? context_.validationMessageCount() : 0;
  PassTimes median = stats_.medians();
  VkExtent2D extent = presenter_.swapchain().extent();
  std::printf("viewed %llu frames of %u characters (%u joints each) at %ux%u, %s: %.1f fps\n",
              static_cast<unsigned long long>(stats_.frames()), characterCount(*scene_),
              frameSynth(*scene_).jointCount(), extent.width, extent.height,
              render::presentModeName(presenter_.swapchain().presentMode()), stats_.averageFps());
  std::printf(
      "GPU time per frame (median): synthesis %.2f ms, render %.2f ms, panel %.2f ms  [%s]\n",
      median.synthesisMs, median.renderMs, median.panelMs, context_.info().name.c_str());
  if (scene_->cloth)
    std::printf("cloth (median, inside render): %.2f ms\n", stats_.clothMedianMs());
  if (o_.printStats) {
    nlohmann::json j;
    j["schema"] = "throng.view_stats";
    j["version"] = 1;
    j["frames"] = stats_.frames();
    j["width"] = extent.width;
    j["height"] = extent.height;
    j["device"] = context_.info().name;
    j["present_mode"] = render::presentModeName(presenter_.swapchain().presentMode());
    j["clock"] = fixedClock_ ? "fixed" : "real";
    j["characters"] = characterCount(*scene_);
    j["joints_per_character"] = frameSynth(*scene_).jointCount();
    LodStats lod = lodStats();
    j["active_joints"] = lod.activeJoints;
    j["lod"] = {{"enabled", frameSynth(*scene_).lod},
                {"active_joints", lod.activeJoints},
                {"levels", lod.levels},
                {"mid_pixels", scene_->options.lodMidPixels},
                {"near_pixels", scene_->options.lodNearPixels},
                {"tint", panel_.lodTint && frameSynth(*scene_).lod}};
    if (frameSynth(*scene_).cached()) {
      synth::MotionCacheStats c = synth::readCacheStats(frameSynth(*scene_));
      j["cache"] = {
          {"hits", c.hits},       {"misses", c.misses},        {"evictions", c.evictions},
          {"entries", c.entries}, {"bytes_used", c.bytesUsed}, {"budget_bytes", c.budgetBytes}};
    } else {
      j["cache"] = "off";
    }
    j["camera"] = {{"eye", {camera_.eye.x, camera_.eye.y, camera_.eye.z}},
                   {"target", {camera_.target.x, camera_.target.y, camera_.target.z}},
                   {"fov_y", camera_.fovYDegrees}};
    j["fps"] = stats_.fps();
    j["average_fps"] = stats_.averageFps();
    j["gpu_ms"] = {
        {"synthesis", median.synthesisMs}, {"render", median.renderMs}, {"panel", median.panelMs}};
    j["panel"] = {{"visible", panelVisible_},
                  {"x", panelRect_.x},
                  {"y", panelRect_.y},
                  {"width", panelRect_.width},
                  {"height", panelRect_.height}};
    j["swapchain_rebuilds"] = presenter_.rebuildCount();
    j["simulated_seconds"] = scene_->simulatedSeconds;
    j["paused"] = panel_.paused;
    j["speed_changes"] = speedChanges_;
    j["respawns"] = respawns_;
    if (scene_->cloth) {
      // What the panel shows (panelInfo): the newest completed frame's counters and times.
      const PanelInfo info = panelInfo();
      const ClothFrameStats& c = info.stats->cloth();
      const CapeCounts n = capeCounts(c.capes, info.clothSplat);
      j["cloth"] = {
          {"file", info.clothFile},
          {"gpu_ms", stats_.clothMedianMs()},
          {"frame", c.frame},
          {"used_states", c.capes.usedStates},
          {"demoted", c.capes.demoted},
          {"levels", {c.capes.capes[0], c.capes.capes[1], c.capes.capes[2], c.capes.capes[3]}},
          {"capes", {{"triangles", n.triangles}, {"coarse", n.coarse}, {"splatted", n.splatted}}},
          {"splat", info.clothSplat},
          {"last_frame_ms",
           {{"total", c.gpu.totalMs()},
            {"advance", c.gpu.advanceMs},
            {"mark", c.gpu.markMs},
            {"decode", c.gpu.decodeMs},
            {"splat", c.gpu.splatMs},
            {"draw", c.gpu.drawMs}}}};
    }
    j["validation_messages"] = messages;
    j["screenshot"] = screenshotWritten_;
    std::printf("%s\n", j.dump().c_str());
  }
  std::fflush(stdout);
  if (messages > 0) fail(messages, " Vulkan validation message(s) during the run");
}

}  // namespace throng::tools
