#pragma once
// --trajectories-out for the frame loops of `throng render` and `throng view`: after each
// frame, the crowd's placement is read back from the GPU and appended to the export. Nothing is
// read back without the option.
#include <memory>

#include "crowd/trajectory_writer.h"
#include "gpu/context.h"
#include "scene_options.h"
#include "scene_storyboard.h"

namespace throng::tools {

class SceneTrajectories {
 public:
  // `frames`: how many frames the run records at most (0: not known yet; the writer's row
  // bound applies). Throws Error naming --trajectories-out.
  SceneTrajectories(const SceneOptions& options, const scene::Scene& scene, uint64_t frames);
  bool enabled() const { return writer_ != nullptr; }
  // After a frame has finished on the GPU; `seconds`: the scene time of that frame.
  void record(const gpu::Context& context, const scene::Scene& scene, double seconds);
  // Writes the file (atomically); nothing when disabled.
  void finish();

 private:
  std::unique_ptr<crowd::TrajectoryWriter> writer_;
};

}  // namespace throng::tools
