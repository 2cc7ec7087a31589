#pragma once
// A database on the GPU with a crowd, its cloth buffers and a camera, for the playback suites.
#include <cstring>
#include <memory>
#include <vector>

#include "cloth_fixtures.h"
#include "crowd/crowd.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "render/offscreen_target.h"
#include "secondary/cloth_gpu_jobs.h"
#include "secondary/cloth_view.h"

namespace throng::test {

struct ClothGpuRun {
  const secondary::ClothDatabase* db = nullptr;
  std::unique_ptr<secondary::ClothPrograms> programs;
  secondary::ClothGpuData cloth;
  crowd::Crowd crowd;
  crowd::CrowdBuffers crowdBuffers;
  secondary::ClothCrowdBuffers buffers;
  gpu::Buffer view;
  gpu_types::ClothView viewData{};

  ClothGpuRun(const secondary::ClothDatabase& database, const std::vector<glm::vec4>& placement,
              const std::vector<glm::vec4>& motion, uint64_t fineBudgetBytes = 48ull << 20)
      : db(&database) {
    gpu::Context& ctx = gpuContext();
    programs =
        std::make_unique<secondary::ClothPrograms>(ctx, render::kColorFormat, render::kDepthFormat);
    cloth = secondary::uploadCloth(ctx, database);
    crowd.resize(placement.size());
    crowd.placement = placement;
    crowd.motion = motion;
    crowdBuffers = crowd::uploadCrowd(ctx, crowd);
    buffers =
        secondary::makeClothCrowdBuffers(ctx, cloth, uint32_t(placement.size()), fineBudgetBytes);
    // Uniform for the mark and the draw, storage for the splat (cloth_splat.comp).
    view = gpu::Buffer(ctx, sizeof(gpu_types::ClothView),
                       VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                       gpu::MemoryUse::HostVisible);
  }

  void setCamera(const render::Camera& camera, uint32_t width, uint32_t height,
                 const secondary::ClothLodSettings& lod) {
    viewData = secondary::makeClothView(camera, width, height, cloth.lod, lod);
    std::memcpy(view.mapped(), &viewData, sizeof(viewData));
  }
  void setMotion(const std::vector<glm::vec4>& motion) {
    crowd.motion = motion;
    gpu::uploadBytes(
        gpuContext(), crowdBuffers.motion,
        {reinterpret_cast<const uint8_t*>(motion.data()), motion.size() * sizeof(glm::vec4)});
  }
  void setCharacters(const std::vector<secondary::ClothCharacter>& characters) {
    gpu::uploadBytes(gpuContext(), buffers.characters,
                     {reinterpret_cast<const uint8_t*>(characters.data()),
                      characters.size() * sizeof(characters[0])});
  }
  std::vector<secondary::ClothCharacter> characters() const {
    return gpu::readback<secondary::ClothCharacter>(gpuContext(), buffers.characters, crowd.size());
  }
  secondary::ClothAdvanceJob advanceJob() const { return {&cloth, &crowdBuffers, &buffers}; }
  secondary::ClothMarkJob markJob() const { return {&cloth, &crowdBuffers, &buffers, &view}; }
  secondary::ClothDecodeJob decodeJob() const { return {&cloth, &buffers}; }
  secondary::ClothDrawJob drawJob() const { return {&cloth, &crowdBuffers, &buffers, &view}; }
};

}  // namespace throng::test
