#pragma once
// The one graphics pipeline that draws every joint of every character as an instanced
// ellipsoid (a ray-cast quad), plus the ground. Records into any colour/depth image pair (offscreen
// target or swapchain image), so the viewer and the frame dumper share it.
#include <memory>
#include <span>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/graphics_pipeline.h"
#include "gpu/image.h"
#include "render/camera.h"
#include "render/frame_targets.h"
#include "render/joint_splat.h"
#include "render/pass_timer.h"
#include "synth/gpu_types.h"

namespace throng::render {

struct DrawParams {
  Camera camera;
  uint32_t width = 0, height = 0;
  uint32_t characterCount = 0;
  uint32_t jointCount = 0;
  const gpu::Buffer* joints = nullptr;  // JointPoint per character per joint
  // Each joint's parent (-1: the root), jointCount of them: a joint's bone runs from its parent's
  // point to its own. The skeleton outlives the draw.
  std::span<const int32_t> jointParents;
  float groundExtent = 100.0f;
  // Joints whose screen sprite is at most this wide go through the compute splat; 0 draws
  // every joint with the graphics pipeline.
  float splatMaxPixels = 24.0f;
  uint64_t drawnBones = ~uint64_t(0);  // bit j: joint j's bone is drawn (anim::drawnBoneMask)
  const gpu::Buffer* masks =
      nullptr;  // coverage LOD: CoverageMask per character (null: all joints)
  const gpu::Buffer* lodLevels =
      nullptr;              // with masks: uniform CoverageParts (levels' drawn joints, long bones)
  bool tintLevels = false;  // colour characters by LOD level (paper Fig. 8)
  const gpu::Buffer* groups = nullptr;  // storyboard group per character (uint): colour by group
  CachedPoseInputs cachedPoses;  // motion cache on: cached characters' joints are composed here
  VkClearColorValue clearColor{{0.55f, 0.66f, 0.78f, 1.0f}};
  // The caller keeps this view for the frames to come (a headless run without a camera path):
  // the ground is made the first time the view is seen, not the second.
  bool stillView = false;
  // Static walls drawn as panels: segments (ax, az, bx, bz) as RGBA32F uniform texels.
  VkBufferView wallSegments = VK_NULL_HANDLE;
  uint32_t wallSegmentCount = 0;
  // The caller draws more with depth between beginDraw and endDraw (the capes): the splatted
  // picture's depths are then copied into the depth attachment.
  bool moreDepthDraws = false;
};

// Camera, light and viewport of a frame as the shaders read them.
gpu_types::FrameUniforms makeFrameUniforms(const DrawParams& params);

// Frames that may be recorded before the first of them completes (uniform buffers per frame).
constexpr uint32_t kFramesInFlight = 3;

class CrowdRenderer {
 public:
  CrowdRenderer(const gpu::Context& context, VkFormat colorFormat, VkFormat depthFormat);

  // False when the device lacks 64-bit buffer atomics: every joint is then drawn as a sprite.
  bool splatSupported() const { return splatSupported_; }

  // The draw in three steps, so that a frame can put other work between them (the capes'
  // splat into the visibility buffer, their draw inside the render pass):
  //  1. recordSplat: the camera uniforms of `frameSlot`, then the compute splat of small joints
  //     into the visibility buffer, which starts as the ground when `target` takes copies and
  //     the view is the previous frame's or stays (DrawParams::stillView); returns the buffer (null
  //     when every joint is drawn as a sprite). Whatever splats into it before beginDraw is
  //     resolved with the joints;
  //  2. beginDraw (the same frame, the same target): puts the visibility buffer into the
  //     target's colour and depth by compute and copies (a ground in the buffer) or clears the
  //     target, begins the render pass and draws the walls, the near joints and, with the target
  //     cleared, the ground and the splat by one full-screen pass (viewport and scissor stay set);
  //  3. endDraw: ends the render pass and leaves the colour image in target.finalLayout.
  // `frameSlot` < kFramesInFlight picks the uniform buffer; reuse a slot only after the frame
  // that last used it has completed. Not const: the splat's visibility buffer follows the
  // target size (old buffers are kept until no frame in flight can use them).
  const gpu::Buffer* recordSplat(VkCommandBuffer cmd, const FrameTargets& target,
                                 const DrawParams& params, uint32_t frameSlot = 0);
  void beginDraw(VkCommandBuffer cmd, const FrameTargets& target, const DrawParams& params,
                 uint32_t frameSlot = 0);
  void endDraw(VkCommandBuffer cmd, const FrameTargets& target);
  // All three steps with nothing between them.
  void record(VkCommandBuffer cmd, const FrameTargets& target, const DrawParams& params,
              uint32_t frameSlot = 0);
  // Per-pass GPU times (THRONG_RENDER_PASS_TIMES=1, one frame in flight at a time).
  PassTimer& passTimer() { return *passTimer_; }

 private:
  gpu::GraphicsProgram joints_;
  gpu::GraphicsProgram jointsOverSplat_;  // near joints tested against the visibility buffer
  gpu::GraphicsProgram ground_;
  gpu::GraphicsProgram walls_;
  std::vector<gpu::Buffer> frameUniforms_;
  const gpu::Context* context_ = nullptr;
  bool splatSupported_ = false;
  SplatWalk splatWalk_ = SplatWalk::PerCharacter;
  std::unique_ptr<PassTimer> passTimer_;
  SplatPrograms splat_;
  SplatLists splatLists_;
  gpu::GraphicsProgram resolve_;
  gpu::Buffer visibility_;
  // The visibility buffer as texels of two pixels each (R32G32B32A32_UINT), as the planes pass
  // reads it: lavapipe gathers a texel fetch's lanes in vector loads, where it moves a storage
  // load's components one lane at a time.
  gpu::Handle<VkBufferView> visibilityTexels_;
  gpu::Buffer draws_;         // indirect draws of the joints too wide to splat, one per chunk
  gpu::Buffer nearList_;      // their indices
  gpu::Buffer onScreenList_;  // characters on screen, whose bodies the splat draws
  gpu::Buffer walkList_;      // characters whose joints the splat walks
  gpu::Buffer listCounts_;    // both lists' lengths and dispatches, per chunk
  gpu::Buffer noMasks_;       // bound when no LOD masks are given
  gpu::Buffer noLodLevels_;   // the uniform bound when no LOD levels are given
  void ensureLists(uint32_t characterCount, uint32_t jointCount);
  uint32_t visibilityWidth_ = 0, visibilityHeight_ = 0;
  std::vector<std::pair<gpu::Buffer, uint32_t>>
      retiredVisibility_;  // buffers, records left before freeing
  std::vector<std::pair<gpu::Handle<VkBufferView>, uint32_t>> retiredViews_;  // the same for views
  void ensureVisibility(uint32_t width, uint32_t height);
  bool splats(const DrawParams& params) const;
  // Whether the splatted picture's depths go into the depth attachment: walls and the caller's
  // draws test against it; near joints alone read the visibility buffer (joints_over_splat.frag).
  static bool depthPlane(const DrawParams& params);
  // The resolve writes the colour plane straight into the target's texels: there is no depth
  // plane to copy in beside it.
  static bool planesInTarget(const FrameTargets& target, const DrawParams& params);
  void drawJoints(VkCommandBuffer cmd, const DrawParams& params, uint32_t frameSlot);
  // The joints too wide to splat (all of them without the splat), by the graphics pipeline.
  void drawNearJoints(VkCommandBuffer cmd, const DrawParams& params, const gpu::Buffer& uniforms);
  // The target's two ways into the render pass: cleared, or the resolved planes copied in
  // (crowd_renderer_planes.cpp).
  void clearTargets(VkCommandBuffer cmd, const FrameTargets& target);
  // True when the ground of this view exists or was recorded now (the same view twice in a row).
  bool groundFor(VkCommandBuffer cmd, const DrawParams& params, uint32_t frameSlot);
  // The visibility buffer (ground and splat) into framePlanes_, then into the target: the colour,
  // and the depth unless only near joints come after.
  void resolvePlanes(VkCommandBuffer cmd, const FrameTargets& target, const DrawParams& params,
                     uint32_t frameSlot);
  void copyPlanesIn(VkCommandBuffer cmd, const FrameTargets& target, const DrawParams& params);
  void beginRendering(VkCommandBuffer cmd, const FrameTargets& target, const DrawParams& params,
                      bool loadColour, bool loadDepth);
  gpu::ComputeProgram groundProgram_;      // ground.comp
  gpu::ComputeProgram planesProgram_;      // visibility_planes.comp
  gpu::Buffer groundVisibility_;           // ground.comp's words, the visibility buffer's start
  std::vector<uint8_t> groundKey_;         // the view they show (uniforms and clear colour)
  std::vector<uint8_t> pendingGroundKey_;  // a ground recorded in a frame not yet whole
  std::vector<uint8_t> previousKey_;       // the previous frame's view
  bool groundCopied_ = false;              // this frame's splat started from the ground
  gpu::Buffer framePlanes_;                // this frame's colour and depth planes
};

}  // namespace throng::render
