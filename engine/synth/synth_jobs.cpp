#include "synth/synth_jobs.h"

#include <bit>

#include "core/error.h"
#include "core/math.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"
#include "shaders/synth_bindings.h"
#include "synth/coverage.h"
#include "synth/gpu_types.h"

namespace throng::synth {

namespace {
// One specialization array serves every synthesis pass: the skeleton's ids run up to the
// texels' (kPoseBoneConstants per joint), and the passes' joint-count ids are the pose pass's.
static_assert(gpu_types::kPoseConstantBones +
                  gpu_types::kPoseBoneConstants * gpu_types::kPoseMaxJoints ==
              gpu_types::kTexelsConstantUniformTexels);
static_assert(gpu_types::kTexelsConstantInUniform + 1 == gpu_types::kPoseConstantCount);
static_assert(gpu_types::kRootMotionConstantJointCount == gpu_types::kPoseConstantJointCount &&
              gpu_types::kPoseCachedConstantJointCount == gpu_types::kPoseConstantJointCount);

// Specialization constants of synth_pose.comp (shaders/synth_bindings.h names the ids): the
// joint count, each joint's parent, the bit masks of joints whose offsets change over frames
// and of fixed bones (synth::fixedBones), whether LOD masks are used, each fixed bone's offset
// xyz and length as float bits, the texels per uniform
// block and whether the texels are read from the uniform buffers. Unused ids hold -1.
std::vector<uint32_t> poseSpecialization(const anim::MotionPair& pair, uint32_t uniformCapacity,
                                         bool useMasks = false) {
  const std::vector<int32_t>& parents = pair.parents;
  if (parents.empty() || parents.size() > gpu_types::kPoseMaxJoints)
    fail("the pose pass supports 1..", gpu_types::kPoseMaxJoints, " joints, the skeleton has ",
         parents.size());
  std::vector<uint32_t> values(gpu_types::kPoseConstantCount, static_cast<uint32_t>(-1));
  const bool inUniform = texelsFitUniform(pair, uniformCapacity);
  values[gpu_types::kTexelsConstantUniformTexels] = inUniform ? uniformCapacity : 1u;
  values[gpu_types::kTexelsConstantInUniform] = inUniform ? 1u : 0u;
  values[gpu_types::kPoseConstantUseMasks] = useMasks ? 1u : 0u;
  values[gpu_types::kPoseConstantJointCount] = static_cast<uint32_t>(parents.size());
  for (size_t j = 0; j < parents.size(); ++j)
    values[gpu_types::kPoseConstantParents + j] = static_cast<uint32_t>(parents[j]);
  values[gpu_types::kPoseConstantAnimatedOffsets] =
      values[gpu_types::kPoseConstantAnimatedOffsets + 1] = 0;
  for (size_t j = 0; j < pair.animatedOffset.size(); ++j)
    if (pair.animatedOffset[j])
      values[gpu_types::kPoseConstantAnimatedOffsets + j / 32] |= 1u << (j % 32);
  values[gpu_types::kPoseConstantFixedBones] = values[gpu_types::kPoseConstantFixedBones + 1] = 0;
  std::vector<bool> fixed = fixedBones(pair);
  for (size_t j = 0; j < fixed.size(); ++j) {
    glm::vec3 offset = pair.slow.offset(0, int(j));
    float bone[gpu_types::kPoseBoneConstants] = {offset.x, offset.y, offset.z, glm::length(offset)};
    for (uint32_t c = 0; c < gpu_types::kPoseBoneConstants; ++c)
      values[gpu_types::kPoseConstantBones + gpu_types::kPoseBoneConstants * j + c] =
          fixed[j] ? std::bit_cast<uint32_t>(bone[c]) : 0u;
    if (fixed[j]) values[gpu_types::kPoseConstantFixedBones + j / 32] |= 1u << (j % 32);
  }
  return values;
}
// Specialization constants of root_motion.comp: the joint count (the texel row width), and
// where the texels are read, as for the pose pass.
std::vector<uint32_t> rootMotionSpecialization(const anim::MotionPair& pair,
                                               uint32_t uniformCapacity) {
  std::vector<uint32_t> values = poseSpecialization(pair, uniformCapacity);
  values[gpu_types::kRootMotionConstantJointCount] = uint32_t(pair.jointCount());
  return values;
}
}  // namespace

SynthPrograms::SynthPrograms(const gpu::Context& context, const anim::MotionPair& pair)
    : rootMotion(context, "root_motion.comp",
                 rootMotionSpecialization(pair, uniformTexelCapacity(context))),
      rootMotionCoverage(context, "root_motion_coverage.comp",
                         rootMotionSpecialization(pair, uniformTexelCapacity(context))),
      rootMotionPrep(context, "root_motion_prep.comp"),
      pose(context, "synth_pose.comp", poseSpecialization(pair, uniformTexelCapacity(context))),
      poseMasked(context, "synth_pose.comp",
                 poseSpecialization(pair, uniformTexelCapacity(context), true)),
      cacheInsert(context, "cache_insert.comp"),
      cacheFill(context, "cache_fill.comp",
                poseSpecialization(pair, uniformTexelCapacity(context))),
      cacheClassify(context, "cache_classify.comp"),
      cacheArgs(context, "cache_dispatch_args.comp"),
      poseCached(context, "synth_pose_cached.comp",
                 poseSpecialization(pair, uniformTexelCapacity(context))),
      coverage(makeCoverageProgram(context)),
      rootMotionGroups(context, "root_motion_groups.comp",
                       rootMotionSpecialization(pair, uniformTexelCapacity(context))),
      rootMotionGroupsCoverage(context, "root_motion_groups_coverage.comp",
                               rootMotionSpecialization(pair, uniformTexelCapacity(context))),
      coverageGroups(context, "coverage_groups.comp"),
      cacheInsertGroups(context, "cache_insert_groups.comp"),
      cacheClassifyGroups(context, "cache_classify_groups.comp"),
      poseParents(pair.parents),
      poseAnimatedOffsets(pair.animatedOffset),
      poseTexelsInUniform(texelsFitUniform(pair, uniformTexelCapacity(context))),
      specialization(poseSpecialization(pair, uniformTexelCapacity(context))) {
  noList = gpu::Buffer(context, 16, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  noParts = gpu::Buffer(context, sizeof(CoverageParts), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                        gpu::MemoryUse::DeviceLocal);
}

gpu::ComputeProgram makeScheduledRootMotionProgram(const gpu::Context& context,
                                                   const anim::MotionPair& pair) {
  return gpu::ComputeProgram(context, "root_motion_scheduled.comp",
                             rootMotionSpecialization(pair, uniformTexelCapacity(context)));
}

bool SynthPrograms::fits(const gpu::Context& context, const anim::MotionPair& pair) const {
  return specialization == poseSpecialization(pair, uniformTexelCapacity(context));
}

std::vector<std::string> CacheJob::validate() const {
  std::vector<std::string> problems;
  if (!motion) problems.push_back("input 'motion' (GPU motion textures) is missing");
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (!cache) problems.push_back("input/output 'cache' is missing");
  if (cache && !cache->options.enabled) problems.push_back("the cache is disabled");
  if (!data || !*data) problems.push_back("output 'data' (the cache entries) is missing");
  if (cache && data && *data &&
      (uint64_t(cache->dataBase) * sizeof(JointPoint) + cache->dataBytes()) > data->size())
    problems.push_back(concat("output 'data' holds ", data->size(), " bytes, the cache needs ",
                              cache->dataBytes(), " from point ", cache->dataBase));
  if (crowd && (firstCharacter > crowd->count ||
                (characterCount && characterCount > crowd->count - firstCharacter)))
    problems.push_back("the group runs past the end of the crowd");
  if (cache && motion && cache->jointCount != motion->jointCount)
    problems.push_back(concat("the cache holds ", cache->jointCount,
                              " joints per pose, the motion pair has ", motion->jointCount));
  if (!parts != !farBodyPoses)
    problems.push_back("inputs 'parts' and 'farBodyPoses' go together (far bodies), or neither");
  if (cache && data && *data && farBodyPoses &&
      farBodyPoses->size() < farBodyPosesBytes(*data, cache->jointCount))
    problems.push_back(concat("output 'farBodyPoses' holds ", farBodyPoses->size(),
                              " bytes, the cache's poses need ",
                              farBodyPosesBytes(*data, cache->jointCount)));
  return problems;
}

namespace {
CachePush cachePush(const CacheJob& job) {
  const uint32_t count =
      job.characterCount ? job.characterCount : job.crowd->count - job.firstCharacter;
  CachePush push{count, job.cache->rowCount, job.cache->capacity, job.cache->options.bucketWidth};
  push.firstCharacter = job.firstCharacter;
  push.dataBase = job.cache->dataBase;
  push.slowFrames = job.motion->slowFrames;
  push.fastFrames = job.motion->fastFrames;
  return push;
}
}  // namespace

void CacheJob::recordInsert(VkCommandBuffer cmd, const SynthPrograms& programs) const {
  gpu::throwIfInvalid("CacheJob", validate());
  const CachePush push = cachePush(*this);
  gpu::Binding insert[] = {
      gpu::storageBinding(gpu_types::kCacheInsertBindingCounters, cache->counters),
      gpu::storageBinding(gpu_types::kCacheInsertBindingRequested, cache->requested),
      gpu::storageBinding(gpu_types::kCacheInsertBindingBucketSlot, cache->bucketSlot),
      gpu::storageBinding(gpu_types::kCacheInsertBindingSlotBucket, cache->slotBucket),
      gpu::storageBinding(gpu_types::kCacheInsertBindingFreshSlots, cache->freshSlots),
      gpu::storageBinding(gpu_types::kCacheInsertBindingFillArgs, cache->fillArgs)};
  gpu::dispatch(cmd, programs.cacheInsert, insert, push, 1);
}

void CacheJob::recordFill(VkCommandBuffer cmd, const SynthPrograms& programs) const {
  gpu::throwIfInvalid("CacheJob", validate());
  if (cache->capacity == 0) return;
  CachePush push = cachePush(*this);
  // Only the entries inserted this frame: an indirect dispatch sized by the insert pass.
  gpu::Binding fill[] = {
      gpu::storageBinding(gpu_types::kTexelsBindingSlow, motion->slowTexels),
      gpu::storageBinding(gpu_types::kTexelsBindingFast, motion->fastTexels),
      gpu::uniformBinding(gpu_types::kTexelsBindingSlowUniform, motion->slowUniformTexels),
      gpu::uniformBinding(gpu_types::kTexelsBindingFastUniform, motion->fastUniformTexels),
      gpu::storageBinding(gpu_types::kCacheFillBindingRadius, motion->jointRadius),
      gpu::uniformBinding(gpu_types::kCacheFillBindingConstantOffsets, motion->constantOffsets),
      gpu::storageBinding(gpu_types::kCacheFillBindingSlotBucket, cache->slotBucket),
      gpu::storageBinding(gpu_types::kCacheFillBindingFreshSlots, cache->freshSlots),
      gpu::storageBinding(gpu_types::kCacheFillBindingCacheData, *data),
      gpu::uniformBinding(gpu_types::kCacheFillBindingParts, parts ? *parts : programs.noParts),
      gpu::storageBinding(gpu_types::kCacheFillBindingFarBodyPoses,
                          farBodyPoses ? *farBodyPoses : programs.noList)};
  push.farBodies = farBodyPoses ? 1u : 0u;
  gpu::dispatchIndirect(cmd, programs.cacheFill, fill, &push, sizeof(push), cache->fillArgs, 0);
}

namespace {
RootMotionPush rootMotionPush(const RootMotionJob& job) {
  const anim::MotionPair* clips = job.clips;
  RootMotionPush push{};
  push.characterCount =
      job.characterCount ? job.characterCount : job.crowd->count - job.firstCharacter;
  push.firstCharacter = job.firstCharacter;
  push.slowFrames = static_cast<uint32_t>(clips->slow.frameCount);
  push.fastFrames = static_cast<uint32_t>(clips->fast.frameCount);
  push.dt = job.dt;
  push.slowDuration = clips->slow.duration();
  push.fastDuration = clips->fast.duration();
  push.slowCycleTravel = glm::vec4(clips->slow.cycleTravel, 0.0f);
  push.fastCycleTravel = glm::vec4(clips->fast.cycleTravel, 0.0f);
  if (job.cache && job.cache->options.enabled) {
    push.cacheBucketWidth = job.cache->options.bucketWidth;
    push.cacheBucketCount = job.cache->bucketCount;
  }
  if (job.updateRate)
    push.reachPerHeight = updateReachPerHeight(job.updateRate->params, job.updateRate->recent);
  return push;
}
}  // namespace

bool recordRootMotionPrep(VkCommandBuffer cmd, const SynthPrograms& programs,
                          const crowd::CrowdBuffers& crowd, uint32_t first, uint32_t count,
                          anim::Steering steering, const anim::SpeedRetarget& retarget) {
  if (count == 0 || (steering == anim::Steering::KeepHeading && retarget.epoch == 0)) return false;
  gpu_types::RootMotionPrepPush push{};
  push.characterCount = count;
  push.firstCharacter = first;
  push.steering = static_cast<uint32_t>(steering);
  push.retargetEpoch = retarget.epoch;
  push.seed = retarget.seed;
  push.minSpeedWeight = retarget.lo;
  push.maxSpeedWeight = retarget.hi;
  push.bucketWidth = retarget.bucketWidth;
  const gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kRootMotionBindingPlacement, crowd.placement),
      gpu::storageBinding(gpu_types::kRootMotionBindingMotion, crowd.motion)};
  gpu::dispatch(cmd, programs.rootMotionPrep, bindings, push, count);
  return true;
}

std::vector<std::string> RootMotionJob::validate() const {
  std::vector<std::string> problems;
  if (!motion) problems.push_back("input 'motion' (GPU motion textures) is missing");
  if (!clips) problems.push_back("input 'clips' (motion pair) is missing");
  if (!crowd) problems.push_back("input/output 'crowd' buffers are missing");
  if (crowd &&
      (!crowd->placement || !crowd->motion || !crowd->placementTexels || !crowd->motionTexels))
    problems.push_back("crowd buffers or their texel views are not allocated (uploadCrowd)");
  if (!(dt >= 0.0f)) problems.push_back(concat("dt must be >= 0, got ", dt));
  if (crowd && (firstCharacter > crowd->count ||
                (characterCount && characterCount > crowd->count - firstCharacter)))
    problems.push_back("the group runs past the end of the crowd");
  if (clips && (clips->slow.duration() <= 0.0f || clips->fast.duration() <= 0.0f))
    problems.push_back("clip durations must be positive");
  if (cache && cache->options.enabled && (!cache->requested || cache->bucketCount == 0))
    problems.push_back("output 'cache' has no requested buckets");
  const bool coverage = coverageView || coverageParts || masks;
  if (coverage &&
      (!coverageView || !*coverageView || !coverageParts || !*coverageParts || !masks || !*masks))
    problems.push_back("the coverage pass needs 'coverageView', 'coverageParts' and 'masks'");
  if (coverage && crowd && masks && *masks &&
      masks->size() < VkDeviceSize(crowd->count) * sizeof(CoverageMask))
    problems.push_back(concat("buffer 'masks' holds ", masks->size(), " bytes, ",
                              VkDeviceSize(crowd->count) * sizeof(CoverageMask), " needed"));
  if (updateRate && !coverage)
    problems.push_back("the update-rate schedule needs the coverage (its heights)");
  if (updateRate && !scheduledProgram) problems.push_back("input 'scheduledProgram' is missing");
  if (updateRate && crowd &&
      updateRate->chunkCount <
          updateChunkCount(characterCount ? characterCount : crowd->count - firstCharacter))
    problems.push_back(concat("the schedule has ", updateRate->chunkCount, " chunks, too few"));
  return problems;
}

void RootMotionJob::record(VkCommandBuffer cmd, const SynthPrograms& programs) const {
  gpu::throwIfInvalid("RootMotionJob", validate());
  if (programs.poseParents.size() != motion->jointCount ||  // the texel row width is baked in
      programs.poseTexelsInUniform != motion->texelsInUniform)
    fail("RootMotionJob: the programs were built for another motion pair (",
         programs.poseParents.size(), " joints, texels in ",
         programs.poseTexelsInUniform ? "uniform" : "storage", " buffers) than this one (",
         motion->jointCount, " joints, ", motion->texelsInUniform ? "uniform" : "storage", ")");
  const RootMotionPush push = rootMotionPush(*this);
  if (recordRootMotionPrep(cmd, programs, *crowd, push.firstCharacter, push.characterCount,
                           steering, retarget))
    gpu::computeToComputeBarrier(cmd);
  const bool lookup = cache && cache->options.enabled;
  gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kTexelsBindingSlow, motion->slowTexels),
      gpu::storageBinding(gpu_types::kTexelsBindingFast, motion->fastTexels),
      gpu::uniformBinding(gpu_types::kTexelsBindingSlowUniform, motion->slowUniformTexels),
      gpu::uniformBinding(gpu_types::kTexelsBindingFastUniform, motion->fastUniformTexels),
      gpu::storageBinding(gpu_types::kRootMotionBindingPlacement, crowd->placement),
      gpu::storageBinding(gpu_types::kRootMotionBindingMotion, crowd->motion),
      // Without a cache a stand-in the shader never writes (cacheBucketWidth is 0).
      gpu::storageBinding(gpu_types::kRootMotionBindingCacheRequested,
                          lookup ? cache->requested : crowd->motion),
  };
  if (!coverageView) {
    gpu::dispatch(cmd, programs.rootMotion, bindings, push, push.characterCount);
    return;
  }
  gpu::Binding withCoverage[std::size(bindings) + 3];
  std::copy(std::begin(bindings), std::end(bindings), withCoverage);
  withCoverage[std::size(bindings)] = gpu::uniformBinding(
      gpu_types::kRootMotionBindingCoverageParts, *coverageParts, 0, sizeof(CoverageParts));
  withCoverage[std::size(bindings) + 1] =
      gpu::storageBinding(gpu_types::kRootMotionBindingMasks, *masks);
  withCoverage[std::size(bindings) + 2] = gpu::uniformBinding(
      gpu_types::kRootMotionBindingCoverageView, *coverageView, 0, sizeof(CoverageView));
  if (!updateRate) {
    gpu::dispatch(cmd, programs.rootMotionCoverage, withCoverage, push, push.characterCount);
    return;
  }
  gpu::Binding scheduled[std::size(withCoverage) + 2];
  std::copy(std::begin(withCoverage), std::end(withCoverage), scheduled);
  scheduled[std::size(withCoverage)] =
      gpu::storageBinding(gpu_types::kRootMotionBindingChunkState, updateRate->chunkState);
  scheduled[std::size(withCoverage) + 1] =
      gpu::storageBinding(gpu_types::kRootMotionBindingChunkList, updateRate->chunkList);
  gpu::dispatchIndirect(cmd, *scheduledProgram, scheduled, &push, sizeof(push),
                        updateRate->dispatchArgs, 0);
}

std::vector<std::string> PoseJob::validate() const {
  std::vector<std::string> problems;
  if (!motion) problems.push_back("input 'motion' (GPU motion textures) is missing");
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (!joints || !*joints) problems.push_back("output 'joints' buffer is missing");
  if (motion && crowd && joints && *joints) {
    if (firstCharacter > crowd->count)
      problems.push_back("firstCharacter is past the end of the crowd");
    uint32_t count =
        characterCount ? characterCount : crowd->count - std::min(firstCharacter, crowd->count);
    if (firstCharacter + count > crowd->count)
      problems.push_back("chunk runs past the end of the crowd");
    if (characterList && (!listCounts || !dispatchArgs))
      problems.push_back("a 'characterList' needs its 'listCounts' and 'dispatchArgs'");
    VkDeviceSize need = VkDeviceSize(count) * motion->jointCount * sizeof(JointPoint);
    if (jointsOffset + need > joints->size())
      problems.push_back(concat("output 'joints' holds ", joints->size(),
                                " bytes, the chunk needs ", need, " at offset ", jointsOffset));
  }
  return problems;
}

void PoseJob::record(VkCommandBuffer cmd, const SynthPrograms& programs) const {
  gpu::throwIfInvalid("PoseJob", validate());
  if (programs.poseParents != motion->parentsHost ||
      programs.poseAnimatedOffsets != motion->animatedOffset ||
      programs.poseTexelsInUniform != motion->texelsInUniform)
    fail("PoseJob: the pose program was specialized for another skeleton (",
         programs.poseParents.size(), " joints) than the motion pair's (",
         motion->parentsHost.size(), " joints)");
  uint32_t count = characterCount ? characterCount : crowd->count - firstCharacter;
  PosePush push{};
  push.characterCount = count;
  push.jointCount = motion->jointCount;
  push.slowFrames = motion->slowFrames;
  push.fastFrames = motion->fastFrames;
  push.firstCharacter = firstCharacter;
  const bool listed = characterList != nullptr;
  push.fromList = listed ? 1u : 0u;
  push.listBase = listBase;
  push.countIndex = countIndex;
  push.flags = masks ? gpu_types::kPoseUseMasks : 0u;
  const gpu::Buffer& maskBuffer = masks ? *masks : programs.noList;
  VkDeviceSize bytes = VkDeviceSize(count) * motion->jointCount * sizeof(JointPoint);
  const gpu::Buffer& list = listed ? *characterList : programs.noList;
  const gpu::Buffer& counts = listed ? *listCounts : programs.noList;
  gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kTexelsBindingSlow, motion->slowTexels),
      gpu::storageBinding(gpu_types::kTexelsBindingFast, motion->fastTexels),
      gpu::uniformBinding(gpu_types::kTexelsBindingSlowUniform, motion->slowUniformTexels),
      gpu::uniformBinding(gpu_types::kTexelsBindingFastUniform, motion->fastUniformTexels),
      gpu::storageBinding(gpu_types::kPoseBindingRadius, motion->jointRadius),
      gpu::storageBinding(gpu_types::kPoseBindingPlacement, crowd->placement),
      gpu::storageBinding(gpu_types::kPoseBindingMotion, crowd->motion),
      gpu::storageBinding(gpu_types::kPoseBindingJoints, *joints, jointsOffset, bytes),
      gpu::uniformBinding(gpu_types::kPoseBindingConstantOffsets, motion->constantOffsets),
      gpu::storageBinding(gpu_types::kPoseBindingCharacterList, list),
      gpu::storageBinding(gpu_types::kPoseBindingListCounts, counts),
      gpu::storageBinding(gpu_types::kPoseBindingMasks, maskBuffer),
  };
  // Both variants declare the masks binding (reflection reads the SPIR-V before specialization);
  // only the masked one reads it.
  const gpu::ComputeProgram& program = masks ? programs.poseMasked : programs.pose;
  std::span<const gpu::Binding> used(bindings);
  if (listed) {
    gpu::dispatchIndirect(cmd, program, used, &push, sizeof(push), *dispatchArgs, argsOffset);
  } else {
    gpu::dispatch(cmd, program, used, push, count);
  }
}

std::vector<std::string> MaterializeCachedJob::validate() const {
  std::vector<std::string> problems;
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (!cache) problems.push_back("input 'cache' is missing");
  if (!cacheData || !*cacheData) problems.push_back("input 'cacheData' buffer is missing");
  if (!poseSource || !*poseSource) problems.push_back("input 'poseSource' buffer is missing");
  if (!joints || !*joints) problems.push_back("output 'joints' buffer is missing");
  if (crowd && firstCharacter + characterCount > crowd->count)
    problems.push_back("chunk runs past the end of the crowd");
  if (cache && joints && *joints &&
      jointsOffset + VkDeviceSize(characterCount) * cache->jointCount * sizeof(JointPoint) >
          joints->size())
    problems.push_back(
        concat("output 'joints' holds ", joints->size(), " bytes, too few for the chunk"));
  return problems;
}

void MaterializeCachedJob::record(VkCommandBuffer cmd, const SynthPrograms& programs) const {
  gpu::throwIfInvalid("MaterializeCachedJob", validate());
  if (characterCount == 0) return;
  PosePush push{};
  push.characterCount = characterCount;
  push.jointCount = cache->jointCount;
  push.firstCharacter = firstCharacter;
  push.flags = masks ? gpu_types::kPoseUseMasks : 0u;
  VkDeviceSize bytes = VkDeviceSize(characterCount) * cache->jointCount * sizeof(JointPoint);
  gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kPoseCachedBindingPlacement, crowd->placement),
      gpu::storageBinding(gpu_types::kPoseCachedBindingMotion, crowd->motion),
      gpu::storageBinding(gpu_types::kPoseCachedBindingJoints, *joints, jointsOffset, bytes),
      gpu::storageBinding(gpu_types::kPoseCachedBindingPoseSource, *poseSource),
      gpu::storageBinding(gpu_types::kPoseCachedBindingCacheData, *cacheData),
      gpu::storageBinding(gpu_types::kPoseCachedBindingMasks, masks ? *masks : programs.noList),
  };
  gpu::dispatch(cmd, programs.poseCached, bindings, push, characterCount);
}

}  // namespace throng::synth
