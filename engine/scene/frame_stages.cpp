#include "scene/frame_stages.h"

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"

namespace throng::scene {

std::vector<std::string> SteerStage::validate() const {
  std::vector<std::string> problems;
  if (!scene) problems.push_back("input 'scene' is missing");
  if (!step) problems.push_back("input 'step' is missing");
  if (scene && step && scene->steered() != step->steering.has_value())
    problems.push_back("the step was not made by this scene's advance()");
  return problems;
}

void SteerStage::record(VkCommandBuffer cmd) const {
  gpu::throwIfInvalid("SteerStage", validate());
  scene->recordSteering(cmd, *step);
}

std::vector<std::string> SynthesisStage::validate() const {
  std::vector<std::string> problems;
  if (!scene) problems.push_back("input 'scene' is missing");
  if (!step) problems.push_back("input 'step' is missing");
  if (maxBindingBytes == 0) problems.push_back("maxBindingBytes must be > 0");
  return problems;
}

void SynthesisStage::record(VkCommandBuffer cmd) const {
  gpu::throwIfInvalid("SynthesisStage", validate());
  // With walls, root motion is followed by the constraint that keeps characters off them, and
  // the pose passes see the constrained placement.
  // Without walls root motion also does the coverage pass.
  scene->recordSavePositions(cmd);
  const bool covered =
      synth::recordRootMotionPasses(cmd, scene->programs(), scene->synth(), step->dt,
                                    step->retarget, scene->hasWalls() ? nullptr : &lodCamera);
  if (scene->hasWalls()) {
    scene->recordWallConstraint(cmd);
    gpu::computeToComputeBarrier(cmd);
  }
  synth::recordPosePasses(cmd, scene->programs(), scene->synth(), maxBindingBytes, &lodCamera,
                          nullptr, covered);
}

std::vector<std::string> SecondaryStage::validate() const {
  std::vector<std::string> problems;
  if (capes && (width == 0 || height == 0)) problems.push_back("the viewport is empty");
  if (frameSlot >= render::kFramesInFlight)
    problems.push_back(concat("frame slot ", frameSlot, " is past ", render::kFramesInFlight));
  return problems;
}

void SecondaryStage::record(VkCommandBuffer cmd) const {
  gpu::throwIfInvalid("SecondaryStage", validate());
  if (capes) capes->recordCompute(cmd, camera, width, height, frameSlot);
}

std::vector<std::string> DrawStage::validate() const {
  std::vector<std::string> problems;
  if (!renderer) problems.push_back("input 'renderer' is missing");
  if (!targets.color || !targets.depth) problems.push_back("the target images are missing");
  if (targets.width != params.width || targets.height != params.height)
    problems.push_back(concat("the target is ", targets.width, "x", targets.height,
                              ", the draw's viewport ", params.width, "x", params.height));
  if (params.characterCount > 0 && !params.joints) problems.push_back("input 'joints' is missing");
  return problems;
}

void DrawStage::record(VkCommandBuffer cmd) const {
  gpu::throwIfInvalid("DrawStage", validate());
  // The capes splat into the joints' visibility buffer, which beginDraw resolves.
  render::DrawParams drawn = params;
  drawn.moreDepthDraws = capes != nullptr;  // their draw inside the render pass tests depth
  const gpu::Buffer* visibility = renderer->recordSplat(cmd, targets, drawn, frameSlot);
  if (capes && visibility) capes->recordSplat(cmd, *visibility, frameSlot);
  renderer->beginDraw(cmd, targets, drawn, frameSlot);
  if (capes) capes->recordDraw(cmd, frameSlot);
  renderer->endDraw(cmd, targets);
}

}  // namespace throng::scene
