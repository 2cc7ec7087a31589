#include "synth/motion_gpu.h"

#include "core/error.h"

namespace throng::synth {

gpu::Image2D uploadMotionTexture(const gpu::Context& context, const anim::MotionTexture& texture) {
  if (texture.jointCount > 64) fail("skeletons of more than 64 joints are not supported (got ", texture.jointCount, ")");
  gpu::Image2D image(context, static_cast<uint32_t>(texture.width()), static_cast<uint32_t>(texture.frameCount),
                     VK_FORMAT_R32G32B32A32_SFLOAT,
                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  gpu::uploadImage(context, image,
                   {reinterpret_cast<const uint8_t*>(texture.texels.data()), texture.texels.size() * sizeof(glm::vec4)});
  return image;
}

std::vector<bool> fixedBones(const anim::MotionPair& pair) {
  std::vector<bool> fixed(size_t(pair.jointCount()), false);
  for (int j = 0; j < pair.jointCount(); ++j)
    fixed[size_t(j)] = pair.parents[size_t(j)] >= 0 && !pair.animatedOffset[size_t(j)] &&
                       pair.slow.offset(0, j) == pair.fast.offset(0, j);
  return fixed;
}

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
  gpuPair.constantOffsets = gpu::Buffer(context, offsets.size() * sizeof(glm::vec4),
                                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                        gpu::MemoryUse::DeviceLocal);
  gpu::uploadBytes(context, gpuPair.constantOffsets,
                   {reinterpret_cast<const uint8_t*>(offsets.data()), offsets.size() * sizeof(glm::vec4)});
  gpuPair.animatedOffset = pair.animatedOffset;
  gpuPair.parentsHost = pair.parents;
  gpuPair.jointRadius = gpu::makeStorageBuffer<float>(context, pair.jointRadius);
  gpuPair.slowTexels = gpu::makeStorageBuffer<glm::vec4>(context, pair.slow.texels);
  gpuPair.fastTexels = gpu::makeStorageBuffer<glm::vec4>(context, pair.fast.texels);
  gpuPair.sampler = gpu::makeNearestSampler(context);
  gpuPair.jointCount = static_cast<uint32_t>(pair.jointCount());
  gpuPair.slowFrames = static_cast<uint32_t>(pair.slow.frameCount);
  gpuPair.fastFrames = static_cast<uint32_t>(pair.fast.frameCount);
  return gpuPair;
}

}  // namespace throng::synth
