#pragma once
// The stages of a frame (scene/frame.h), each a small job: named inputs, validate() listing
// what is missing, record() that checks them and records the stage with its barriers.
#include <string>
#include <vector>

#include "render/crowd_renderer.h"
#include "scene/scene.h"
#include "secondary/cloth_gpu_layer.h"
#include "synth/coverage.h"

namespace throng::scene {

// Goals, grid and avoidance of a steered scene (nothing for other scenes).
struct SteerStage {
  const Scene* scene = nullptr;
  const SceneStep* step = nullptr;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd) const;
};

// Every synthesis pass over each group's range of the scene's crowd; with walls, the wall
// constraint between root motion and the pose passes.
struct SynthesisStage {
  const Scene* scene = nullptr;
  const SceneStep* step = nullptr;
  synth::CoverageCamera lodCamera;  // the draw's camera and viewport
  VkDeviceSize maxBindingBytes = 0;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd) const;
};

// Secondary motion: the capes' advance, mark and decode passes.
struct SecondaryStage {
  secondary::ClothLayer* capes = nullptr;
  render::Camera camera;
  uint32_t width = 0, height = 0, frameSlot = 0;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd) const;
};

// The draw: joints' splat, capes' splat, render pass with ground, joints, capes.
struct DrawStage {
  render::CrowdRenderer* renderer = nullptr;
  secondary::ClothLayer* capes = nullptr;  // optional
  render::DrawParams params;
  render::FrameTargets targets;
  uint32_t frameSlot = 0;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd) const;
};

}  // namespace throng::scene
