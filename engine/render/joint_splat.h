#pragma once
// The compute path for small joints (a job: named inputs and outputs, validate(), record()).
// A first pass per character (joint_splat.comp) splats far characters a few pixels tall as one
// ellipsoid each (joint_far_body.glsl) and lists the others, whose joints the second pass
// (joint_splat_walk.comp) walks; each joint's ellipsoid is ray-cast over its few screen pixels,
// by the walk itself or one invocation per pixel (joint_splat_pixels.comp), as SplatWalk says.
// The nearest hit per pixel is kept in
// a visibility buffer of (depth << 32 | colour), which the renderer puts into the frame with
// depth. On lavapipe this is an order of magnitude cheaper than sending tens of
// thousands of tiny sprites through the single-threaded vertex pipeline.
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "shaders/render_bindings.h"

namespace throng::render {

class PassTimer;

constexpr uint64_t kEmptyPixel = ~uint64_t(0);

// Characters are processed in chunks whose joint points fit one storage-buffer binding;
// the splat and the draw use the same chunks (chunk c's indirect draw is at draws[c]).
struct JointChunk {
  uint32_t firstCharacter = 0;
  uint32_t characterCount = 0;
};
std::vector<JointChunk> jointChunks(uint32_t characterCount, uint32_t jointCount,
                                    uint32_t maxStorageBufferRange);

// What the renderer needs to place cached characters' joints itself (M · p from the motion
// cache, see shaders/joint_fetch.glsl). Without a motion cache every joint is read from
// the joints buffer; the bindings still exist, so the renderer binds placeholders.
struct CachedPoseInputs {
  const gpu::Buffer* placement = nullptr;   // vec4 per character (crowd)
  const gpu::Buffer* motion = nullptr;      // vec4 per character (crowd): scale in w
  const gpu::Buffer* poseSource = nullptr;  // uint per character (cache classify pass)
  const gpu::Buffer* cacheData = nullptr;   // JointPoint per cache slot, row and joint
  // The far bodies' table (synth::makeFarBodyPoses), filled with the cache when the LOD is on;
  // the renderer binds a placeholder without it (no far bodies are drawn then).
  const gpu::Buffer* farBodyPoses = nullptr;
  bool enabled() const { return placement && motion && poseSource && cacheData; }
};

// How joint_splat_walk.comp's invocations share the listed characters' joints, and where their
// pixels are ray-cast. Per character: each invocation walks its character's joints in turn and
// ray-casts each joint's pixels itself (lavapipe runs 8 lanes side by side, so lanes are
// characters at the same joint, a character's mask, tint and pose are read once, and no pixel
// entry is stored and loaded back one lane at a time). Per joint: a row of workgroups per joint,
// each invocation one joint, whose pixels it reserves as entries for joint_splat_pixels.comp (a
// GPU runs thousands of threads: a thread looping over 25 joints and their pixels would hold its
// warp up, and the pixel pass gives every lane equal work). The same picture either way.
enum class SplatWalk { PerCharacter, PerJoint };
// Per character on a CPU device, per joint on a GPU; THRONG_SPLAT_WALK=character|joint chooses
// (for measuring one against the other).
SplatWalk splatWalkFor(const gpu::DeviceInfo& device);

// joint_splat.comp (far bodies), joint_splat_walk.comp (a sprite per joint) and
// joint_splat_pixels.comp (an invocation per pixel), specialized with the work lists' capacities
// and the far body's height (0: every character by its joints); the walk also by how it walks
// (specialization constant 3: its pixels ray-cast inline when per character).
struct SplatPrograms {
  gpu::ComputeProgram onScreen;  // joint_splat_list.comp: the characters on screen
  gpu::ComputeProgram joints;    // joint_splat.comp: their far bodies and the walk list
  gpu::ComputeProgram walk;      // joint_splat_walk.comp: the listed characters' joints
  gpu::ComputeProgram pixels;    // joint_splat_pixels.comp: the entries of a walk per joint (only)
  SplatWalk walkKind = SplatWalk::PerCharacter;  // what `walk` was specialized for
};
SplatPrograms makeSplatPrograms(const gpu::Context& context, SplatWalk walk,
                                uint32_t spriteCapacity = gpu_types::kSplatSpriteCapacity,
                                uint32_t pixelCapacity = gpu_types::kSplatPixelCapacity,
                                float farBodyPixels = gpu_types::kSplatFarBodyPixels);

// Bytes of the list-counts buffer for `chunks` chunks (render_bindings.h, kSplatListArgsWords).
VkDeviceSize listCountsBytes(size_t chunks);

// The work lists' capacities a walk needs: a walk per joint reserves its pixels in them (the
// defaults of render_bindings.h); a walk per character ray-casts its pixels itself and writes
// none, so its lists hold one sprite and one entry (its bindings still exist): 48 MiB less.
struct SplatCapacity {
  uint32_t sprites = gpu_types::kSplatSpriteCapacity;
  uint32_t pixels = gpu_types::kSplatPixelCapacity;
};
SplatCapacity splatCapacityFor(SplatWalk walk);

// The work lists for those capacities (device-local).
struct SplatLists {
  gpu::Buffer sprites, pixelOwners, counters;
};
SplatLists makeSplatLists(const gpu::Context& context,
                          uint32_t spriteCapacity = gpu_types::kSplatSpriteCapacity,
                          uint32_t pixelCapacity = gpu_types::kSplatPixelCapacity);

struct SplatJob {
  const gpu::Buffer* joints = nullptr;         // input: JointPoint per character per joint
  const gpu::Buffer* frameUniforms = nullptr;  // input: gpu_types::FrameUniforms
  const gpu::Buffer* visibility = nullptr;     // output: width × height uint64, reset first
  const gpu::Buffer* draws = nullptr;  // output: VkDrawIndirectCommand per chunk (too-wide joints)
  const gpu::Buffer* nearList = nullptr;  // output: chunk-local indices of too-wide joints
  uint32_t width = 0, height = 0;
  uint32_t characterCount = 0;
  uint32_t jointCount = 0;             // per character
  float maxPixels = 16.0f;             // wider sprites are left to the graphics pipeline
  uint32_t maxStorageBufferRange = 0;  // chunk size of the joints binding
  const gpu::Buffer* masks = nullptr;  // input: CoverageMask per character (LOD), see flags
  uint32_t flags = 0;            // kDrawUseMasks, kDrawTintLevel, kDrawCachedPoses, kDrawGroupTint
  CachedPoseInputs cachedPoses;  // inputs: all four bound (placeholders when unused)
  const gpu::Buffer* groups =
      nullptr;  // input: group per character (kDrawGroupTint; a placeholder otherwise)
  uint64_t drawnBones = ~uint64_t(0);  // bit j: joint j's bone is drawn (placements' are not)
  const gpu::Buffer* lodLevels =
      nullptr;  // input: uniform CoverageParts (kDrawLodLevels; a placeholder otherwise)
  PassTimer* timer = nullptr;  // optional: marks the clear and the splat
  // The pixel pass's work lists (render_bindings.h), sized for the capacities both programs
  // were specialized with (makeSplatPrograms).
  const gpu::Buffer* sprites = nullptr;      // spriteCapacity × kSplatSpriteBytes
  const gpu::Buffer* pixelOwners = nullptr;  // pixelCapacity 64-bit entries
  const gpu::Buffer* counters = nullptr;     // 16 bytes, cleared by record()
  // The characters on screen and the characters whose joints are walked (the rest of those on
  // screen are far bodies): a uint per character each, and per chunk both lists' lengths and
  // indirect dispatches (listCountsBytes; reset by record(); the buffer needs
  // VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT).
  const gpu::Buffer* onScreenList = nullptr;
  const gpu::Buffer* walkList = nullptr;
  const gpu::Buffer* listCounts = nullptr;
  uint32_t spriteCapacity = gpu_types::kSplatSpriteCapacity;
  uint32_t pixelCapacity = gpu_types::kSplatPixelCapacity;
  // The same picture either way; the programs must have been made for it (makeSplatPrograms).
  SplatWalk walk = SplatWalk::PerCharacter;
  // Optional input: width × height uint64 the visibility buffer starts from (the ground's words,
  // so the splat's atomicMin keeps the nearer of the ground and each hit); null: kEmptyPixel.
  const gpu::Buffer* initialVisibility = nullptr;

  std::vector<std::string> validate() const;
  // Resets the visibility buffer, lists the characters on screen and splats them (chunked);
  // leaves barriers for the fragment resolve and the near joints' indirect draw (the compute
  // resolve, CrowdRenderer::resolvePlanes, orders itself after every compute write).
  void record(VkCommandBuffer cmd, const SplatPrograms& programs) const;

 private:
  // One of the passes over a chunk: the list of characters on screen (argsWord < 0; one
  // invocation per kSplatListRun characters), or a pass dispatched indirectly by the chunk's list
  // at argsWord (kSplatOnScreenArgs, kSplatWalkArgs).
  void recordChunk(VkCommandBuffer cmd, const gpu::ComputeProgram& program, const JointChunk& chunk,
                   size_t c, int argsWord) const;
  // The pixel pass over the entries a walk per joint reserved.
  void recordPixels(VkCommandBuffer cmd, const SplatPrograms& programs) const;
};

}  // namespace throng::render
