#include "bench_render_loop.h"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "core/error.h"
#include "core/file_io.h"

namespace throng::tools {
namespace {

// The frames' folder, removed however the run ends (the frames are not what the row is for).
class TemporaryFolder {
 public:
  TemporaryFolder() : path_(renderLoopFolder()) { ensureWritableDirectory(path_); }
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace

std::filesystem::path renderLoopFolder() {
  std::error_code error;
  const std::filesystem::path temporary = std::filesystem::temp_directory_path(error);
  if (error)
    fail("the render-loop row writes its frames to a temporary folder, and there is none (",
         error.message(), "; set TMPDIR to a writable folder)");
  ensureWritableDirectory(temporary);
  return temporary / ("throng-bench-render-" + std::to_string(::getpid()));
}

RenderRunTimes benchRenderLoop(const RenderLoopBenchOptions& options) {
  RenderOptions o = defaultRenderOptions();
  o.scene.device = options.device;
  if (options.quick) {
    o.frames = 5;
    o.scene.characters = 1000;
    o.scene.size = "320x180";
  }
  TemporaryFolder folder;
  o.out = folder.path().string();
  o.overwrite = true;
  o.report = false;
  return runRender(o);
}

}  // namespace throng::tools
