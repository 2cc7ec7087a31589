// `throng view` in the `throng` binary: the options are parsed and checked here like every other
// command's, then the same command line runs `throng-view`, installed beside `throng`, which
// holds the window, swapchain and Dear ImGui layer. So `throng` itself links neither GLFW nor
// Dear ImGui.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "command.h"
#include "core/error.h"
#include "view_app.h"

namespace throng::tools {

namespace {
std::filesystem::path viewerExecutable() {
  std::error_code error;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) throw Error("cannot find the throng executable (/proc/self/exe): " + error.message());
  return self.parent_path() / "throng-view";
}
}  // namespace

void runView(ViewOptions&) {
  std::filesystem::path viewer = viewerExecutable();
  std::span<char* const> argv = commandLine();
  execv(viewer.c_str(), argv.data());
  throw Error("cannot run " + viewer.string() +
              " (the viewer, built beside throng): " + std::strerror(errno));
}

}  // namespace throng::tools
