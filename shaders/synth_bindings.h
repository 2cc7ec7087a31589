// Descriptor binding numbers and specialization-constant ids of the synthesis passes (root
// motion, pose, motion cache, coverage LOD; engine/synth) and of the shaders the tests bind
// directly, named once for the shaders and the C++; included like shared_types.h. The pose
// passes and the cache fill mostly keep a buffer's number, but each pass has its own list: a
// number is only meaningful within one pass.
#ifndef THRONG_SYNTH_BINDINGS_H
#define THRONG_SYNTH_BINDINGS_H

#ifdef __cplusplus
#include <cstdint>
namespace throng::gpu_types {
using uint = uint32_t;
#endif

// motion_texels.glsl, in root_motion.comp, synth_pose.comp and cache_fill.comp: the two clips'
// motion texels, in storage buffers or (kTexelsConstantInUniform) in uniform buffers.
const uint kTexelsBindingSlow = 0u;
const uint kTexelsBindingFast = 1u;
const uint kTexelsBindingSlowUniform = 12u;  // uniform
const uint kTexelsBindingFastUniform = 13u;  // uniform
// Its specialization constants: the texels per uniform block, whether they are read from there.
// Past the pose constants below, so one specialization array serves every pass.
const uint kTexelsConstantUniformTexels = 326u;
const uint kTexelsConstantInUniform = 327u;

// root_motion.comp: each character's phase, speed weight and root (the paper's eq. 10).
const uint kRootMotionBindingPlacement = 2u;  // vec4 per character as two 64-bit words
const uint kRootMotionBindingMotion = 3u;     // vec4 per character as two 64-bit words
const uint kRootMotionBindingCacheRequested = 4u;  // uint per bucket (a placeholder without cache)
// root_motion_coverage.comp also: the group's CoverageParts (uniform), the masks (in/out) and
// the frame's CoverageView (uniform).
const uint kRootMotionBindingCoverageParts = 5u;
const uint kRootMotionBindingMasks = 6u;
const uint kRootMotionBindingCoverageView = 7u;
// root_motion_groups.comp (and _coverage): every group in one dispatch, the group table
// (uniform SynthGroupTable) and the clips' root rows; the coverage variant binds an array of
// kSynthMaxGroups CoverageParts at kRootMotionBindingCoverageParts.
const uint kRootMotionBindingGroups = 8u;
const uint kRootMotionBindingRootRows = 9u;
const uint kRootMotionConstantJointCount = 0u;  // the texel row width
// root_motion_scheduled.comp: the update-rate LOD's chunks (update_rate.h). Each workgroup moves
// the chunk its list entry names by the entry's seconds and raises the chunk's largest
// projected height.
const uint kRootMotionBindingChunkState = 10u;  // uvec2 per chunk: height bits, last step
const uint kRootMotionBindingChunkList = 11u;   // uvec2 per listed chunk: chunk, seconds' bits

// update_schedule.comp: which chunks move this step (update_rate.h).
const uint kUpdateScheduleBindingChunkState = 0u;
const uint kUpdateScheduleBindingChunkList = 1u;
const uint kUpdateScheduleBindingArgs = 2u;  // VkDispatchIndirectCommand: x counts the list

// synth_pose.comp: blend, hierarchy and joint points per character.
const uint kPoseBindingRadius = 2u;
const uint kPoseBindingPlacement = 3u;
const uint kPoseBindingMotion = 4u;
const uint kPoseBindingJoints = 5u;
const uint kPoseBindingConstantOffsets = 6u;  // uniform
const uint kPoseBindingCharacterList = 7u;
const uint kPoseBindingListCounts = 8u;
const uint kPoseBindingMasks = 11u;
// The skeleton's specialization constants (pose_skeleton.glsl, in synth_pose.comp and
// cache_fill.comp; synth_jobs.cpp poseSpecialization fills them). Bit masks over the joints are
// two words, joints 0..31 at the id, 32..63 at the id + 1.
const uint kPoseMaxJoints = 64u;
const uint kPoseConstantJointCount = 0u;
const uint kPoseConstantParents = 1u;          // + j: the parent of joint j (-1: a root)
const uint kPoseConstantAnimatedOffsets = 65u;  // bit mask: offsets that change over frames
const uint kPoseConstantUseMasks = 67u;         // skip joints outside the LOD mask
const uint kPoseConstantFixedBones = 68u;       // bit mask (synth::fixedBones)
// + 4j + c: joint j's fixed bone, c = offset xyz, length (float bits; generated pose_bones.glsl).
const uint kPoseConstantBones = 70u;
const uint kPoseBoneConstants = 4u;
const uint kPoseConstantCount = 328u;  // every id above and the texels' below this

// synth_pose_cached.comp: cached characters' joint points, M · p from the cache.
const uint kPoseCachedBindingPlacement = 3u;
const uint kPoseCachedBindingMotion = 4u;
const uint kPoseCachedBindingJoints = 5u;
const uint kPoseCachedBindingPoseSource = 9u;
const uint kPoseCachedBindingCacheData = 10u;
const uint kPoseCachedBindingMasks = 11u;
const uint kPoseCachedConstantJointCount = 0u;

// cache_insert.comp: FIFO slots for the missing buckets, the fill's indirect dispatch.
const uint kCacheInsertBindingCounters = 1u;
const uint kCacheInsertBindingRequested = 2u;
const uint kCacheInsertBindingBucketSlot = 3u;
const uint kCacheInsertBindingSlotBucket = 4u;
const uint kCacheInsertBindingFreshSlots = 5u;
const uint kCacheInsertBindingFillArgs = 8u;

// cache_insert_groups.comp: every group's insert in one dispatch; the shared request flags and
// bucket slots, the group table, then per group g each buffer at its binding + g.
const uint kCacheInsertGroupsBindingRequested = 1u;
const uint kCacheInsertGroupsBindingBucketSlot = 2u;
const uint kCacheInsertGroupsBindingGroups = 3u;  // uniform SynthGroupTable
const uint kCacheInsertGroupsBindingCounters = 8u;
const uint kCacheInsertGroupsBindingSlotBucket = 12u;
const uint kCacheInsertGroupsBindingFreshSlots = 16u;
const uint kCacheInsertGroupsBindingFillArgs = 20u;

// cache_fill.comp: the poses of the entries inserted this frame (plus the texels above and the
// skeleton's constants).
const uint kCacheFillBindingRadius = 2u;
const uint kCacheFillBindingConstantOffsets = 6u;  // uniform
const uint kCacheFillBindingSlotBucket = 7u;
const uint kCacheFillBindingFreshSlots = 8u;
const uint kCacheFillBindingCacheData = 10u;
const uint kCacheFillBindingParts = 14u;         // uniform CoverageParts (push.farBodies != 0)
const uint kCacheFillBindingFarBodyPoses = 15u;  // FarBodyPose per cached pose

// cache_classify.comp: cached characters' pose source, the others into the pose lists.
const uint kCacheClassifyBindingMotion = 0u;  // uniform texel buffer
const uint kCacheClassifyBindingBucketSlot = 3u;
const uint kCacheClassifyBindingCharacterList = 6u;
const uint kCacheClassifyBindingListCounts = 7u;
const uint kCacheClassifyBindingPoseSource = 9u;

// cache_classify_groups.comp also: the group table; bucketSlot is then every group's, shared.
const uint kCacheClassifyBindingGroups = 10u;  // uniform SynthGroupTable

// cache_classify_scheduled.comp also (the update-rate LOD): the chunks moved this step and the
// dispatch's arguments, whose fourth word says it covers every chunk instead.
const uint kCacheClassifyBindingChunkList = 11u;  // update_schedule.comp's list
const uint kCacheClassifyBindingArgs = 12u;       // ScheduledClassifyArgs

// cache_classify_args.comp: the scheduled classify's dispatch, from the schedule's and the
// cache's counts.
const uint kClassifyArgsBindingFreshSlots = 0u;  // the cache insert's [0]: entries filled now
const uint kClassifyArgsBindingSchedule = 1u;    // update_schedule.comp's dispatch (x: its list)
const uint kClassifyArgsBindingArgs = 2u;        // ScheduledClassifyArgs

// cache_dispatch_args.comp: the list counts as indirect dispatch sizes.
const uint kCacheArgsBindingListCounts = 7u;
const uint kCacheArgsBindingDispatchArgs = 8u;

// coverage.comp: the body parts' screen coverage and each character's LOD mask.
const uint kCoverageBindingParts = 0u;  // uniform
const uint kCoverageBindingPlacement = 1u;  // uniform texel buffer
const uint kCoverageBindingMotion = 2u;     // uniform texel buffer
const uint kCoverageBindingJoints = 3u;
const uint kCoverageBindingMasks = 4u;  // CoverageMask as two 64-bit words
const uint kCoverageBindingAreas = 5u;

// coverage_groups.comp: the frame's coverage over every group (the walls' frame).
const uint kCoverageGroupsBindingGroups = 0u;  // uniform SynthGroupTable
const uint kCoverageGroupsBindingParts = 1u;   // uniform CoverageParts[kSynthMaxGroups]
const uint kCoverageGroupsBindingView = 2u;    // uniform CoverageView
const uint kCoverageGroupsBindingPlacement = 3u;  // uniform texel buffer
const uint kCoverageGroupsBindingMotion = 4u;     // uniform texel buffer
const uint kCoverageGroupsBindingMasks = 5u;

// texel_readback.comp (tests/synth): a motion texture and the parents, copied out.
const uint kTexelReadbackBindingTexture = 0u;  // combined image sampler
const uint kTexelReadbackBindingParents = 1u;
const uint kTexelReadbackBindingTexels = 2u;
const uint kTexelReadbackBindingParentsOut = 3u;

// test_scale.comp and test_texels.comp (tests/gpu): the program and binding checks' shaders.
const uint kTestScaleBindingInput = 0u;
const uint kTestScaleBindingOutput = 1u;
const uint kTestTexelsBindingTexels = 0u;  // uniform texel buffer
const uint kTestTexelsBindingOutput = 1u;

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
