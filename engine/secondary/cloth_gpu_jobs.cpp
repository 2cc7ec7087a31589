#include "secondary/cloth_gpu_jobs.h"

#include <cstring>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"
#include "secondary/cloth_gpu_types.h"
#include "synth/synth_jobs.h"

namespace throng::secondary {

namespace {
// The inputs of the passes that read the crowd and this frame's ClothView (mark, draw, splat).
void checkCrowdAndView(std::vector<std::string>& problems, const crowd::CrowdBuffers* crowd,
                       const gpu::Buffer* view) {
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (!view || !*view) problems.push_back("input 'view' (the frame's ClothView buffer) is missing");
}

void checkCommon(std::vector<std::string>& problems, const ClothGpuData* cloth,
                 const crowd::CrowdBuffers* crowd, const ClothCrowdBuffers* buffers) {
  if (!cloth) problems.push_back("input 'cloth' (the uploaded database) is missing");
  if (!buffers) problems.push_back("'buffers' (the crowd's cloth buffers) are missing");
  if (crowd && (!crowd->placement || !crowd->motion))
    problems.push_back("crowd buffers are not allocated");
  if (crowd && buffers && crowd->count != buffers->characterCount)
    problems.push_back(concat("the crowd has ", crowd->count,
                              " characters, the cloth buffers were made for ",
                              buffers->characterCount));
  if (cloth && buffers && buffers->stateLevel.size() < VkDeviceSize(cloth->stateCount) * 4)
    problems.push_back("the cloth buffers were made for a smaller database");
}

constexpr VkPipelineStageFlags kDrawStages =
    VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT;

}  // namespace

std::vector<std::string> ClothAdvanceJob::validate() const {
  std::vector<std::string> problems;
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  checkCommon(problems, cloth, crowd, buffers);
  return problems;
}

void ClothAdvanceJob::record(VkCommandBuffer cmd, const ClothPrograms& programs) const {
  gpu::throwIfInvalid("ClothAdvanceJob", validate());
  if (crowd->count == 0) return;
  gpu_types::ClothAdvancePush push{};
  push.characterCount = crowd->count;
  push.bucketCount = cloth->bucketCount;
  push.bucketWidth = cloth->bucketWidth;
  push.maxWalkSteps = kMaxWalkSteps;
  push.blendFrames = kMergeBlendFrames;
  gpu::Binding bindings[] = {gpu::storageBinding(0, crowd->motion),
                             gpu::storageBinding(1, buffers->characters),
                             gpu::storageBinding(2, cloth->graph)};
  gpu::dispatch(cmd, programs.advance, bindings, push, crowd->count);
}

std::vector<std::string> ClothMarkJob::validate() const {
  std::vector<std::string> problems;
  checkCrowdAndView(problems, crowd, view);
  checkCommon(problems, cloth, crowd, buffers);
  return problems;
}

void ClothMarkJob::record(VkCommandBuffer cmd, const ClothPrograms& programs) const {
  gpu::throwIfInvalid("ClothMarkJob", validate());
  // The previous frame's draw may still read these lists (same queue): wait for it, then reset.
  gpu::memoryBarrier(cmd, kDrawStages | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT);
  vkCmdFillBuffer(cmd, buffers->counters.get(), 0, sizeof(gpu_types::ClothCounters), 0u);
  vkCmdFillBuffer(cmd, buffers->stateLevel.get(), 0, VK_WHOLE_SIZE, gpu_types::kClothNone);
  uint32_t draws[kClothLevels * 5];
  for (uint32_t L = 0; L < kClothLevels; ++L) {
    draws[5 * L + 0] = cloth->lod.indexCount[L];
    draws[5 * L + 1] = 0;  // instances: counted by the mark pass
    draws[5 * L + 2] = cloth->lod.firstIndex[L];
    draws[5 * L + 3] = 0;
    draws[5 * L + 4] = L * buffers->characterCount;  // firstInstance: the level's part of drawList
  }
  vkCmdUpdateBuffer(cmd, buffers->draws.get(), 0, sizeof(draws), draws);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  if (crowd->count > 0) {
    gpu_types::ClothMarkPush push{crowd->count, buffers->maxUsedStates, 0u, 0u};
    gpu::Binding bindings[] = {
        gpu::uniformBinding(0, *view),
        gpu::storageBinding(1, buffers->characters),
        gpu::storageBinding(2, crowd->placement),
        gpu::storageBinding(3, crowd->motion),
        gpu::storageBinding(4, buffers->counters),
        gpu::storageBinding(5, buffers->stateLevel),
        gpu::storageBinding(6, buffers->usedStates),
        gpu::storageBinding(7, buffers->draws),
        gpu::storageBinding(8, buffers->drawList),
        gpu::storageBinding(10, cloth->graph),
    };
    gpu::dispatch(cmd, programs.mark, bindings, push, crowd->count);
  }
  gpu::computeToComputeBarrier(cmd);
  const VkPipelineStageFlags computeAndIndirect =
      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT;
  gpu::Binding args[] = {gpu::storageBinding(4, buffers->counters),
                         gpu::storageBinding(7, buffers->draws),
                         gpu::storageBinding(9, buffers->dispatchArgs)};
  gpu_types::ClothArgsPush argsPush{0u, buffers->maxUsedStates, crowd->count, 0u};
  gpu::dispatch(cmd, programs.args, args, argsPush, 1);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, computeAndIndirect);
  gpu_types::ClothClassifyPush classifyPush{buffers->maxUsedStates, buffers->fineBudget,
                                            buffers->reservedVertices, 0u};
  gpu::Binding classify[] = {
      gpu::storageBinding(3, cloth->levels),       gpu::storageBinding(4, buffers->counters),
      gpu::storageBinding(5, buffers->stateLevel), gpu::storageBinding(6, buffers->usedStates),
      gpu::storageBinding(7, buffers->slots),      gpu::storageBinding(8, buffers->levelLists),
  };
  gpu::dispatchIndirect(cmd, programs.classify, classify, &classifyPush, sizeof(classifyPush),
                        buffers->dispatchArgs, 0);
  gpu::computeToComputeBarrier(cmd);
  argsPush.mode = 1u;
  gpu::dispatch(cmd, programs.args, args, argsPush, 1);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, computeAndIndirect);
}

std::vector<std::string> ClothDecodeJob::validate() const {
  std::vector<std::string> problems;
  checkCommon(problems, cloth, nullptr, buffers);
  return problems;
}

void ClothDecodeJob::record(VkCommandBuffer cmd, const ClothPrograms& programs) const {
  gpu::throwIfInvalid("ClothDecodeJob", validate());
  gpu::Binding bindings[] = {
      gpu::storageBinding(0, cloth->mean),         gpu::storageBinding(1, cloth->bases),
      gpu::storageBinding(2, cloth->coefficients), gpu::storageBinding(3, cloth->levels),
      gpu::storageBinding(4, buffers->counters),   gpu::storageBinding(6, buffers->levelLists),
      gpu::storageBinding(7, buffers->slots),      gpu::storageBinding(8, buffers->pool),
  };
  for (uint32_t level = 0; level < kClothLevels; ++level) {
    gpu_types::ClothDecodePush push{cloth->rowVectors, cloth->basisCount, level,
                                    buffers->maxUsedStates};
    gpu::dispatchIndirect(cmd, programs.decode, bindings, &push, sizeof(push),
                          buffers->dispatchArgs, 12 * (1 + level));
  }
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     kDrawStages | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
}

std::vector<std::string> ClothDrawJob::validate() const {
  std::vector<std::string> problems;
  checkCrowdAndView(problems, crowd, view);
  checkCommon(problems, cloth, crowd, buffers);
  return problems;
}

void ClothDrawJob::record(VkCommandBuffer cmd, const ClothPrograms& programs) const {
  gpu::throwIfInvalid("ClothDrawJob", validate());
  if (crowd->count == 0) return;
  gpu_types::ClothDrawPush push{crowd->count, cloth->vertexCount, kMergeBlendFrames,
                                tintLevels ? gpu_types::kClothDrawTint : 0u};
  gpu::Binding bindings[] = {
      gpu::uniformBinding(0, *view),
      gpu::storageBinding(1, buffers->characters),
      gpu::storageBinding(2, crowd->placement),
      gpu::storageBinding(3, crowd->motion),
      gpu::storageBinding(4, buffers->drawList),
      gpu::storageBinding(5, buffers->slots),
      gpu::storageBinding(6, buffers->pool),
      gpu::storageBinding(7, cloth->remap),
      gpu::storageBinding(8, cloth->graph),
  };
  programs.draw.bind(cmd, bindings, &push, sizeof(push));
  vkCmdBindIndexBuffer(cmd, cloth->indices.get(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexedIndirect(cmd, buffers->draws.get(), 0,
                           splatted ? gpu_types::kClothSplatLevel : kClothLevels, 20);
}

std::vector<std::string> ClothSplatJob::validate() const {
  std::vector<std::string> problems;
  checkCrowdAndView(problems, crowd, view);
  if (!visibility || !*visibility)
    problems.push_back("input/output 'visibility' buffer is missing");
  checkCommon(problems, cloth, crowd, buffers);
  if (cloth && !clothSplattable(*cloth))
    problems.push_back(
        concat("no splat program: the device lacks 64-bit atomics, or the splat level (",
               cloth->lod.levelVertices[gpu_types::kClothSplatLevel], " vertices, ",
               cloth->lod.indexCount[gpu_types::kClothSplatLevel] / 3, " triangles) exceeds ",
               gpu_types::kClothSplatMaxVertices, " / ", gpu_types::kClothSplatMaxTriangles));
  if (view && *view && visibility && *visibility && view->hostVisible()) {
    gpu_types::ClothView v;
    std::memcpy(&v, view->mapped(), sizeof(v));
    const VkDeviceSize pixels = VkDeviceSize(v.viewport.x) * VkDeviceSize(v.viewport.y);
    if (visibility->size() < pixels * 8)
      problems.push_back(concat("the visibility buffer holds ", visibility->size() / 8,
                                " pixels, the view has ", pixels));
  }
  return problems;
}

void ClothSplatJob::record(VkCommandBuffer cmd, const ClothPrograms&) const {
  gpu::throwIfInvalid("ClothSplatJob", validate());
  gpu_types::ClothSplatPush push{crowd->count, 0u, 0u, 0u};
  gpu::Binding bindings[] = {
      gpu::storageBinding(0, *view),  // a storage buffer there (cloth_splat.comp says why)
      gpu::storageBinding(1, buffers->characters),
      gpu::storageBinding(2, crowd->placement),
      gpu::storageBinding(3, crowd->motion),
      gpu::storageBinding(4, buffers->drawList),
      gpu::storageBinding(5, buffers->slots),
      gpu::storageBinding(6, buffers->pool),
      gpu::storageBinding(8, cloth->graph),
      gpu::storageBinding(10, buffers->draws),
      gpu::storageBinding(11, *visibility),
  };
  gpu::dispatchIndirect(cmd, cloth->splat, bindings, &push, sizeof(push), buffers->dispatchArgs,
                        12 * (1 + kClothLevels));
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
}

}  // namespace throng::secondary
