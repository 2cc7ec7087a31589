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

GpuMotionPair uploadMotionPair(const gpu::Context& context, const anim::MotionPair& pair) {
  GpuMotionPair gpuPair;
  gpuPair.slow = uploadMotionTexture(context, pair.slow);
  gpuPair.fast = uploadMotionTexture(context, pair.fast);
  gpuPair.parents = gpu::makeStorageBuffer<int32_t>(context, pair.parents);
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
