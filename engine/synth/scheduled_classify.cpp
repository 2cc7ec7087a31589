#include "synth/scheduled_classify.h"

#include <algorithm>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"
#include "gpu/limits.h"
#include "shaders/synth_bindings.h"
#include "synth/gpu_types.h"

namespace throng::synth {

ScheduledClassify makeScheduledClassify(const gpu::Context& context, uint32_t chunkCount) {
  // A step that filled a cache entry classifies every chunk in one dispatch.
  gpu::checkLimit(context, "the scheduled classify of every chunk", "maxComputeWorkGroupCount[0]",
                  chunkCount, context.info().maxComputeWorkGroupCount[0], "workgroups");
  ScheduledClassify out;
  out.args = gpu::ComputeProgram(context, "cache_classify_args.comp");
  out.classify = gpu::ComputeProgram(context, "cache_classify_scheduled.comp");
  // A workgroup classifies one chunk.
  THRONG_CHECK(out.classify.localSizeX() == kUpdateChunkCharacters,
               "cache_classify_scheduled.comp's workgroup must be a chunk of ",
               kUpdateChunkCharacters, " characters");
  const ScheduledClassifyArgs none{0u, 1u, 1u, 0u};
  out.dispatchArgs = gpu::makeStorageBuffer<ScheduledClassifyArgs>(
      context, std::span(&none, 1), gpu::MemoryUse::DeviceLocal,
      VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
  return out;
}

std::vector<std::string> ScheduledClassifyJob::validate() const {
  std::vector<std::string> problems;
  if (!crowd || !crowd->motionTexels) problems.push_back("input 'crowd' motion texels are missing");
  if (!cache || !cache->bucketSlot || !cache->freshSlots)
    problems.push_back("input 'cache' (bucketSlot, freshSlots) is missing");
  if (!rate || !rate->chunkList || !rate->dispatchArgs)
    problems.push_back("input 'rate' (the schedule's list and dispatch) is missing");
  if (!dispatchArgs || !*dispatchArgs) problems.push_back("output 'dispatchArgs' is missing");
  if (!poseSource || !*poseSource) problems.push_back("output 'poseSource' is missing");
  if (!characterLists || !*characterLists) problems.push_back("output 'characterLists' is missing");
  if (!listCounts || !*listCounts) problems.push_back("output 'listCounts' is missing");
  if (characterCount == 0) problems.push_back("characterCount must be > 0");
  if (poseChunk == 0) problems.push_back("poseChunk must be > 0");
  if (jointCount == 0) problems.push_back("jointCount must be > 0");
  if (rate && rate->chunkCount != updateChunkCount(characterCount))
    problems.push_back(concat("the schedule has ", rate->chunkCount, " chunks, ", characterCount,
                              " characters make ", updateChunkCount(characterCount)));
  const VkDeviceSize characters = characterCount;
  if (poseSource && *poseSource && poseSource->size() < characters * 4)
    problems.push_back(concat("buffer 'poseSource' holds ", poseSource->size(), " bytes, ",
                              characters * 4, " needed"));
  if (characterLists && *characterLists && characterLists->size() < characters * 4)
    problems.push_back(concat("buffer 'characterLists' holds ", characterLists->size(), " bytes, ",
                              characters * 4, " needed"));
  const VkDeviceSize chunks = poseChunk > 0 ? (characters + poseChunk - 1) / poseChunk : 0;
  if (listCounts && *listCounts && listCounts->size() < chunks * 4)
    problems.push_back(concat("buffer 'listCounts' holds ", listCounts->size(), " bytes, ",
                              chunks * 4, " needed"));
  if (dispatchArgs && *dispatchArgs && dispatchArgs->size() < sizeof(ScheduledClassifyArgs))
    problems.push_back("buffer 'dispatchArgs' is smaller than ScheduledClassifyArgs");
  return problems;
}

void ScheduledClassifyJob::record(VkCommandBuffer cmd, const ScheduledClassify& programs) const {
  gpu::throwIfInvalid("ScheduledClassifyJob", validate());
  // An earlier step's classify may still read the arguments.
  gpu::memoryBarrier(cmd,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  const gpu::Binding argBindings[] = {
      gpu::storageBinding(gpu_types::kClassifyArgsBindingFreshSlots, cache->freshSlots),
      gpu::storageBinding(gpu_types::kClassifyArgsBindingSchedule, rate->dispatchArgs),
      gpu::storageBinding(gpu_types::kClassifyArgsBindingArgs, *dispatchArgs)};
  gpu::dispatch(cmd, programs.args, argBindings, rate->chunkCount, 1u);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT);
  ClassifySchedulePush push{};
  push.characterCount = characterCount;
  push.rowCount = cache->rowCount;
  push.bucketWidth = cache->options.bucketWidth;
  push.dataBase = cache->dataBase;
  push.jointCount = jointCount;
  push.poseChunk = poseChunk;
  const gpu::Binding bindings[] = {
      gpu::uniformTexelBinding(gpu_types::kCacheClassifyBindingMotion, crowd->motionTexels.get()),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingBucketSlot, cache->bucketSlot),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingCharacterList, *characterLists),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingListCounts, *listCounts),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingPoseSource, *poseSource),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingChunkList, rate->chunkList),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingArgs, *dispatchArgs)};
  gpu::dispatchIndirect(cmd, programs.classify, bindings, &push, sizeof(push), *dispatchArgs, 0);
}

bool classifyScheduledCpu(std::span<const uint32_t> movedChunks, uint32_t freshSlots,
                          std::span<const glm::vec4> motion, std::span<const int32_t> bucketSlot,
                          const ClassifySchedulePush& push, std::span<uint32_t> poseSource,
                          std::vector<std::vector<uint32_t>>& misses) {
  THRONG_CHECK(push.poseChunk > 0 && motion.size() >= push.characterCount &&
                   poseSource.size() >= push.characterCount,
               "classifyScheduledCpu: ", push.characterCount, " characters, ", motion.size(),
               " motions, ", poseSource.size(), " pose sources, pose chunk ", push.poseChunk);
  const bool all = freshSlots > 0;
  std::vector<uint32_t> chunks(movedChunks.begin(), movedChunks.end());
  if (all) {
    chunks.resize(updateChunkCount(push.characterCount));
    for (uint32_t c = 0; c < chunks.size(); ++c) chunks[c] = c;
  }
  std::sort(chunks.begin(), chunks.end());
  misses.assign((push.characterCount + push.poseChunk - 1) / push.poseChunk, {});
  const uint32_t bucketCount = uint32_t(bucketSlot.size());
  for (uint32_t chunk : chunks)
    for (uint32_t k = 0; k < kUpdateChunkCharacters; ++k) {
      const uint32_t i = chunk * kUpdateChunkCharacters + k;
      if (i >= push.characterCount) break;
      const glm::vec4 m = motion[i];
      const int32_t slot =
          bucketSlot[speedBucket(gpu_types::speedWeight(m), push.bucketWidth, bucketCount)];
      if (slot >= 0) {
        const uint32_t row = cacheRow(gpu_types::cyclePhase(m), push.rowCount);
        poseSource[i] = push.dataBase + (uint32_t(slot) * push.rowCount + row) * push.jointCount;
        continue;
      }
      poseSource[i] = gpu_types::kPoseInJoints;
      misses[i / push.poseChunk].push_back(i - i / push.poseChunk * push.poseChunk);
    }
  return all;
}

}  // namespace throng::synth
