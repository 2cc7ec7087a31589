#include "render/joint_splat.h"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <initializer_list>
#include <string_view>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"
#include "render/pass_timer.h"
#include "shaders/render_bindings.h"
#include "synth/coverage.h"
#include "synth/gpu_types.h"
#include "synth/synth_jobs.h"

namespace throng::render {

using gpu_types::SplatPush;
static_assert(sizeof(SplatPush) == 40, "SplatPush must match the GLSL push block");
// A subgroup's summed pixel entries stay below the reservation word's sprite bits.
static_assert(128ull * gpu_types::kSplatMaxSpritePixels * gpu_types::kSplatMaxSpritePixels <
                  (1ull << gpu_types::kSplatReserveSpriteShift),
              "the splat's reservation word needs more entry bits");
static_assert(gpu_types::kSplatListRun <= 32,
              "joint_splat_list.comp keeps a run's flags in 32 bits");

std::vector<JointChunk> jointChunks(uint32_t characterCount, uint32_t jointCount,
                                    uint32_t maxStorageBufferRange) {
  std::vector<JointChunk> chunks;
  if (characterCount == 0 || jointCount == 0) return chunks;
  // Bounded by one binding of joint points and by 65535 workgroups of 64 joints per dispatch.
  uint32_t perChunk =
      std::min(maxStorageBufferRange / (jointCount * uint32_t(sizeof(gpu_types::JointPoint))),
               65535u * 64u / jointCount);
  perChunk = std::max(1u, perChunk);
  for (uint32_t first = 0; first < characterCount; first += perChunk)
    chunks.push_back({first, std::min(perChunk, characterCount - first)});
  return chunks;
}

SplatPrograms makeSplatPrograms(const gpu::Context& context, SplatWalk walk,
                                uint32_t spriteCapacity, uint32_t pixelCapacity,
                                float farBodyPixels) {
  const uint32_t capacities[] = {spriteCapacity, pixelCapacity};
  const uint32_t splat[] = {spriteCapacity, pixelCapacity, std::bit_cast<uint32_t>(farBodyPixels)};
  const uint32_t inlinePixels = walk == SplatWalk::PerCharacter ? VK_TRUE : VK_FALSE;
  const uint32_t walked[] = {spriteCapacity, pixelCapacity, std::bit_cast<uint32_t>(farBodyPixels),
                             inlinePixels};
  return {gpu::ComputeProgram(context, "joint_splat_list.comp"),
          gpu::ComputeProgram(context, "joint_splat.comp", splat),
          gpu::ComputeProgram(context, "joint_splat_walk.comp", walked),
          walk == SplatWalk::PerJoint
              ? gpu::ComputeProgram(context, "joint_splat_pixels.comp", capacities)
              : gpu::ComputeProgram{},  // never recorded: not compiled
          walk};
}

SplatLists makeSplatLists(const gpu::Context& context, uint32_t spriteCapacity,
                          uint32_t pixelCapacity) {
  const auto buffer = [&](VkDeviceSize bytes) {
    return gpu::Buffer(context, bytes, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  };
  return {buffer(VkDeviceSize(spriteCapacity) * gpu_types::kSplatSpriteBytes),
          buffer(VkDeviceSize(pixelCapacity) * gpu_types::kSplatEntryBytes), buffer(16)};
}

SplatCapacity splatCapacityFor(SplatWalk walk) {
  return walk == SplatWalk::PerJoint ? SplatCapacity{} : SplatCapacity{1u, 1u};
}

VkDeviceSize listCountsBytes(size_t chunks) {
  return std::max<size_t>(chunks, 1) * gpu_types::kSplatListArgsWords * sizeof(uint32_t);
}

SplatWalk splatWalkFor(const gpu::DeviceInfo& device) {
  const char* chosen = std::getenv("THRONG_SPLAT_WALK");
  if (!chosen || !*chosen) return device.isCpu() ? SplatWalk::PerCharacter : SplatWalk::PerJoint;
  if (std::string_view(chosen) == "character") return SplatWalk::PerCharacter;
  if (std::string_view(chosen) == "joint") return SplatWalk::PerJoint;
  fail("THRONG_SPLAT_WALK is '", chosen, "': expected 'character' or 'joint'");
}

namespace {
// `words` written `times` times in a row at the start of `buffer` (vkCmdUpdateBuffer, at most
// 64 KiB per command).
void updateRepeated(VkCommandBuffer cmd, const gpu::Buffer& buffer,
                    std::initializer_list<uint32_t> words, size_t times) {
  std::vector<uint32_t> data;
  for (size_t i = 0; i < times; ++i) data.insert(data.end(), words);
  for (size_t offset = 0; offset < data.size(); offset += 16384) {
    const size_t count = std::min<size_t>(16384, data.size() - offset);
    vkCmdUpdateBuffer(cmd, buffer.get(), offset * 4, count * 4, data.data() + offset);
  }
}
}  // namespace

std::vector<std::string> SplatJob::validate() const {
  std::vector<std::string> problems;
  if (!joints || !*joints) problems.push_back("input 'joints' buffer is missing");
  if (!frameUniforms || !*frameUniforms)
    problems.push_back("input 'frameUniforms' buffer is missing");
  if (!visibility || !*visibility) problems.push_back("output 'visibility' buffer is missing");
  if (width == 0 || height == 0) problems.push_back("the target size is zero");
  const VkDeviceSize visibilityBytes = VkDeviceSize(width) * height * sizeof(uint64_t);
  if (visibility && *visibility && visibility->size() < visibilityBytes)
    problems.push_back(concat("output 'visibility' holds ", visibility->size(), " bytes, ", width,
                              "x", height, " needs ", visibilityBytes));
  if (initialVisibility && (!*initialVisibility || initialVisibility->size() < visibilityBytes))
    problems.push_back(concat("input 'initialVisibility' holds ",
                              *initialVisibility ? initialVisibility->size() : 0, " bytes, ", width,
                              "x", height, " needs ", visibilityBytes));
  if (characterCount > 0 && jointCount == 0) problems.push_back("jointCount is zero");
  // Walked per joint, a row of workgroups per joint; every device allows 65535 rows
  // (maxComputeWorkGroupCount[1]).
  if (walk == SplatWalk::PerJoint && jointCount > 65535u)
    problems.push_back(
        concat("jointCount ", jointCount, " is above 65535, a walk's rows per joint"));
  if (joints && *joints &&
      joints->size() < VkDeviceSize(characterCount) * jointCount * sizeof(gpu_types::JointPoint))
    problems.push_back("input 'joints' is smaller than characterCount × jointCount joint points");
  if (maxStorageBufferRange == 0) problems.push_back("maxStorageBufferRange is zero");
  if (!masks || !*masks)
    problems.push_back("input 'masks' buffer is missing (bind a small one when flags are 0)");
  if (!lodLevels || !*lodLevels)
    problems.push_back(
        "input 'lodLevels' is missing (bind a placeholder uniform when flags do not use it)");
  else if (lodLevels->size() < sizeof(gpu_types::CoverageParts))
    problems.push_back(concat("input 'lodLevels' holds ", lodLevels->size(),
                              " bytes, CoverageParts needs ", sizeof(gpu_types::CoverageParts)));
  if (!cachedPoses.enabled())
    problems.push_back(
        "inputs 'cachedPoses' are missing (bind small placeholders without a motion cache)");
  const uint32_t cachedFarBodies =
      gpu_types::kDrawCachedPoses | gpu_types::kDrawUseMasks | gpu_types::kDrawLodLevels;
  if (!cachedPoses.farBodyPoses)
    problems.push_back(
        "input 'cachedPoses.farBodyPoses' is missing (a placeholder without far bodies)");
  else if ((flags & cachedFarBodies) == cachedFarBodies &&
           cachedPoses.farBodyPoses->size() < sizeof(gpu_types::FarBodyPose))
    problems.push_back(
        "cached characters' far bodies need 'cachedPoses.farBodyPoses' (synth::makeFarBodyPoses)");
  size_t chunks =
      jointChunks(characterCount, jointCount, std::max(1u, maxStorageBufferRange)).size();
  if (!draws || !*draws)
    problems.push_back("output 'draws' buffer is missing");
  else if (draws->size() < chunks * 16)
    problems.push_back(concat("output 'draws' holds ", draws->size(), " bytes, ", chunks,
                              " chunks need ", chunks * 16));
  if (!nearList || !*nearList)
    problems.push_back("output 'nearList' buffer is missing");
  else if (nearList->size() < VkDeviceSize(characterCount) * jointCount * 4)
    problems.push_back("output 'nearList' is smaller than one index per joint");
  if (spriteCapacity == 0 || pixelCapacity == 0) problems.push_back("a work-list capacity is zero");
  if (spriteCapacity == gpu_types::kSplatNoSprite)
    problems.push_back(
        concat("spriteCapacity ", spriteCapacity, " leaves no value for 'no sprite'"));
  if (!(maxPixels <= float(gpu_types::kSplatMaxSpritePixels)))
    problems.push_back(concat("maxPixels ", maxPixels, " is above ",
                              gpu_types::kSplatMaxSpritePixels,
                              ", the widest joint a splat takes"));
  if (width > 0xFFFFu || height > 0xFFFFu)
    problems.push_back(concat("target ", width, "x", height,
                              " is wider or taller than a pixel entry's 16-bit coordinates"));
  const auto checkList = [&](const gpu::Buffer* list, const char* name, VkDeviceSize bytes) {
    if (!list || !*list)
      problems.push_back(concat("work list '", name, "' is missing"));
    else if (list->size() < bytes)
      problems.push_back(
          concat("work list '", name, "' holds ", list->size(), " bytes, ", bytes, " needed"));
  };
  checkList(sprites, "sprites", VkDeviceSize(spriteCapacity) * gpu_types::kSplatSpriteBytes);
  checkList(pixelOwners, "pixelOwners", VkDeviceSize(pixelCapacity) * gpu_types::kSplatEntryBytes);
  checkList(counters, "counters", 16);
  const VkDeviceSize listBytes = std::max<VkDeviceSize>(4, VkDeviceSize(characterCount) * 4u);
  checkList(onScreenList, "onScreenList", listBytes);
  checkList(walkList, "walkList", listBytes);
  checkList(listCounts, "listCounts", listCountsBytes(chunks));
  return problems;
}

void SplatJob::recordChunk(VkCommandBuffer cmd, const gpu::ComputeProgram& program,
                           const JointChunk& chunk, size_t c, int argsWord) const {
  const VkDeviceSize pixels = VkDeviceSize(width) * height;
  const VkDeviceSize perCharacter = VkDeviceSize(jointCount) * sizeof(gpu_types::JointPoint);
  SplatPush push{jointCount,
                 chunk.firstCharacter,
                 chunk.characterCount * jointCount,
                 maxPixels,
                 static_cast<uint32_t>(c),
                 chunk.firstCharacter * jointCount,
                 flags,
                 0,
                 uint32_t(drawnBones),
                 uint32_t(drawnBones >> 32)};
  gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kRenderBindingJoints, *joints,
                          chunk.firstCharacter * perCharacter, chunk.characterCount * perCharacter),
      gpu::uniformBinding(gpu_types::kRenderBindingFrame, *frameUniforms),
      gpu::storageBinding(gpu_types::kRenderBindingVisibility, *visibility, 0,
                          pixels * sizeof(uint64_t)),
      gpu::storageBinding(gpu_types::kRenderBindingDraws, *draws),
      gpu::storageBinding(gpu_types::kRenderBindingNearList, *nearList),
      gpu::storageBinding(gpu_types::kRenderBindingMasks, *masks),
      gpu::storageBinding(gpu_types::kRenderBindingPlacement, *cachedPoses.placement),
      gpu::storageBinding(gpu_types::kRenderBindingMotion, *cachedPoses.motion),
      gpu::storageBinding(gpu_types::kRenderBindingPoseSource, *cachedPoses.poseSource),
      gpu::storageBinding(gpu_types::kRenderBindingCacheData, *cachedPoses.cacheData),
      gpu::storageBinding(gpu_types::kRenderBindingFarBodyPoses, *cachedPoses.farBodyPoses),
      gpu::storageBinding(gpu_types::kRenderBindingGroups, groups ? *groups : *masks),
      gpu::uniformBinding(gpu_types::kRenderBindingLodLevels, *lodLevels, 0,
                          sizeof(gpu_types::CoverageParts)),
      gpu::storageBinding(gpu_types::kRenderBindingSprites, *sprites),
      gpu::storageBinding(gpu_types::kRenderBindingPixelOwners, *pixelOwners),
      gpu::storageBinding(gpu_types::kRenderBindingSplatCounters, *counters),
      gpu::storageBinding(gpu_types::kRenderBindingWalkList, *walkList),
      gpu::storageBinding(gpu_types::kRenderBindingListCounts, *listCounts),
      gpu::storageBinding(gpu_types::kRenderBindingOnScreenList, *onScreenList),
  };
  // The passes share the bindings; each is given the ones it declares.
  std::vector<gpu::Binding> declared;
  for (const gpu::Binding& b : bindings)
    for (const gpu::ReflectedBinding& r : program.reflection().bindings)
      if (r.binding == b.slot) declared.push_back(b);
  if (argsWord >= 0) {
    const VkDeviceSize args =
        (c * gpu_types::kSplatListArgsWords + uint32_t(argsWord) + 1) * sizeof(uint32_t);
    gpu::dispatchIndirect(cmd, program, declared, &push, sizeof(push), *listCounts, args);
    return;
  }
  const uint32_t runs =
      (chunk.characterCount + gpu_types::kSplatListRun - 1) / gpu_types::kSplatListRun;
  gpu::dispatch(cmd, program, declared, push, runs);
}

void SplatJob::record(VkCommandBuffer cmd, const SplatPrograms& programs) const {
  gpu::throwIfInvalid("SplatJob", validate());
  THRONG_CHECK(programs.walkKind == walk, "SplatJob walks ",
               walk == SplatWalk::PerJoint ? "per joint" : "per character",
               " with programs made for the other walk");
  const VkDeviceSize pixels = VkDeviceSize(width) * height;
  // The previous frame's resolve may still read the buffer, and the initial words were just
  // written by a compute pass: order the reset after both.
  gpu::memoryBarrier(cmd,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT);
  if (timer) timer->mark(cmd, "setup");
  const VkBufferCopy initial{0, 0, pixels * sizeof(uint64_t)};
  if (initialVisibility)
    vkCmdCopyBuffer(cmd, initialVisibility->get(), visibility->get(), 1, &initial);
  else
    vkCmdFillBuffer(cmd, visibility->get(), 0, pixels * sizeof(uint64_t), 0xFFFFFFFFu);
  vkCmdFillBuffer(cmd, counters->get(), 0, 16, 0u);
  if (timer) timer->mark(cmd, "clear");
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  const std::vector<JointChunk> chunks =
      jointChunks(characterCount, jointCount, maxStorageBufferRange);
  // Per chunk: an empty indirect draw {0 vertices, 1 instance}, and two empty lists with
  // dispatches of no workgroups {count 0; x 0, y 1, z 1}; the walk's y is its rows of
  // workgroups, one per joint when it walks per joint (joint_splat_walk.comp).
  const uint32_t walkRows = walk == SplatWalk::PerJoint ? jointCount : 1u;
  updateRepeated(cmd, *draws, {0u, 1u, 0u, 0u}, chunks.size());
  updateRepeated(cmd, *listCounts, {0u, 0u, 1u, 1u, 0u, 0u, walkRows, 1u}, chunks.size());
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  // Per chunk: the characters on screen; their far bodies and the walk list; the listed
  // characters' joints. Each pass after the first is dispatched by the list before it.
  for (size_t c = 0; c < chunks.size(); ++c) recordChunk(cmd, programs.onScreen, chunks[c], c, -1);
  if (timer) timer->mark(cmd, "splat-list");
  const auto listBarrier = [&] {
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT);
  };
  listBarrier();
  for (size_t c = 0; c < chunks.size(); ++c)
    recordChunk(cmd, programs.joints, chunks[c], c, gpu_types::kSplatOnScreenArgs);
  if (timer) timer->mark(cmd, "splat-bodies");
  listBarrier();
  for (size_t c = 0; c < chunks.size(); ++c)
    recordChunk(cmd, programs.walk, chunks[c], c, gpu_types::kSplatWalkArgs);
  if (timer) timer->mark(cmd, "splat-joints");
  if (walk == SplatWalk::PerJoint) recordPixels(cmd, programs);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
}

void SplatJob::recordPixels(VkCommandBuffer cmd, const SplatPrograms& programs) const {
  const VkDeviceSize pixels = VkDeviceSize(width) * height;
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  gpu::Binding pixelBindings[] = {
      gpu::uniformBinding(gpu_types::kRenderBindingFrame, *frameUniforms),
      gpu::storageBinding(gpu_types::kRenderBindingVisibility, *visibility, 0,
                          pixels * sizeof(uint64_t)),
      gpu::storageBinding(gpu_types::kRenderBindingSprites, *sprites),
      gpu::storageBinding(gpu_types::kRenderBindingPixelOwners, *pixelOwners),
      gpu::storageBinding(gpu_types::kRenderBindingSplatCounters, *counters),
  };
  gpu::dispatch(cmd, programs.pixels, pixelBindings, nullptr, 0,
                gpu_types::kSplatPixelGroups * programs.pixels.localSizeX());
  if (timer) timer->mark(cmd, "splat-pixels");
}

}  // namespace throng::render
