#pragma once
// The crowd's state as structure of arrays: what the synthesis passes read and write.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/reference_synth.h"
#include "gpu/buffer.h"

namespace throng::crowd {

struct Crowd {
  // placement[i] = (x, y, z, heading); motion[i] = (phase, w, wTarget, scale).
  std::vector<glm::vec4> placement;
  std::vector<glm::vec4> motion;
  std::vector<uint32_t> clipSet;  // which slow/fast pair animates the character (0: default)
  anim::Steering steering = anim::Steering::KeepHeading;

  size_t size() const { return placement.size(); }
  void resize(size_t n);
};

// The same arrays on the GPU (updated in place by the root-motion pass).
struct CrowdBuffers {
  gpu::Buffer placement;
  gpu::Buffer motion;
  // The same as RGBA32F texels: lavapipe gathers a texel fetch in vector loads but moves a
  // storage-buffer vector one component per lane in a loop, so per-character passes read here.
  gpu::Handle<VkBufferView> placementTexels;
  gpu::Handle<VkBufferView> motionTexels;
  uint32_t count = 0;
};
CrowdBuffers uploadCrowd(const gpu::Context& context, const Crowd& crowd);
void downloadCrowd(const gpu::Context& context, const CrowdBuffers& buffers, Crowd& crowd);

}  // namespace throng::crowd
