// `throng view`: the interactive viewer (GLFW window, Vulkan swapchain, Dear ImGui panel). It
// shares the scene options and the frame code with `throng render`.
#include <memory>

#include "command.h"
#include "view_app.h"

namespace throng::tools {
namespace {

void addViewCommand(CLI::App& app) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* cmd =
      app.add_subcommand("view", "Fly around a crowd in a window (Vulkan + Dear ImGui)");
  // The method's defaults: the coverage LOD and the motion cache (--no-lod, --no-cache).
  options->scene.lod = options->scene.cache = true;
  addSceneOptions(*cmd, options->scene);
  cmd->add_option("--frames", options->frames,
                  "Show this many frames, then exit (0: until the window closes)")
      ->capture_default_str();
  cmd->add_option("--screenshot", options->screenshot,
                  "Save the last of --frames as this PNG, then exit");
  cmd->add_option(
      "--input-script", options->inputScript,
      "Replay input: lines 'wait N', 'drag X0 Y0 X1 Y1 [N] [left|right|middle]', 'key NAME [N]', "
      "'scroll STEPS', 'resize W H', 'respawn N [SCENARIO]', 'close' (see docs/viewer.md)");
  cmd->add_option(
      "--clock", options->clock,
      "real: animate in wall-clock time; fixed: every frame advances --dt (default with --frames, "
      "so screenshots match `throng render`)");
  cmd->add_flag("--vsync,!--no-vsync", options->vsync,
                "Wait for vertical blank: FIFO (default) or MAILBOX/IMMEDIATE with --no-vsync");
  cmd->add_flag("--panel,!--no-panel", options->panel,
                "Show the ImGui panel at start (default; Tab toggles it)");
  cmd->add_flag("--validation", options->validation, "Enable the Khronos validation layer");
  cmd->add_flag("--print-stats", options->printStats,
                "Print the final camera and statistics as one JSON line");
  cmd->callback([options] { runView(*options); });
}

const CommandRegistration kRegistration("view", addViewCommand);

}  // namespace
}  // namespace throng::tools
