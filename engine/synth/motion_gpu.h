#pragma once
// A slow/fast motion pair on the GPU: two RGBA32F motion textures sampled with texelFetch,
// the parent array and the joint radii as SSBOs.
#include "anim/motion_texture.h"
#include "gpu/buffer.h"
#include "gpu/image.h"

namespace throng::synth {

// Joints whose bone never changes: the offset is the same in both clips and not animated, so the
// pose pass gets its offset, length and alignment as specialization constants (synth_jobs.cpp).
std::vector<bool> fixedBones(const anim::MotionPair& pair);

// On a CPU device (lavapipe) the pose pass reads the motion texels from uniform buffers when
// both clips fit: lavapipe gathers uniform data with unrolled loads, storage data with a loop
// per lane and component (12% of the pass at 100,000 characters on one thread). The capacity in
// texels: min(maxUniformBufferRange, 64 KiB) / 16 on a CPU device, 0 (storage buffers) on a GPU.
uint32_t uniformTexelCapacity(const gpu::Context& context);
bool texelsFitUniform(const anim::MotionPair& pair, uint32_t capacity);

struct GpuMotionPair {
  gpu::Image2D slow;
  gpu::Image2D fast;
  gpu::Buffer parents;  // int32 per joint, root −1 (the parent array of docs/design.md)
  std::vector<int32_t> parentsHost;  // the same on the host (the pose pipeline bakes it in)
  std::vector<bool> animatedOffset;  // baked into the pose pipeline too
  gpu::Buffer jointRadius;
  gpu::Buffer constantOffsets;  // uniform buffer: slow and fast offset of each joint (vec4 × 128)
  // The same texels as SSBOs: the pose pass reads these, because on lavapipe a buffer load is
  // several times cheaper than texelFetch (see README, benchmarks).
  gpu::Buffer slowTexels;
  gpu::Buffer fastTexels;
  // The same again as uniform buffers padded to uniformTexelCapacity(context) texels when
  // texelsInUniform, else 16-byte placeholders (the shaders declare both).
  gpu::Buffer slowUniformTexels;
  gpu::Buffer fastUniformTexels;
  bool texelsInUniform = false;
  gpu::Handle<VkSampler> sampler;
  uint32_t jointCount = 0;
  uint32_t slowFrames = 0;
  uint32_t fastFrames = 0;
};

gpu::Image2D uploadMotionTexture(const gpu::Context& context, const anim::MotionTexture& texture);
GpuMotionPair uploadMotionPair(const gpu::Context& context, const anim::MotionPair& pair);

}  // namespace throng::synth
