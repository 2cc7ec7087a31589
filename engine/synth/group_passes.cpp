#include "synth/group_passes.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"
#include "gpu/program.h"
#include "shaders/synth_bindings.h"
#include "synth/gpu_types.h"

namespace throng::synth {

using gpu_types::ClassifyGroupsPush;
using gpu_types::kSynthMaxGroups;
using gpu_types::SynthGroupInfo;
using gpu_types::SynthGroupTable;
static_assert(sizeof(SynthGroupInfo) == 80 && sizeof(SynthGroupTable) == 16 + 4 * 80,
              "SynthGroupTable must match the GLSL std140 block");
static_assert(sizeof(ClassifyGroupsPush) == 48);

namespace {

void checkGroups(std::span<const GroupDescription> groups) {
  if (groups.empty() || groups.size() > kSynthMaxGroups)
    fail("a crowd synthesized in shared passes has 1 to ", kSynthMaxGroups, " groups, got ",
         groups.size());
  for (size_t g = 0; g < groups.size(); ++g) {
    if (!groups[g].pair || !groups[g].cache) fail("crowd group ", g, " has no pair or cache");
    if (g > 0 && groups[g].first <= groups[g - 1].first)
      fail("crowd groups must start in ascending order (group ", g, ")");
  }
}

// Each clip's root position per frame (texel 1 of every row), slow then fast per group.
std::vector<glm::vec4> rootRows(std::span<const GroupDescription> groups,
                                std::vector<uint32_t>& slowBase, std::vector<uint32_t>& fastBase) {
  std::vector<glm::vec4> rows;
  auto append = [&rows](const anim::MotionTexture& clip) {
    const auto base = static_cast<uint32_t>(rows.size());
    for (int f = 0; f < clip.frameCount; ++f) rows.push_back(clip.texel(1, f));
    return base;
  };
  for (const GroupDescription& g : groups) {
    slowBase.push_back(append(g.pair->slow));
    fastBase.push_back(append(g.pair->fast));
  }
  return rows;
}

// Each group's first bucket in the shared request flags and bucket slots, each group's on cache
// lines of its own: root motion's threads flag buckets of different groups at once.
std::vector<uint32_t> bucketBases(std::span<const GroupDescription> groups, uint32_t& total) {
  constexpr uint32_t kLine = 64 / sizeof(uint32_t);
  std::vector<uint32_t> bases;
  total = 0;
  for (const GroupDescription& g : groups) {
    total = (total + kLine - 1) / kLine * kLine;
    bases.push_back(total);
    total += g.cache->bucketCount;
  }
  return bases;
}

SynthGroupTable groupTable(std::span<const GroupDescription> groups,
                           std::span<const uint32_t> slowBase, std::span<const uint32_t> fastBase,
                           std::span<const uint32_t> bucketBase) {
  SynthGroupTable table{};
  table.counts.x = static_cast<uint32_t>(groups.size());
  for (size_t k = 0; k < groups.size(); ++k) {
    const anim::MotionPair& pair = *groups[k].pair;
    SynthGroupInfo& info = table.groups[k];
    info.firstCharacter = groups[k].first;
    info.slowFrames = static_cast<uint32_t>(pair.slow.frameCount);
    info.fastFrames = static_cast<uint32_t>(pair.fast.frameCount);
    info.slowDuration = pair.slow.duration();
    info.fastDuration = pair.fast.duration();
    info.slowRootBase = slowBase[k];
    info.fastRootBase = fastBase[k];
    info.slowCycleTravel = glm::vec4(pair.slow.cycleTravel, 0.0f);
    info.fastCycleTravel = glm::vec4(pair.fast.cycleTravel, 0.0f);
    info.bucketBase = bucketBase[k];
    info.cacheRowCount = groups[k].cache->rowCount;
    info.cacheDataBase = groups[k].cache->dataBase;
  }
  return table;
}

}  // namespace

SynthGroupBuffers makeSynthGroupBuffers(const gpu::Context& context,
                                        std::span<const GroupDescription> groups, bool lod,
                                        bool cached) {
  checkGroups(groups);
  SynthGroupBuffers b;
  b.groupCount = static_cast<uint32_t>(groups.size());
  for (const GroupDescription& g : groups) {
    b.firsts.push_back(g.first);
    b.steerings.push_back(g.steering);
  }
  std::vector<uint32_t> slowBase, fastBase;
  const std::vector<glm::vec4> rows = rootRows(groups, slowBase, fastBase);
  b.rootRows = gpu::makeStorageBuffer<glm::vec4>(context, rows);
  uint32_t buckets = 0;
  const std::vector<uint32_t> bucketBase = bucketBases(groups, buckets);
  if (cached) {
    b.requested = gpu::makeStorageBuffer<uint32_t>(context, std::vector<uint32_t>(buckets, 0u));
    b.bucketSlot = gpu::makeStorageBuffer<int32_t>(context, std::vector<int32_t>(buckets, -1));
  }
  const SynthGroupTable table = groupTable(groups, slowBase, fastBase, bucketBase);
  b.table = gpu::Buffer(context, sizeof(table),
                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        gpu::MemoryUse::DeviceLocal);
  gpu::uploadBytes(context, b.table, {reinterpret_cast<const uint8_t*>(&table), sizeof(table)});
  if (lod)
    b.coverageParts = gpu::Buffer(context, sizeof(CoverageParts) * kSynthMaxGroups,
                                  VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryUse::HostVisible);
  return b;
}

void writeGroupCoverageParts(const SynthGroupBuffers& buffers, uint32_t group,
                             const CoverageParts& parts) {
  if (!buffers.coverageParts || group >= kSynthMaxGroups)
    fail("no coverage parts for group ", group);
  std::memcpy(static_cast<uint8_t*>(buffers.coverageParts.mapped()) + group * sizeof(parts), &parts,
              sizeof(parts));
}

std::vector<std::string> GroupRootMotionJob::validate() const {
  std::vector<std::string> problems;
  if (!groups || !groups->table || !groups->rootRows)
    problems.push_back("input 'groups' (the group table and root rows) is missing");
  if (!crowd || !crowd->placement || !crowd->motion)
    problems.push_back("input/output 'crowd' buffers are missing");
  if (!(dt >= 0.0f)) problems.push_back(concat("dt must be >= 0, got ", dt));
  if (cache && cache->enabled && (!groups || !groups->requested || bucketCount == 0))
    problems.push_back("the cache's lookup needs the groups' shared 'requested' buffer");
  const bool coverage = coverageView || masks;
  if (coverage &&
      (!coverageView || !*coverageView || !masks || !*masks || !groups || !groups->coverageParts))
    problems.push_back("the coverage pass needs 'coverageView', 'masks' and the groups' parts");
  if (coverage && crowd && masks && *masks &&
      masks->size() < VkDeviceSize(crowd->count) * sizeof(CoverageMask))
    problems.push_back(concat("buffer 'masks' holds ", masks->size(), " bytes, ",
                              VkDeviceSize(crowd->count) * sizeof(CoverageMask), " needed"));
  return problems;
}

void GroupRootMotionJob::record(VkCommandBuffer cmd, const SynthPrograms& programs) const {
  gpu::throwIfInvalid("GroupRootMotionJob", validate());
  bool prepared = false;
  for (uint32_t k = 0; k < groups->groupCount; ++k) {
    const uint32_t first = groups->firsts[k];
    const uint32_t end = k + 1 < groups->groupCount ? groups->firsts[k + 1] : crowd->count;
    prepared |= recordRootMotionPrep(cmd, programs, *crowd, first, end - first,
                                     groups->steerings[k], retarget);
  }
  if (prepared) gpu::computeToComputeBarrier(cmd);
  RootMotionPush push{};
  push.characterCount = crowd->count;
  push.dt = dt;
  const bool lookup = cache && cache->enabled;
  if (lookup) {
    push.cacheBucketWidth = cache->bucketWidth;
    push.cacheBucketCount = bucketCount;
  }
  gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kRootMotionBindingPlacement, crowd->placement),
      gpu::storageBinding(gpu_types::kRootMotionBindingMotion, crowd->motion),
      // Without a cache a stand-in the shader never writes (cacheBucketWidth is 0).
      gpu::storageBinding(gpu_types::kRootMotionBindingCacheRequested,
                          lookup ? groups->requested : crowd->motion),
      gpu::uniformBinding(gpu_types::kRootMotionBindingGroups, groups->table),
      gpu::storageBinding(gpu_types::kRootMotionBindingRootRows, groups->rootRows),
      gpu::Binding{},
      gpu::Binding{},
      gpu::Binding{},
  };
  std::span<const gpu::Binding> used(bindings, 5);
  if (coverageView) {
    bindings[5] =
        gpu::uniformBinding(gpu_types::kRootMotionBindingCoverageParts, groups->coverageParts);
    bindings[6] = gpu::storageBinding(gpu_types::kRootMotionBindingMasks, *masks);
    bindings[7] = gpu::uniformBinding(gpu_types::kRootMotionBindingCoverageView, *coverageView, 0,
                                      sizeof(CoverageView));
    used = bindings;
  }
  gpu::dispatch(cmd, coverageView ? programs.rootMotionGroupsCoverage : programs.rootMotionGroups,
                used, push, push.characterCount);
}

std::vector<std::string> GroupCoverageJob::validate() const {
  std::vector<std::string> problems;
  if (!groups || !groups->table || !groups->coverageParts)
    problems.push_back("input 'groups' (the group table and parts) is missing");
  if (!crowd || !crowd->placementTexels || !crowd->motionTexels)
    problems.push_back("input 'crowd' buffers or their texel views are missing");
  if (!coverageView || !*coverageView) problems.push_back("input 'coverageView' is missing");
  if (!masks || !*masks) problems.push_back("input/output 'masks' is missing");
  if (crowd && masks && *masks && masks->size() < VkDeviceSize(crowd->count) * sizeof(CoverageMask))
    problems.push_back(concat("buffer 'masks' holds ", masks->size(), " bytes, ",
                              VkDeviceSize(crowd->count) * sizeof(CoverageMask), " needed"));
  return problems;
}

void GroupCoverageJob::record(VkCommandBuffer cmd, const SynthPrograms& programs) const {
  gpu::throwIfInvalid("GroupCoverageJob", validate());
  const uint32_t count = crowd->count;
  gpu::Binding bindings[] = {
      gpu::uniformBinding(gpu_types::kCoverageGroupsBindingGroups, groups->table),
      gpu::uniformBinding(gpu_types::kCoverageGroupsBindingParts, groups->coverageParts),
      gpu::uniformBinding(gpu_types::kCoverageGroupsBindingView, *coverageView, 0,
                          sizeof(CoverageView)),
      gpu::uniformTexelBinding(gpu_types::kCoverageGroupsBindingPlacement,
                               crowd->placementTexels.get()),
      gpu::uniformTexelBinding(gpu_types::kCoverageGroupsBindingMotion, crowd->motionTexels.get()),
      gpu::storageBinding(gpu_types::kCoverageGroupsBindingMasks, *masks)};
  gpu::dispatch(cmd, programs.coverageGroups, bindings, count, count);
}

std::vector<std::string> GroupInsertJob::validate() const {
  std::vector<std::string> problems;
  if (!groups || !groups->table || !groups->requested || !groups->bucketSlot)
    problems.push_back("input 'groups' (the group table and shared cache buffers) is missing");
  if (groups && caches.size() != groups->groupCount)
    problems.push_back(concat(caches.size(), " caches for ", groups->groupCount, " groups"));
  for (const GpuMotionCache* cache : caches)
    if (!cache || !cache->options.enabled)
      problems.push_back("every group needs its enabled cache");
  return problems;
}

void GroupInsertJob::record(VkCommandBuffer cmd, const SynthPrograms& programs) const {
  gpu::throwIfInvalid("GroupInsertJob", validate());
  static_assert(kSynthMaxGroups == 4, "cache_insert_groups.comp includes one insert per group");
  std::vector<gpu::Binding> bindings = {
      gpu::storageBinding(gpu_types::kCacheInsertGroupsBindingRequested, groups->requested),
      gpu::storageBinding(gpu_types::kCacheInsertGroupsBindingBucketSlot, groups->bucketSlot),
      gpu::uniformBinding(gpu_types::kCacheInsertGroupsBindingGroups, groups->table)};
  for (uint32_t g = 0; g < kSynthMaxGroups; ++g) {
    // Groups past the last get the first one's buffers: the shader never reaches them.
    const GpuMotionCache& c = *caches[g < caches.size() ? g : 0];
    bindings.push_back(
        gpu::storageBinding(gpu_types::kCacheInsertGroupsBindingCounters + g, c.counters));
    bindings.push_back(
        gpu::storageBinding(gpu_types::kCacheInsertGroupsBindingSlotBucket + g, c.slotBucket));
    bindings.push_back(
        gpu::storageBinding(gpu_types::kCacheInsertGroupsBindingFreshSlots + g, c.freshSlots));
    bindings.push_back(
        gpu::storageBinding(gpu_types::kCacheInsertGroupsBindingFillArgs + g, c.fillArgs));
  }
  gpu::dispatch(cmd, programs.cacheInsertGroups, bindings, nullptr, 0, 1);
}

std::vector<std::string> GroupClassifyJob::validate() const {
  std::vector<std::string> problems;
  if (!groups || !groups->table || !groups->bucketSlot)
    problems.push_back("input 'groups' (the group table and shared bucket slots) is missing");
  if (!crowd || !crowd->motionTexels) problems.push_back("input 'crowd' buffers are missing");
  if (!characterLists || !*characterLists || !listCounts || !*listCounts || !poseSource ||
      !*poseSource)
    problems.push_back("outputs 'characterLists', 'listCounts' and 'poseSource' are needed");
  if (crowd && crowd->count >= (1u << 23))
    problems.push_back(
        concat("the shared classify numbers chunks of at most 2^23 characters (a "
               "float division), the crowd has ",
               crowd->count));
  if (chunkSize == 0 || bucketCount == 0 || !(bucketWidth > 0.0f))
    problems.push_back("chunkSize, bucketCount and bucketWidth must be positive");
  if (groups && firstChunk.size() != groups->groupCount)
    problems.push_back(concat("firstChunk has ", firstChunk.size(), " entries for ",
                              groups->groupCount, " groups"));
  return problems;
}

void GroupClassifyJob::record(VkCommandBuffer cmd, const SynthPrograms& programs) const {
  gpu::throwIfInvalid("GroupClassifyJob", validate());
  ClassifyGroupsPush push{};
  push.characterCount = crowd->count;
  push.chunkSize = chunkSize;
  push.bucketCount = bucketCount;
  push.bucketWidth = bucketWidth;
  push.jointCount = jointCount;
  for (size_t g = 0; g < firstChunk.size(); ++g) push.firstChunk[int(g)] = firstChunk[g];
  gpu::Binding bindings[] = {
      gpu::uniformTexelBinding(gpu_types::kCacheClassifyBindingMotion, crowd->motionTexels.get()),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingBucketSlot, groups->bucketSlot),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingCharacterList, *characterLists),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingListCounts, *listCounts),
      gpu::storageBinding(gpu_types::kCacheClassifyBindingPoseSource, *poseSource),
      gpu::uniformBinding(gpu_types::kCacheClassifyBindingGroups, groups->table)};
  gpu::dispatch(cmd, programs.cacheClassifyGroups, bindings, push, push.characterCount);
}

}  // namespace throng::synth
