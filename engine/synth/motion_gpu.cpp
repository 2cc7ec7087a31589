#include "synth/motion_gpu.h"

#include <algorithm>

#include "core/error.h"

namespace throng::synth {

gpu::Image2D uploadMotionTexture(const gpu::Context& context, const anim::MotionTexture& texture) {
  if (texture.jointCount > 64)
    fail("skeletons of more than 64 joints are not supported (got ", texture.jointCount, ")");
  gpu::Image2D image(context, static_cast<uint32_t>(texture.width()),
                     static_cast<uint32_t>(texture.frameCount), VK_FORMAT_R32G32B32A32_SFLOAT,
                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  gpu::uploadImage(context, image,
                   {reinterpret_cast<const uint8_t*>(texture.texels.data()),
                    texture.texels.size() * sizeof(glm::vec4)});
  return image;
}

std::vector<bool> fixedBones(const anim::MotionPair& pair) {
  std::vector<bool> fixed(size_t(pair.jointCount()), false);
  for (int j = 0; j < pair.jointCount(); ++j)
    fixed[size_t(j)] = pair.parents[size_t(j)] >= 0 && !pair.animatedOffset[size_t(j)] &&
                       pair.slow.offset(0, j) == pair.fast.offset(0, j);
  return fixed;
}

uint32_t uniformTexelCapacity(const gpu::Context& context) {
  if (!context.info().isCpu()) return 0;
  return std::min<uint32_t>(context.info().maxUniformBufferRange, 65536u) / sizeof(glm::vec4);
}

bool texelsFitUniform(const anim::MotionPair& pair, uint32_t capacity) {
  return capacity > 0 && pair.slow.texels.size() <= capacity && pair.fast.texels.size() <= capacity;
}

namespace {
gpu::Buffer uniformTexels(const gpu::Context& context, const std::vector<glm::vec4>& texels,
                          uint32_t slots) {
  std::vector<glm::vec4> padded(std::max<size_t>(slots, 1), glm::vec4(0.0f));
  std::copy(texels.begin(), texels.begin() + std::min(texels.size(), padded.size()),
            padded.begin());
  gpu::Buffer buffer(context, padded.size() * sizeof(glm::vec4),
                     VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                     gpu::MemoryUse::DeviceLocal);
  gpu::uploadBytes(
      context, buffer,
      {reinterpret_cast<const uint8_t*>(padded.data()), padded.size() * sizeof(glm::vec4)});
  return buffer;
}
}  // namespace

GpuMotionPair uploadMotionPair(const gpu::Context& context, const anim::MotionPair& pair) {
  GpuMotionPair gpuPair;
  gpuPair.slow = uploadMotionTexture(context, pair.slow);
  gpuPair.fast = uploadMotionTexture(context, pair.fast);
  gpuPair.parents = gpu::makeStorageBuffer<int32_t>(context, pair.parents);
  std::vector<glm::vec4> offsets(128, glm::vec4(0.0f));
  for (int j = 0; j < pair.jointCount(); ++j) {
    offsets[2 * j] = glm::vec4(pair.slow.offset(0, j), 0.0f);
    offsets[2 * j + 1] = glm::vec4(pair.fast.offset(0, j), 0.0f);
  }
  gpuPair.constantOffsets =
      gpu::Buffer(context, offsets.size() * sizeof(glm::vec4),
                  VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  gpu::MemoryUse::DeviceLocal);
  gpu::uploadBytes(
      context, gpuPair.constantOffsets,
      {reinterpret_cast<const uint8_t*>(offsets.data()), offsets.size() * sizeof(glm::vec4)});
  gpuPair.animatedOffset = pair.animatedOffset;
  gpuPair.parentsHost = pair.parents;
  gpuPair.jointRadius = gpu::makeStorageBuffer<float>(context, pair.jointRadius);
  gpuPair.slowTexels = gpu::makeStorageBuffer<glm::vec4>(context, pair.slow.texels);
  gpuPair.fastTexels = gpu::makeStorageBuffer<glm::vec4>(context, pair.fast.texels);
  const uint32_t capacity = uniformTexelCapacity(context);
  gpuPair.texelsInUniform = texelsFitUniform(pair, capacity);
  const uint32_t slots = gpuPair.texelsInUniform ? capacity : 1u;
  gpuPair.slowUniformTexels = uniformTexels(context, pair.slow.texels, slots);
  gpuPair.fastUniformTexels = uniformTexels(context, pair.fast.texels, slots);
  gpuPair.sampler = gpu::makeNearestSampler(context);
  gpuPair.jointCount = static_cast<uint32_t>(pair.jointCount());
  gpuPair.slowFrames = static_cast<uint32_t>(pair.slow.frameCount);
  gpuPair.fastFrames = static_cast<uint32_t>(pair.fast.frameCount);
  return gpuPair;
}

}  // namespace throng::synth
