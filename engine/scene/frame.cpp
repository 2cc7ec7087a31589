#include "scene/frame.h"

#include "anim/pair_placement.h"
#include "gpu/commands.h"
#include "scene/frame_stages.h"

namespace throng::scene {

render::DrawParams drawParams(const Scene& scene, const FrameSettings& settings) {
  const synth::CrowdSynth& synth = scene.synth();
  render::DrawParams params;
  params.camera = settings.camera;
  params.width = settings.targets.width;
  params.height = settings.targets.height;
  params.characterCount = scene.count();
  params.jointCount = scene.jointCount();
  params.joints = &synth.joints;
  // Every group has the same joint count; the first pair's placement joints stand for all.
  params.drawnBones = anim::drawnBoneMask(anim::placementJoints(scene.pair(0)));
  params.groundExtent = settings.groundExtent;
  params.masks = synth.lod ? &synth.masks : nullptr;
  params.lodLevels = synth.lod ? &synth.front().coverageParts : nullptr;
  params.tintLevels = settings.tintLevels;
  params.groups = scene.tints();
  if (const crowd::WallBuffers* walls = scene.walls()) {
    params.wallSegments = walls->segmentTexels.get();
    params.wallSegmentCount = walls->segmentCount;
  }
  if (synth.cached())
    params.cachedPoses = {&synth.crowd.placement, &synth.crowd.motion, &synth.poseSource,
                          &synth.cacheData};
  return params;
}

FrameTimestamps recordFrame(VkCommandBuffer cmd, const gpu::Context& context, const Scene& scene,
                            const SceneStep& step, render::CrowdRenderer& renderer,
                            secondary::ClothLayer* capes, const FrameSettings& settings,
                            gpu::TimestampPool& timestamps) {
  const render::FrameTargets& targets = settings.targets;
  const render::Camera& camera = settings.camera;
  FrameTimestamps marks;
  marks.start = timestamps.write(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
  // 1. Steer.
  SteerStage{&scene, &step}.record(cmd);
  marks.steered = timestamps.write(cmd);
  // 2. Synthesize; the coverage LOD sees the frame through the draw's camera and viewport.
  SynthesisStage synthesis{&scene, &step,
                           synth::coverageCamera(camera.view(), camera.fovYDegrees, targets.width,
                                                 targets.height, camera.nearPlane),
                           context.info().maxStorageBufferRange};
  synthesis.record(cmd);
  marks.synthesized = timestamps.write(cmd);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  // 3. Secondary motion.
  SecondaryStage{capes, camera, targets.width, targets.height, settings.frameSlot}.record(cmd);
  // 4. Draw.
  DrawStage{&renderer, capes, drawParams(scene, settings), targets, settings.frameSlot}.record(cmd);
  marks.rendered = timestamps.write(cmd);
  return marks;
}

FrameTimings readFrameTimings(const gpu::TimestampPool& timestamps, const FrameTimestamps& marks) {
  std::vector<uint64_t> ticks = timestamps.fetch();
  return {timestamps.millisecondsBetween(ticks, marks.start, marks.steered),
          timestamps.millisecondsBetween(ticks, marks.steered, marks.synthesized),
          timestamps.millisecondsBetween(ticks, marks.synthesized, marks.rendered)};
}

}  // namespace throng::scene
