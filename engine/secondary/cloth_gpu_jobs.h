#pragma once
// The cloth playback passes as jobs (named inputs and outputs, validate() listing what is missing,
// record() checking and recording). Order in a frame, after the synthesis moved the crowd:
// advance → mark (+ indirect sizes) → decode → splat (far capes, into the joint renderer's
// visibility buffer), then, inside the render pass, draw. Twins: advanceCharacter,
// markCharacters, decodeStateSubset, splatCapesCpu, placeClothVertex.
#include <string>
#include <vector>

#include "crowd/crowd.h"
#include "secondary/cloth_gpu.h"

namespace throng::secondary {

// Each character's cloth state follows its traversal (reads the crowd's motion).
struct ClothAdvanceJob {
  const ClothGpuData* cloth = nullptr;         // input
  const crowd::CrowdBuffers* crowd = nullptr;  // input: motion (phase, w, wTarget, scale)
  const ClothCrowdBuffers* buffers = nullptr;  // input/output: characters

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const ClothPrograms& programs) const;
};

// Clears the frame's counters, culls and levels each cape, marks the used states and lists the
// characters per level, then gives each used state its pool slot and level (classify) and sizes
// the decode and splat dispatches.
struct ClothMarkJob {
  const ClothGpuData* cloth = nullptr;         // input: levels
  const crowd::CrowdBuffers* crowd = nullptr;  // input: placement, motion
  const ClothCrowdBuffers* buffers = nullptr;  // input: characters; output: the frame's lists
  const gpu::Buffer* view = nullptr;           // input: gpu_types::ClothView (uniform)

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const ClothPrograms& programs) const;
};

// B'·c' + mean for the used states into the pool (one indirect dispatch per level, one invocation
// per state).
struct ClothDecodeJob {
  const ClothGpuData* cloth = nullptr;         // input
  const ClothCrowdBuffers* buffers = nullptr;  // input: used states; output: slots, pool

  std::vector<std::string> validate() const;
  // Ends with a barrier making the pool, slots and draws visible to the draw and the splat.
  void record(VkCommandBuffer cmd, const ClothPrograms& programs) const;
};

// The capes of the splat level rasterized by a compute pass into a visibility buffer of
// (depth bits << 32 | colour) per pixel (render::SplatJob's), which the renderer resolves with
// depth. Needs clothSplattable(*cloth).
struct ClothSplatJob {
  const ClothGpuData* cloth = nullptr;
  const crowd::CrowdBuffers* crowd = nullptr;
  const ClothCrowdBuffers* buffers = nullptr;
  const gpu::Buffer* view = nullptr;        // its viewport must be the visibility buffer's size
  const gpu::Buffer* visibility = nullptr;  // input/output: width × height uint64

  std::vector<std::string> validate() const;
  // Ends with a barrier making the visibility buffer visible to the fragment resolve (the
  // compute resolve orders itself after every compute write).
  void record(VkCommandBuffer cmd, const ClothPrograms& programs) const;  // uses cloth->splat
};

// Every visible cape as triangles: one indexed indirect draw per level (inside a render pass with
// the colour/depth formats the programs were built for; viewport and scissor already set). With
// `splatted` the splat level is left to ClothSplatJob.
struct ClothDrawJob {
  const ClothGpuData* cloth = nullptr;
  const crowd::CrowdBuffers* crowd = nullptr;
  const ClothCrowdBuffers* buffers = nullptr;
  const gpu::Buffer* view = nullptr;
  bool tintLevels = false;
  bool splatted = false;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const ClothPrograms& programs) const;
};

}  // namespace throng::secondary
