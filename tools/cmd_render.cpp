// `throng render`: headless frame dumps of a crowd (synthesis + draw on the GPU, PNG files and/or
// a video). The run itself is render_run.h's.
#include <memory>

#include "command.h"
#include "render_run.h"
#include "scene_options.h"

namespace throng::tools {
namespace {

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>(defaultRenderOptions());
  CLI::App* cmd =
      app.add_subcommand("render", "Render a crowd headless into PNG frames and/or an MP4 video");
  addSceneOptions(*cmd, options->scene);
  cmd->add_option("--frames", options->frames, "Number of frames")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--seconds", options->seconds, "Seconds of animation (instead of --frames)")
      ->check(CLI::Range(0.001f, 3600.0f))
      ->excludes("--frames");
  cmd->add_option("--out,-o", options->out, "Output directory for PNG frames (frame_0000.png ...)")
      ->capture_default_str();
  cmd->add_option("--video", options->video,
                  "Also (without --out: only) an H.264 MP4 video, e.g. crowd.mp4");
  cmd->add_option("--fps", options->fps, "Video frame rate (default: 1 / --dt)")
      ->check(CLI::Range(1.0f, 240.0f));
  cmd->add_flag("--overwrite", options->overwrite, "Replace frames or a video of an earlier run");
  cmd->add_flag("--validation", options->validation, "Enable the Khronos validation layer");
  cmd->add_option("--save-scene", options->saveScene,
                  "Also write the scene as a scene file (JSON) that `throng render FILE` renders "
                  "the same");
  cmd->callback([options, cmd] {
    options->pngs = options->video.empty() || cmd->count("--out") > 0;
    runRender(*options);
  });
}

const CommandRegistration kRegistration("render", addRenderCommand);
}  // namespace
}  // namespace throng::tools
