#include "scene_trajectories.h"

#include "gpu/buffer.h"

namespace throng::tools {

SceneTrajectories::SceneTrajectories(const SceneOptions& o, const scene::Scene& scene,
                                     uint64_t frames) {
  if (o.trajectoriesOut.empty()) return;
  crowd::checkTrajectoryOutput(o.trajectoriesOut, scene.count(), frames);
  writer_ = std::make_unique<crowd::TrajectoryWriter>(o.trajectoriesOut, 1.0 / double(o.dt),
                                                      scene.labels());
}

void SceneTrajectories::record(const gpu::Context& context, const scene::Scene& scene,
                               double seconds) {
  if (!writer_) return;
  const std::vector<glm::vec4> placement =
      gpu::readback<glm::vec4>(context, scene.crowd().placement, scene.count());
  writer_->addFrame(placement, scene.activeAt(seconds));
}

void SceneTrajectories::finish() {
  if (writer_) writer_->finish();
}

}  // namespace throng::tools
