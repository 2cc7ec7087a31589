#include "secondary/cloth_gpu_jobs.h"

#include <cstring>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"
#include "secondary/cloth_gpu_types.h"
#include "shaders/cloth_bindings.h"
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
  gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kClothAdvanceBindingMotion, crowd->motion),
      gpu::storageBinding(gpu_types::kClothAdvanceBindingCharacters, buffers->characters),
      gpu::storageBinding(gpu_types::kClothAdvanceBindingGraph, cloth->graph)};
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
        gpu::uniformBinding(gpu_types::kClothMarkBindingView, *view),
        gpu::storageBinding(gpu_types::kClothMarkBindingCharacters, buffers->characters),
        gpu::storageBinding(gpu_types::kClothMarkBindingPlacement, crowd->placement),
        gpu::storageBinding(gpu_types::kClothMarkBindingMotion, crowd->motion),
        gpu::storageBinding(gpu_types::kClothMarkBindingCounters, buffers->counters),
        gpu::storageBinding(gpu_types::kClothMarkBindingStateLevel, buffers->stateLevel),
        gpu::storageBinding(gpu_types::kClothMarkBindingUsedStates, buffers->usedStates),
        gpu::storageBinding(gpu_types::kClothMarkBindingDraws, buffers->draws),
        gpu::storageBinding(gpu_types::kClothMarkBindingDrawList, buffers->drawList),
        gpu::storageBinding(gpu_types::kClothMarkBindingGraph, cloth->graph),
    };
    gpu::dispatch(cmd, programs.mark, bindings, push, crowd->count);
  }
  gpu::computeToComputeBarrier(cmd);
  const VkPipelineStageFlags computeAndIndirect =
      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT;
  gpu::Binding args[] = {
      gpu::storageBinding(gpu_types::kClothArgsBindingCounters, buffers->counters),
      gpu::storageBinding(gpu_types::kClothArgsBindingDraws, buffers->draws),
      gpu::storageBinding(gpu_types::kClothArgsBindingDispatchArgs, buffers->dispatchArgs)};
  gpu_types::ClothArgsPush argsPush{0u, buffers->maxUsedStates, crowd->count, 0u};
  gpu::dispatch(cmd, programs.args, args, argsPush, 1);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, computeAndIndirect);
  gpu_types::ClothClassifyPush classifyPush{buffers->maxUsedStates, buffers->fineBudget,
                                            buffers->reservedVertices, 0u};
  gpu::Binding classify[] = {
      gpu::storageBinding(gpu_types::kClothClassifyBindingLevels, cloth->levels),
      gpu::storageBinding(gpu_types::kClothClassifyBindingCounters, buffers->counters),
      gpu::storageBinding(gpu_types::kClothClassifyBindingStateLevel, buffers->stateLevel),
      gpu::storageBinding(gpu_types::kClothClassifyBindingUsedStates, buffers->usedStates),
      gpu::storageBinding(gpu_types::kClothClassifyBindingSlots, buffers->slots),
      gpu::storageBinding(gpu_types::kClothClassifyBindingLevelLists, buffers->levelLists),
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
      gpu::storageBinding(gpu_types::kClothDecodeBindingMean, cloth->mean),
      gpu::storageBinding(gpu_types::kClothDecodeBindingBases, cloth->bases),
      gpu::storageBinding(gpu_types::kClothDecodeBindingCoefficients, cloth->coefficients),
      gpu::storageBinding(gpu_types::kClothDecodeBindingLevels, cloth->levels),
      gpu::storageBinding(gpu_types::kClothDecodeBindingCounters, buffers->counters),
      gpu::storageBinding(gpu_types::kClothDecodeBindingLevelLists, buffers->levelLists),
      gpu::storageBinding(gpu_types::kClothDecodeBindingSlots, buffers->slots),
      gpu::storageBinding(gpu_types::kClothDecodeBindingPool, buffers->pool),
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
      gpu::uniformBinding(gpu_types::kClothDrawBindingView, *view),
      gpu::storageBinding(gpu_types::kClothDrawBindingCharacters, buffers->characters),
      gpu::storageBinding(gpu_types::kClothDrawBindingPlacement, crowd->placement),
      gpu::storageBinding(gpu_types::kClothDrawBindingMotion, crowd->motion),
      gpu::storageBinding(gpu_types::kClothDrawBindingDrawList, buffers->drawList),
      gpu::storageBinding(gpu_types::kClothDrawBindingSlots, buffers->slots),
      gpu::storageBinding(gpu_types::kClothDrawBindingPool, buffers->pool),
      gpu::storageBinding(gpu_types::kClothDrawBindingRemap, cloth->remap),
      gpu::storageBinding(gpu_types::kClothDrawBindingGraph, cloth->graph),
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
      // The view as a storage buffer there (cloth_splat.comp says why).
      gpu::storageBinding(gpu_types::kClothSplatBindingView, *view),
      gpu::storageBinding(gpu_types::kClothSplatBindingCharacters, buffers->characters),
      gpu::storageBinding(gpu_types::kClothSplatBindingPlacement, crowd->placement),
      gpu::storageBinding(gpu_types::kClothSplatBindingMotion, crowd->motion),
      gpu::storageBinding(gpu_types::kClothSplatBindingDrawList, buffers->drawList),
      gpu::storageBinding(gpu_types::kClothSplatBindingSlots, buffers->slots),
      gpu::storageBinding(gpu_types::kClothSplatBindingPool, buffers->pool),
      gpu::storageBinding(gpu_types::kClothSplatBindingGraph, cloth->graph),
      gpu::storageBinding(gpu_types::kClothSplatBindingDraws, buffers->draws),
      gpu::storageBinding(gpu_types::kClothSplatBindingVisibility, *visibility),
  };
  gpu::dispatchIndirect(cmd, cloth->splat, bindings, &push, sizeof(push), buffers->dispatchArgs,
                        12 * (1 + kClothLevels));
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
}

}  // namespace throng::secondary
