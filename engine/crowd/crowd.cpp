#include "crowd/crowd.h"

namespace throng::crowd {

void Crowd::resize(size_t n) {
  placement.resize(n, glm::vec4(0.0f));
  motion.resize(n, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  clipSet.resize(n, 0);
}

CrowdBuffers uploadCrowd(const gpu::Context& context, const Crowd& crowd) {
  CrowdBuffers buffers;
  buffers.count = static_cast<uint32_t>(crowd.size());
  buffers.placement =
      gpu::makeStorageBuffer<glm::vec4>(context, crowd.placement, gpu::MemoryUse::DeviceLocal,
                                        VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
  buffers.placementTexels =
      gpu::makeBufferView(context, buffers.placement, VK_FORMAT_R32G32B32A32_SFLOAT);
  buffers.motion = gpu::makeStorageBuffer<glm::vec4>(
      context, crowd.motion, gpu::MemoryUse::DeviceLocal, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
  buffers.motionTexels =
      gpu::makeBufferView(context, buffers.motion, VK_FORMAT_R32G32B32A32_SFLOAT);
  return buffers;
}

void downloadCrowd(const gpu::Context& context, const CrowdBuffers& buffers, Crowd& crowd) {
  crowd.resize(buffers.count);
  crowd.placement = gpu::readback<glm::vec4>(context, buffers.placement, buffers.count);
  crowd.motion = gpu::readback<glm::vec4>(context, buffers.motion, buffers.count);
}

}  // namespace throng::crowd
