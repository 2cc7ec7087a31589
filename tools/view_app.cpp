#include "view_app.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "core/file_io.h"
#include "view_session.h"

namespace throng::tools {
namespace fs = std::filesystem;

namespace {

fs::path nextScreenshotPath() {
  for (int i = 1; i < 10000; ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "throng_view_%04d.png", i);
    if (!fs::exists(name)) return name;
  }
  fail("throng_view_0001.png .. throng_view_9999.png all exist in the working directory");
}

}  // namespace

void checkViewOptions(ViewOptions& o) {
  validateSceneOptions(o.scene);
  if (o.frames < 0 || o.frames > 100000)
    fail("--frames: expected 0..100000 (0: until the window closes), got ", o.frames);
  if (!o.clock.empty() && o.clock != "real" && o.clock != "fixed")
    fail("--clock: expected real or fixed, got '", o.clock, "'");
  if (!o.screenshot.empty()) {
    if (o.frames == 0) fail("--screenshot needs --frames K: the screenshot is taken of frame K");
    fs::path path = o.screenshot;
    if (path.extension() != ".png")
      fail("--screenshot: expected a .png path, got '", o.screenshot, "'");
    ensureWritableDirectory(path.has_parent_path() ? path.parent_path() : fs::path("."));
  }
}

void ViewSession::run() {
  using Clock = std::chrono::steady_clock;
  Clock::time_point last = Clock::now();
  size_t scriptFrame = 0;
  while (true) {
    window_.pollEvents();
    if (scriptFrame < script_.frames.size()) applyScript(script_.frames[scriptFrame++]);
    if (window_.shouldClose()) break;
    if (window_.minimized()) {  // nothing to present to; frames do not count
      window_.waitEvents(0.1);
      last = Clock::now();
      continue;
    }
    Clock::time_point now = Clock::now();
    double wall = std::chrono::duration<double>(now - last).count();
    last = now;

    const bool withPanel = panelVisible_;
    if (withPanel) imgui_->newFrame();
    float flySeconds = fixedClock_ ? o_.scene.dt : static_cast<float>(std::min(wall, 0.1));
    const render::Camera before = camera_;
    for (render::ViewAction action :
         controls_.update(camera_, flySeconds, float(presenter_.swapchain().extent().height)))
      handle(action);
    applyPanel();
    followCameraPath(before);
    float dt = simulationStep(wall);

    std::optional<render::PresentFrame> frame = presenter_.beginFrame([this](uint32_t slot) {
      collectTimes(slot);
      lod_.collect(slot);
    });
    if (!frame) {
      if (withPanel) imgui_->discardFrame();
      continue;
    }
    marks_[frame->slot] = recordCrowd(*frame, dt);
    if (withPanel) {
      panelRect_ = drawPanel(panel_, panelInfo());
      imgui_->record(frame->cmd, presenter_.swapchain(), frame->imageIndex,
                     presenter_.generation());
    }
    panelMarks_[frame->slot] = frame->timestamps->write(frame->cmd);
    lod_.record(frame->cmd, frameSynth(*scene_), frame->slot, stats_.frames() + 1);
    pending_[frame->slot] = true;

    const bool lastFrame = o_.frames > 0 && stats_.frames() + 1 >= uint64_t(o_.frames);
    const bool requested = lastFrame && !o_.screenshot.empty();
    const bool capture = requested || panel_.screenshot;
    presenter_.endFrame(*frame, capture);
    recordTrajectories();
    scene_->simulatedSeconds += dt;
    // Goals: the state machines run between frames on read-back positions (the device idle),
    // every 15 frames.
    if (scene_->crowd->hasGoals() && stats_.frames() % 15 == 14) {
      context_.waitIdle();
      scene_->crowd->updateGoals(context_);
    }
    stats_.frameDone(wall);
    if ((titleSeconds_ += wall) >= 1.0) {
      titleSeconds_ = 0.0;
      window_.setTitle(concat("throng view - ", characterCount(*scene_), " characters - ",
                              int(stats_.fps() + 0.5), " fps"));
    }
    if (capture) saveScreenshot(requested ? fs::path(o_.screenshot) : nextScreenshotPath());
    panel_.screenshot = false;
    if (lastFrame) break;
  }
  context_.waitIdle();
  if (trajectories_) trajectories_->finish();
  for (uint32_t slot = 0; slot < render::kPresenterFrames; ++slot) {
    collectTimes(slot);
    lod_.collect(slot);
  }
}

void runView(ViewOptions& o) {
  checkViewOptions(o);
  Size size = parseSize(o.scene.size);
  render::InputScript script =
      o.inputScript.empty() ? render::InputScript{} : render::loadInputScript(o.inputScript);
  anim::ClipPair clips = loadSceneClips(o.scene);  // file errors before "no display"
  ViewSession session(o, size, std::move(script), std::move(clips));
  session.run();
  session.report();
}

}  // namespace throng::tools
