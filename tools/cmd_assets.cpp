// `throng assets generate [--out DIR]`: writes the project's own default motion clips (the
// run, walk, idle/talk and hop pairs) from the parametric gait, and the example scene files
// (DIR/scenes/). The committed assets/ files are this command's output; tests check that they
// are up to date.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "anim/bvh.h"
#include "anim/gait.h"
#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "scene/example_scenes.h"

namespace throng::tools {
namespace {

struct AssetsOptions {
  std::string out = "assets";
};

void runGenerate(const AssetsOptions& options) {
  const std::filesystem::path dir(options.out);
  ensureWritableDirectory(dir);
  for (const anim::GaitParams& params : anim::allGaits()) {
    anim::RawClip clip = anim::generateGait(params);
    const std::filesystem::path path = dir / clip.sourceName;
    writeTextFileAtomic(path, anim::formatBvh(clip));
    std::printf("%s: %d joints, %d frames at %.0f fps, %.2f m/s\n", path.string().c_str(),
                clip.skeleton.jointCount(), clip.frameCount, 1.0 / params.frameTime, params.speed);
  }
  const std::filesystem::path scenes = dir / "scenes";
  ensureWritableDirectory(scenes);
  for (const auto& [name, scene] : scene::exampleScenes()) {
    writeTextFileAtomic(scenes / name, scene::writeSceneFile(scene));
    std::printf("%s: scene file\n", (scenes / name).string().c_str());
  }
}

void addAssetsCommands(CLI::App& app) {
  CLI::App* assets = app.add_subcommand("assets", "The project's own default assets");
  assets->require_subcommand(1);
  CLI::App* generate =
      assets->add_subcommand("generate",
                             "Write the default clips (run, walk, idle/talk, hop pairs) from the "
                             "parametric gait and the example scene files");
  auto options = std::make_shared<AssetsOptions>();
  generate->add_option("--out", options->out, "Output directory")->capture_default_str();
  generate->callback([options] { runGenerate(*options); });
}

const CommandRegistration kRegistration("assets", addAssetsCommands);

}  // namespace
}  // namespace throng::tools
