#include "render/crowd_frame.h"

#include "anim/pair_placement.h"
#include "gpu/commands.h"

namespace throng::render {

FrameTargets offscreenFrameTargets(const OffscreenTarget& target) {
  return {target.color.get(),
          target.color.view(),
          target.depth.get(),
          target.depth.view(),
          target.width,
          target.height,
          VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
}

FrameTimestamps recordCrowdFrame(VkCommandBuffer cmd, const gpu::Context& context,
                                 const synth::SynthPrograms& programs,
                                 const synth::CrowdSynth& synth, CrowdRenderer& renderer,
                                 const Camera& camera, float groundExtent,
                                 const FrameTargets& targets, float dt,
                                 gpu::TimestampPool& timestamps, uint32_t frameSlot,
                                 const anim::SpeedRetarget& retarget, bool tintLevels,
                                 const FrameHooks* hooks) {
  FrameTimestamps marks;
  marks.start = timestamps.write(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
  if (hooks && hooks->beforeSynthesis) hooks->beforeSynthesis(cmd);
  // The coverage LOD sees the frame through the same camera and viewport as the draw.
  synth::CoverageCamera lodCamera = synth::coverageCamera(
      camera.view(), camera.fovYDegrees, targets.width, targets.height, camera.nearPlane);
  synth::recordSynthesis(cmd, programs, synth, dt, context.info().maxStorageBufferRange, retarget,
                         &lodCamera);
  DrawParams params;
  params.camera = camera;
  params.width = targets.width;
  params.height = targets.height;
  params.characterCount = synth.crowd.count;
  params.jointCount = synth.jointCount();
  params.joints = &synth.joints;
  params.drawnBones = anim::drawnBoneMask(anim::placementJoints(*synth.pair));
  params.groundExtent = groundExtent;
  params.masks = synth.lod ? &synth.masks : nullptr;
  params.lodLevels = synth.lod ? &synth.coverageParts : nullptr;
  params.tintLevels = tintLevels;
  if (synth.cache.options.enabled)
    params.cachedPoses = {&synth.crowd.placement, &synth.crowd.motion, &synth.poseSource,
                          &synth.cache.data};
  if (hooks && hooks->moreSynthesis) hooks->moreSynthesis(cmd, lodCamera, params);
  marks.synthesized = timestamps.write(cmd);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  if (hooks && hooks->afterSynthesis) hooks->afterSynthesis(cmd, params);
  if (hooks) {
    params.intoSplat = hooks->intoSplat;
    params.insideRenderPass = hooks->insideRenderPass;
  }
  renderer.record(cmd, targets.color, targets.colorView, targets.depth, targets.depthView, params,
                  targets.finalLayout, frameSlot);
  marks.rendered = timestamps.write(cmd);
  return marks;
}

FrameTimings readFrameTimings(const gpu::TimestampPool& timestamps, const FrameTimestamps& marks) {
  std::vector<uint64_t> ticks = timestamps.fetch();
  return {timestamps.millisecondsBetween(ticks, marks.start, marks.synthesized),
          timestamps.millisecondsBetween(ticks, marks.synthesized, marks.rendered)};
}

}  // namespace throng::render
