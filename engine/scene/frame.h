#pragma once
// One frame of a scene, as a plain ordered list of stages (scene/frame_stages.h):
//   1. steer       goals, grid and avoidance (steered scenes)
//   2. synthesize  root motion, coverage LOD, motion cache and pose pass over each group's range
//   3. secondary   capes: advance, mark, decode (when the scene wears capes)
//   4. draw        joints (compute splat and sprites), capes' splat and draw, ground
// with GPU timestamps between them. A headless target and a window are two targets for the
// same frame. A new pass goes into the stage it belongs to; a new stage goes into recordFrame.
#include "gpu/context.h"
#include "gpu/timestamps.h"
#include "render/camera.h"
#include "render/crowd_renderer.h"
#include "render/frame_targets.h"
#include "scene/scene.h"
#include "secondary/cloth_gpu_layer.h"

namespace throng::scene {

struct FrameSettings {
  render::Camera camera;
  render::FrameTargets targets;
  float groundExtent = 100.0f;
  uint32_t frameSlot = 0;   // < render::kFramesInFlight
  bool tintLevels = false;  // colour characters by LOD level (paper Fig. 8)
  bool stillView = false;   // the camera stays for the frames to come (DrawParams::stillView)
};

// Timestamp indices written by recordFrame.
struct FrameTimestamps {
  uint32_t start = 0, steered = 0, synthesized = 0, rendered = 0;
};

// GPU milliseconds of a frame's stages (render includes the capes' compute and draw).
struct FrameTimings {
  double steerMs = 0.0;
  double synthesisMs = 0.0;
  double renderMs = 0.0;
};

// What the draw stage draws for this scene through this camera.
render::DrawParams drawParams(const Scene& scene, const FrameSettings& settings);

// Records the frame's stages for `step` (from scene.advance). `capes` may be null.
FrameTimestamps recordFrame(VkCommandBuffer cmd, const gpu::Context& context, const Scene& scene,
                            const SceneStep& step, render::CrowdRenderer& renderer,
                            secondary::ClothLayer* capes, const FrameSettings& settings,
                            gpu::TimestampPool& timestamps);

// What a first frame pays once, paid before the frames are timed: the coverage, motion cache
// and pose passes and the draw (a pipeline's first draw, where lavapipe compiles its shaders;
// the first touch of every buffer; a still view's ground). It leaves the scene as it found it:
// no root motion and no steering (nothing moves, the update-rate LOD's schedule keeps its clock,
// the motion cache is asked for nothing, so its first frame counts what it would have counted),
// no capes, and the LOD masks, which the coverage pass moves on by a step of their hysteresis,
// copied back afterwards. What it draws is not a frame of the run. Meant for before a scene's
// first frame: later, an update-rate scene's full classify would rewrite chunks' pose sources
// that its next scheduled classify does not visit.
class FramePreparation {
 public:
  // Makes the masks' copy (throws gpu::LimitError past a device limit).
  FramePreparation(const gpu::Context& context, const Scene& scene);
  // Records it. Keep this object until the commands completed (the masks' copy).
  void record(VkCommandBuffer cmd, render::CrowdRenderer& renderer,
              const FrameSettings& settings) const;

 private:
  const gpu::Context* context_;
  const Scene* scene_;
  gpu::Buffer savedMasks_;  // empty without the coverage LOD
};

FrameTimings readFrameTimings(const gpu::TimestampPool& timestamps, const FrameTimestamps& marks);

}  // namespace throng::scene
