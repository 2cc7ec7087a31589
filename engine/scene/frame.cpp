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
  params.jointParents = scene.pair(0).parents;
  // Every group has the same joint count; the first pair's placement joints stand for all.
  params.drawnBones = anim::drawnBoneMask(anim::placementJoints(scene.pair(0)));
  params.groundExtent = settings.groundExtent;
  params.masks = synth.lod ? &synth.masks : nullptr;
  params.lodLevels = synth.lod ? &synth.front().coverageParts : nullptr;
  params.tintLevels = settings.tintLevels;
  params.stillView = settings.stillView;
  params.groups = scene.tints();
  if (const crowd::WallBuffers* walls = scene.walls()) {
    params.wallSegments = walls->segmentTexels.get();
    params.wallSegmentCount = walls->segmentCount;
  }
  if (synth.cached())
    params.cachedPoses = {&synth.crowd.placement, &synth.crowd.motion, &synth.poseSource,
                          &synth.cacheData, synth.farBodyPoses ? &synth.farBodyPoses : nullptr};
  return params;
}

namespace {

// The coverage LOD sees a frame through the draw's camera and viewport.
synth::CoverageCamera coverageCameraFor(const FrameSettings& settings) {
  const render::Camera& camera = settings.camera;
  return synth::coverageCamera(camera.view(), camera.fovYDegrees, settings.targets.width,
                               settings.targets.height, camera.nearPlane);
}

// The synthesized joints and LOD masks are read by the capes' compute and the draw.
void synthesisToDrawBarrier(VkCommandBuffer cmd) {
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
}

// The stages that read or write the LOD masks: the synthesis passes and the splat (compute) and
// the joints' vertex shader.
constexpr VkPipelineStageFlags kMaskStages =
    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT;

void copyWhole(VkCommandBuffer cmd, const gpu::Buffer& from, const gpu::Buffer& to) {
  const VkBufferCopy region{0, 0, from.size()};
  vkCmdCopyBuffer(cmd, from.get(), to.get(), 1, &region);
}

}  // namespace

FrameTimestamps recordFrame(VkCommandBuffer cmd, const gpu::Context& context, const Scene& scene,
                            const SceneStep& step, render::CrowdRenderer& renderer,
                            secondary::ClothLayer* capes, const FrameSettings& settings,
                            gpu::TimestampPool& timestamps) {
  const render::FrameTargets& targets = settings.targets;
  FrameTimestamps marks;
  marks.start = timestamps.write(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
  // 1. Steer.
  SteerStage{&scene, &step}.record(cmd);
  marks.steered = timestamps.write(cmd);
  // 2. Synthesize.
  SynthesisStage{&scene, &step, coverageCameraFor(settings), context.info().maxStorageBufferRange}
      .record(cmd);
  marks.synthesized = timestamps.write(cmd);
  synthesisToDrawBarrier(cmd);
  // 3. Secondary motion.
  SecondaryStage{capes, settings.camera, targets.width, targets.height, settings.frameSlot}.record(
      cmd);
  // 4. Draw.
  DrawStage{&renderer, capes, drawParams(scene, settings), targets, settings.frameSlot}.record(cmd);
  marks.rendered = timestamps.write(cmd);
  return marks;
}

FramePreparation::FramePreparation(const gpu::Context& context, const Scene& scene)
    : context_(&context), scene_(&scene) {
  const synth::CrowdSynth& synth = scene.synth();
  if (synth.lod)
    savedMasks_ = gpu::Buffer(context, synth.masks.size(),
                              VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              gpu::MemoryUse::DeviceLocal);
}

void FramePreparation::record(VkCommandBuffer cmd, render::CrowdRenderer& renderer,
                              const FrameSettings& settings) const {
  const synth::CrowdSynth& synth = scene_->synth();
  if (savedMasks_) {
    // After whatever last wrote the masks; before the coverage pass overwrites them.
    gpu::memoryBarrier(cmd, kMaskStages | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT);
    copyWhole(cmd, synth.masks, savedMasks_);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, kMaskStages);
  }
  const synth::CoverageCamera lodCamera = coverageCameraFor(settings);
  synth::recordPosePasses(cmd, scene_->programs(), synth, context_->info().maxStorageBufferRange,
                          &lodCamera);
  synthesisToDrawBarrier(cmd);
  DrawStage{&renderer, nullptr, drawParams(*scene_, settings), settings.targets, settings.frameSlot}
      .record(cmd);
  if (savedMasks_) {
    // After the pose passes, the splat and the joints' draw read them; before the first frame's.
    gpu::memoryBarrier(cmd, kMaskStages | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT);
    copyWhole(cmd, savedMasks_, synth.masks);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, kMaskStages);
  }
}

FrameTimings readFrameTimings(const gpu::TimestampPool& timestamps, const FrameTimestamps& marks) {
  std::vector<uint64_t> ticks = timestamps.fetch();
  return {timestamps.millisecondsBetween(ticks, marks.start, marks.steered),
          timestamps.millisecondsBetween(ticks, marks.steered, marks.synthesized),
          timestamps.millisecondsBetween(ticks, marks.synthesized, marks.rendered)};
}

}  // namespace throng::scene
