// SplatJob: validity, then the GPU pass against its CPU twin on a real crowd.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <optional>
#include <string>

#include "anim/default_clips.h"
#include "core/error.h"
#include "crowd/scenario.h"
#include "gpu/commands.h"
#include "gpu/program.h"
#include "gpu_fixture.h"
#include "render/crowd_renderer.h"
#include "render/joint_far_body_cpu.h"
#include "render/joint_lod_cpu.h"
#include "render/joint_splat.h"
#include "render/joint_splat_cpu.h"
#include "synth/coverage.h"
#include "synth/cpu_synth.h"

using namespace throng;

TEST_CASE("SplatJob: validity") {
  render::SplatJob job;
  auto problems = job.validate();
  std::string all;
  for (auto& p : problems) all += p + "\n";
  CHECK(all.find("'joints'") != std::string::npos);
  CHECK(all.find("'frameUniforms'") != std::string::npos);
  CHECK(all.find("'visibility'") != std::string::npos);
  CHECK(all.find("'draws'") != std::string::npos);
  CHECK(all.find("'nearList'") != std::string::npos);
  CHECK(all.find("'lodLevels'") != std::string::npos);
  CHECK(all.find("'walkList'") != std::string::npos);
  CHECK(all.find("target size is zero") != std::string::npos);
  // Walked per joint, a dispatch has a row of workgroups per joint: at most 65535 of them.
  job.characterCount = 1;
  job.jointCount = 70000;
  const auto problemsOf = [&] {
    std::string text;
    for (auto& p : job.validate()) text += p + "\n";
    return text;
  };
  CHECK(problemsOf().find("rows per joint") == std::string::npos);
  job.walk = render::SplatWalk::PerJoint;
  CHECK(problemsOf().find("jointCount 70000 is above 65535, a walk's rows per joint") !=
        std::string::npos);
}

namespace {
// Sets an environment variable for a scope and restores it after, whatever happens.
class ScopedEnv {
 public:
  explicit ScopedEnv(const char* name) : name_(name) {
    const char* value = std::getenv(name);
    if (value) saved_ = value;
  }
  ~ScopedEnv() {
    if (saved_)
      setenv(name_, saved_->c_str(), 1);
    else
      unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;
  void set(const char* value) const { setenv(name_, value, 1); }
  void unset() const { unsetenv(name_); }

 private:
  const char* name_;
  std::optional<std::string> saved_;
};
}  // namespace

TEST_CASE("SplatJob: a walk per character needs work lists of one sprite and one entry") {
  const render::SplatCapacity perJoint = render::splatCapacityFor(render::SplatWalk::PerJoint);
  CHECK(perJoint.sprites == gpu_types::kSplatSpriteCapacity);
  CHECK(perJoint.pixels == gpu_types::kSplatPixelCapacity);
  const render::SplatCapacity perCharacter =
      render::splatCapacityFor(render::SplatWalk::PerCharacter);
  CHECK((perCharacter.sprites == 1u && perCharacter.pixels == 1u));
}

TEST_CASE("SplatJob: the walk by the device's type, or as THRONG_SPLAT_WALK says") {
  const ScopedEnv walkEnv("THRONG_SPLAT_WALK");
  gpu::DeviceInfo cpu, gpuDevice;
  cpu.type = VK_PHYSICAL_DEVICE_TYPE_CPU;
  gpuDevice.type = VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  walkEnv.unset();
  CHECK(render::splatWalkFor(cpu) == render::SplatWalk::PerCharacter);
  CHECK(render::splatWalkFor(gpuDevice) == render::SplatWalk::PerJoint);
  walkEnv.set("joint");
  CHECK(render::splatWalkFor(cpu) == render::SplatWalk::PerJoint);
  walkEnv.set("character");
  CHECK(render::splatWalkFor(gpuDevice) == render::SplatWalk::PerCharacter);
  walkEnv.set("joints");
  CHECK_THROWS_WITH_AS(render::splatWalkFor(cpu),
                       doctest::Contains("expected 'character' or 'joint'"), throng::Error);
}

TEST_CASE("SplatJob: chunks cover the crowd exactly") {
  auto chunks = render::jointChunks(100000, 25, 128u << 20);
  uint32_t next = 0;
  for (auto& c : chunks) {
    CHECK(c.firstCharacter == next);
    CHECK(c.characterCount * 25u * sizeof(gpu_types::JointPoint) <= (128u << 20));
    next += c.characterCount;
  }
  CHECK(next == 100000);
  CHECK(render::jointChunks(0, 25, 1 << 20).empty());
}

namespace {

const gpu_types::CoverageParts kNoLevels{};

// One splat to check: a crowd's joint points (characters × joints) seen by a camera.
struct SplatCase {
  std::span<const synth::JointPoint> points;
  std::span<const int32_t> parents;  // the skeleton's, joints of them
  uint32_t joints = 0;
  render::Camera camera;
  uint64_t bones = ~uint64_t(0);
  std::span<const synth::CoverageMask> masks;  // empty: every joint, no LOD
  const gpu_types::CoverageParts* levels = nullptr;
  uint32_t spriteCapacity = gpu_types::kSplatSpriteCapacity;
  uint32_t pixelCapacity = gpu_types::kSplatPixelCapacity;
  float farBodyPixels = gpu_types::kSplatFarBodyPixels;
  float maxPixels = 12.0f;
  uint32_t width = 320, height = 180;
  uint32_t chunkCharacters = 0;  // 0: chunks as the device's binding range makes them
  size_t characters() const { return points.size() / joints; }
};

// What one GPU splat left.
struct GpuSplat {
  std::vector<uint64_t> visibility;
  std::vector<uint32_t> nearJoints;  // listed for the graphics pipeline: crowd-wide, sorted
  std::vector<uint32_t> counters;    // sprites and sprite pixels reserved
  std::vector<uint32_t> listCounts;  // per chunk (render_bindings.h, kSplatListArgsWords)
  std::vector<uint32_t> onScreenEntries;
};

// A case's buffers, programs and job, splatted once per walk.
class GpuSplatRun {
 public:
  explicit GpuSplatRun(const SplatCase& c)
      : c_(c),
        ctx_(test::gpuContext()),
        bindingRange_(c.chunkCharacters > 0 ? c.chunkCharacters * c.joints * 48u
                                            : ctx_.info().maxStorageBufferRange),
        chunks_(render::jointChunks(uint32_t(c.characters()), c.joints, bindingRange_)),
        frame_(frameFor(c)),
        perCharacter_(render::makeSplatPrograms(ctx_, render::SplatWalk::PerCharacter,
                                                c.spriteCapacity, c.pixelCapacity,
                                                c.farBodyPixels)),
        perJoint_(render::makeSplatPrograms(ctx_, render::SplatWalk::PerJoint, c.spriteCapacity,
                                            c.pixelCapacity, c.farBodyPixels)),
        lists_(render::makeSplatLists(ctx_, c.spriteCapacity, c.pixelCapacity)) {
    makeBuffers();
    makeJob();
  }
  GpuSplatRun(const GpuSplatRun&) = delete;  // the job points into the buffers
  GpuSplatRun& operator=(const GpuSplatRun&) = delete;

  const gpu_types::FrameUniforms& frame() const { return frame_; }

  // Records the job walked one way with the programs made for the other (refused).
  void recordWithOtherPrograms(render::SplatWalk walk) {
    job_.walk = walk;
    const render::SplatPrograms& other =
        walk == render::SplatWalk::PerJoint ? perCharacter_ : perJoint_;
    gpu::submitAndWait(ctx_, [&](VkCommandBuffer cmd) { job_.record(cmd, other); });
  }
  const std::vector<render::JointChunk>& chunks() const { return chunks_; }

  GpuSplat splat(render::SplatWalk walk) {
    job_.walk = walk;
    const render::SplatPrograms& programs =
        walk == render::SplatWalk::PerJoint ? perJoint_ : perCharacter_;
    gpu::submitAndWait(ctx_, [&](VkCommandBuffer cmd) { job_.record(cmd, programs); });
    GpuSplat g;
    g.visibility = gpu::readback<uint64_t>(ctx_, visibility_, size_t(c_.width) * c_.height);
    // Each chunk's list of joints left to the graphics pipeline, from its first joint.
    const auto drawCommands = gpu::readback<uint32_t>(ctx_, draws_, chunks_.size() * 4);
    const auto nearEntries = gpu::readback<uint32_t>(ctx_, nearList_, c_.points.size());
    for (size_t k = 0; k < chunks_.size(); ++k) {
      const uint32_t first = chunks_[k].firstCharacter * c_.joints;
      for (uint32_t n = 0; n < drawCommands[4 * k]; ++n)
        g.nearJoints.push_back(first + nearEntries[first + n]);
    }
    std::sort(g.nearJoints.begin(), g.nearJoints.end());
    g.counters = gpu::readback<uint32_t>(ctx_, lists_.counters, 2);
    g.listCounts =
        gpu::readback<uint32_t>(ctx_, listCounts_, chunks_.size() * gpu_types::kSplatListArgsWords);
    g.onScreenEntries = gpu::readback<uint32_t>(ctx_, onScreenList_, c_.characters());
    return g;
  }

 private:
  static gpu_types::FrameUniforms frameFor(const SplatCase& c) {
    render::DrawParams params;
    params.camera = c.camera;
    params.width = c.width;
    params.height = c.height;
    params.jointCount = c.joints;
    params.jointParents = c.parents;
    return render::makeFrameUniforms(params);
  }

  gpu::Buffer deviceBuffer(VkDeviceSize bytes, VkBufferUsageFlags extra = 0) {
    return gpu::Buffer(ctx_, std::max<VkDeviceSize>(16, bytes), gpu::kStorageUsage | extra,
                       gpu::MemoryUse::DeviceLocal);
  }

  void makeBuffers() {
    joints_ = gpu::makeStorageBuffer<synth::JointPoint>(ctx_, c_.points);
    uniforms_ = gpu::Buffer(ctx_, sizeof(frame_), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                            gpu::MemoryUse::HostVisible);
    std::memcpy(uniforms_.mapped(), &frame_, sizeof(frame_));
    visibility_ = deviceBuffer(VkDeviceSize(c_.width) * c_.height * 8);
    draws_ = deviceBuffer(chunks_.size() * 16, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
    nearList_ = deviceBuffer(VkDeviceSize(c_.points.size()) * 4);
    // Bound where the flags leave a binding unread: a buffer no pass writes, so that chunks'
    // passes do not seem to read what earlier ones wrote.
    unread_ = deviceBuffer(16);
    // The LOD levels' uniform (a placeholder the flags leave unread without LOD).
    levels_ = gpu::Buffer(ctx_, sizeof(gpu_types::CoverageParts),
                          VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryUse::HostVisible);
    std::memcpy(levels_.mapped(), c_.levels ? c_.levels : &kNoLevels,
                sizeof(gpu_types::CoverageParts));
    if (!c_.masks.empty()) masks_ = gpu::makeStorageBuffer<synth::CoverageMask>(ctx_, c_.masks);
    onScreenList_ = deviceBuffer(c_.characters() * 4);
    walkList_ = deviceBuffer(c_.characters() * 4);
    listCounts_ =
        deviceBuffer(render::listCountsBytes(chunks_.size()), VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
  }

  void makeJob() {
    job_ = render::SplatJob{&joints_,
                            &uniforms_,
                            &visibility_,
                            &draws_,
                            &nearList_,
                            c_.width,
                            c_.height,
                            uint32_t(c_.characters()),
                            c_.joints,
                            c_.maxPixels,
                            bindingRange_,
                            &unread_,
                            0,
                            {&unread_, &unread_, &unread_, &unread_, &unread_}};  // no cache
    if (!c_.masks.empty()) {
      job_.masks = &masks_;
      job_.flags = gpu_types::kDrawUseMasks | (c_.levels ? gpu_types::kDrawLodLevels : 0u);
    }
    job_.lodLevels = &levels_;
    job_.drawnBones = c_.bones;
    job_.sprites = &lists_.sprites;
    job_.pixelOwners = &lists_.pixelOwners;
    job_.counters = &lists_.counters;
    job_.onScreenList = &onScreenList_;
    job_.walkList = &walkList_;
    job_.listCounts = &listCounts_;
    job_.spriteCapacity = c_.spriteCapacity;
    job_.pixelCapacity = c_.pixelCapacity;
    REQUIRE(job_.validate().empty());
  }

  const SplatCase& c_;
  gpu::Context& ctx_;
  uint32_t bindingRange_;
  std::vector<render::JointChunk> chunks_;
  gpu_types::FrameUniforms frame_;
  render::SplatPrograms perCharacter_, perJoint_;
  render::SplatLists lists_;
  gpu::Buffer joints_, uniforms_, visibility_, draws_, nearList_, unread_, levels_, masks_;
  gpu::Buffer onScreenList_, walkList_, listCounts_;
  render::SplatJob job_;
};

// The far bodies the twin splats (test_far_body.cpp bounds how they look). splatBody keeps the
// hits of boxes up to 64 pixels as bits and asks larger ones again (counted here by the boxes'
// extents, near enough to their pixel counts).
void checkFarBodies(const SplatCase& c, const render::SplatInputsCpu& drawn,
                    const gpu_types::FrameUniforms& frame) {
  size_t largeBoxes = 0;
  for (const render::FarBodyCpu& b : drawn.bodies) {
    const render::JointSpriteCpu s = render::jointSpriteCpu(b.body, frame);
    largeBoxes += (s.hi.x - s.lo.x + 1.0f) * (s.hi.y - s.lo.y + 1.0f) > 64.0f;
  }
  MESSAGE(drawn.bodies.size(), " characters drawn as their far body, ", largeBoxes,
          " with boxes over 64 pixels");
  CHECK(drawn.bodies.size() > 20);
  if (c.farBodyPixels > 24.0f) CHECK(largeBoxes > 5);
}

// Pixels of two visibility buffers: where two ellipsoids meet at nearly the same depth, float
// rounding may pick the other one (differentWinner); the rest must match in depth and colour.
struct VisibilityDiff {
  size_t covered = 0, coverageMismatch = 0, colourMismatch = 0, differentWinner = 0;
  float worstDepth = 0.0f;
};

VisibilityDiff compareVisibility(const std::vector<uint64_t>& gpu,
                                 const std::vector<uint64_t>& cpu) {
  VisibilityDiff d;
  for (size_t i = 0; i < gpu.size(); ++i) {
    const uint64_t g = gpu[i], c = cpu[i];
    const bool gHit = g != render::kEmptyPixel, cHit = c != render::kEmptyPixel;
    d.covered += cHit;
    if (gHit != cHit) {
      ++d.coverageMismatch;
      continue;
    }
    if (!gHit) continue;
    float gd, cd;
    const uint32_t gBits = uint32_t(g >> 32), cBits = uint32_t(c >> 32);
    std::memcpy(&gd, &gBits, 4);
    std::memcpy(&cd, &cBits, 4);
    if (std::abs(gd - cd) > 2e-6f) {  // NDC depth: 1e-6 is millimetres at 20 m
      ++d.differentWinner;
      continue;
    }
    d.worstDepth = std::max(d.worstDepth, std::abs(gd - cd));
    for (int k = 0; k < 3; ++k) {
      const int gc = int((g >> (8 * k)) & 0xFF), cc = int((c >> (8 * k)) & 0xFF);
      if (std::abs(gc - cc) > 2) ++d.colourMismatch;
    }
  }
  return d;
}

// The GPU's visibility buffer and near joints against the twin's. Walked per joint, joints the
// work lists cannot hold are listed for the graphics pipeline like the too-wide ones: the twin
// splats every joint but those. Walked per character, the walk ray-casts every joint's pixels
// itself and reserves nothing. Returns whether the work lists were full.
bool checkVisibility(const SplatCase& c, const GpuSplat& g, const render::SplatInputsCpu& drawn,
                     const gpu_types::FrameUniforms& frame, render::SplatWalk walk) {
  MESSAGE("work lists: ", g.counters[0], " sprites (capacity ", c.spriteCapacity, "), ",
          g.counters[1], " sprite pixels (capacity ", c.pixelCapacity, ")");
  if (walk == render::SplatWalk::PerJoint)
    CHECK(g.counters[0] > 0);
  else
    CHECK(g.counters == std::vector<uint32_t>{0u, 0u});
  render::SplatCpuResult cpu =
      render::splatJointsCpu(drawn.joints, frame, c.joints, c.maxPixels, c.width, c.height);
  const std::vector<uint32_t> wide = cpu.nearJoints;
  std::vector<uint32_t> overflowed;
  std::set_difference(g.nearJoints.begin(), g.nearJoints.end(), wide.begin(), wide.end(),
                      std::back_inserter(overflowed));
  const bool full = g.counters[0] > c.spriteCapacity || g.counters[1] > c.pixelCapacity;
  MESSAGE(overflowed.size(), " joints listed because the work lists were full");
  CHECK(full == !overflowed.empty());
  CHECK(std::includes(g.nearJoints.begin(), g.nearJoints.end(), wide.begin(), wide.end()));
  if (!overflowed.empty()) {
    std::vector<synth::JointMatrix> splatted = drawn.joints;
    for (uint32_t j : overflowed) splatted[j] = synth::JointMatrix{};  // no ellipsoid: not drawn
    cpu = render::splatJointsCpu(splatted, frame, c.joints, c.maxPixels, c.width, c.height);
  }
  render::splatFarBodiesCpu(drawn.bodies, frame, c.width, c.height, cpu.visibility);
  const VisibilityDiff d = compareVisibility(g.visibility, cpu.visibility);
  MESSAGE("splat: ", d.covered, " pixels covered, ", d.coverageMismatch, " coverage mismatches, ",
          d.colourMismatch, " colour mismatches, ", d.differentWinner,
          " pixels won by another joint, worst depth diff ", d.worstDepth, "; near joints GPU ",
          g.nearJoints.size(), " CPU ", wide.size(), " + ", overflowed.size(),
          " past the work lists");
  // Silhouette pixels may flip, and a ray grazing an ellipsoid gets a normal that swings with
  // the last bit of the hit (these joints are a pixel or two across, so many rays graze). How
  // many depends on the device's rounding: lavapipe 6 flips and 47 channels (0.26%) here, an
  // NVIDIA H100 (fused multiply-adds, approximate square roots) 29 and 238 (1.3%). With lists
  // too small only the sprites that fit are splatted, and which fit depends on the order in which
  // the device runs the walk (walked per character and per joint: lavapipe 786 and 1,228 pixels,
  // an H100 1,215 and 350).
  CHECK(d.covered > (full ? 200u : 500u));
  CHECK(d.coverageMismatch <= d.covered / 100);
  CHECK(d.colourMismatch <= 3 * d.covered / 50);  // ≤ 2% of channels off by more than 2 levels
  CHECK(d.differentWinner <= d.covered / 50);
  CHECK(wide.size() > 0);
  return full;
}

// The on-screen list holds exactly the characters whose mask is not empty (all of them without
// masks), each once, and each chunk's bodies pass is dispatched with a workgroup per
// kSplatBodyGroupSize of them. The walk list holds the characters on screen that are not far
// bodies, and each chunk's walk has a workgroup per kSplatWalkGroupSize of them, in a row per
// joint when it walks per joint. Entries are chunk-local, from the chunk's first character.
void checkLists(const SplatCase& c, const GpuSplat& g,
                const std::vector<render::JointChunk>& chunks, const render::SplatInputsCpu& drawn,
                render::SplatWalk walk) {
  std::vector<uint32_t> twinOnScreen, gpuOnScreen;
  for (uint32_t i = 0; i < c.characters(); ++i)
    if (c.masks.empty() || (c.masks[i].lo | c.masks[i].hi) != 0u) twinOnScreen.push_back(i);
  size_t walked = 0;
  const uint32_t walkRows = walk == render::SplatWalk::PerJoint ? c.joints : 1u;
  for (size_t k = 0; k < chunks.size(); ++k) {
    const uint32_t* listed = g.listCounts.data() + k * gpu_types::kSplatListArgsWords;
    const uint32_t* walkArgs = listed + gpu_types::kSplatWalkArgs;
    REQUIRE(listed[0] <= chunks[k].characterCount);
    for (uint32_t n = 0; n < listed[0]; ++n)
      gpuOnScreen.push_back(chunks[k].firstCharacter +
                            g.onScreenEntries[chunks[k].firstCharacter + n]);
    const uint32_t bodyGroup = gpu_types::kSplatBodyGroupSize;
    const uint32_t walkGroup = gpu_types::kSplatWalkGroupSize;
    CHECK(listed[1] == (listed[0] + bodyGroup - 1) / bodyGroup);
    CHECK(walkArgs[1] == (walkArgs[0] + walkGroup - 1) / walkGroup);
    CHECK((listed[2] == 1u && listed[3] == 1u && walkArgs[2] == walkRows && walkArgs[3] == 1u));
    walked += walkArgs[0];
  }
  std::sort(gpuOnScreen.begin(), gpuOnScreen.end());
  MESSAGE("on-screen list: ", gpuOnScreen.size(), " of ", c.characters(),
          " characters (twin: ", twinOnScreen.size(), ") in ", chunks.size(), " chunks");
  CHECK(gpuOnScreen == twinOnScreen);
  const size_t walkers = twinOnScreen.size() - drawn.bodies.size();
  MESSAGE("walk list: ", walked, " characters (twin: ", walkers, ")");
  if (c.levels)  // a body on the height threshold may round the other way on the GPU
    CHECK(std::abs(double(walked) - double(walkers)) <= 0.01 * double(walkers) + 1.0);
  else
    CHECK(walked == walkers);
}

// Splats the case on the GPU, walked per character and per joint (render::SplatWalk), and with
// the CPU twins (splatInputsCpu, splatJointsCpu): each walk against the twin, and the walks
// against each other.
void checkSplatTwin(const SplatCase& c) {
  GpuSplatRun run(c);
  const render::SplatInputsCpu drawn = render::splatInputsCpu(
      c.points, c.parents, c.bones, c.masks, c.levels, run.frame(), c.maxPixels, c.farBodyPixels);
  if (c.levels) checkFarBodies(c, drawn, run.frame());
  const GpuSplat perCharacter = run.splat(render::SplatWalk::PerCharacter);
  const GpuSplat perJoint = run.splat(render::SplatWalk::PerJoint);
  bool full = false;
  for (render::SplatWalk walk : {render::SplatWalk::PerCharacter, render::SplatWalk::PerJoint}) {
    CAPTURE(walk == render::SplatWalk::PerJoint);
    const GpuSplat& g = walk == render::SplatWalk::PerJoint ? perJoint : perCharacter;
    const bool listsFull = checkVisibility(c, g, drawn, run.frame(), walk);
    if (walk == render::SplatWalk::PerJoint) full = listsFull;
    checkLists(c, g, run.chunks(), drawn, walk);
  }
  // Either walk ray-casts the same pixels of the same sprites, only in another order (and per
  // joint through the work lists); with room for every joint each pixel keeps the same nearest
  // hit, bit for bit.
  if (!full) CHECK(perJoint.visibility == perCharacter.visibility);
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

}  // namespace

TEST_CASE("SplatJob: GPU visibility buffer matches the CPU twin") {
  gpu::Context& ctx = test::gpuContext();
  if (!ctx.info().int64Atomics) {
    MESSAGE("SKIPPED: device lacks 64-bit buffer atomics");
    return;
  }
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  crowd::ScenarioOptions options;
  options.characters = 400;
  options.seed = 3;
  crowd::Crowd crowd = crowd::makeScenario(options);
  const uint32_t joints = static_cast<uint32_t>(pair.jointCount());
  std::vector<synth::JointPoint> points(crowd.size() * joints);
  synth::poseCrowdCpu(pair, crowd, points, 2);
  SplatCase base;
  base.points = points;
  base.parents = pair.parents;
  base.joints = joints;
  base.camera = render::cameraPreset("street", crowd::scenarioExtent(options));
  SUBCASE("every joint") {
    checkSplatTwin(base);
  }
  SUBCASE("a walk recorded with programs made for the other walk is refused") {
    GpuSplatRun run(base);
    for (render::SplatWalk walk : {render::SplatWalk::PerCharacter, render::SplatWalk::PerJoint})
      CHECK_THROWS_WITH_AS(run.recordWithOtherPrograms(walk),
                           doctest::Contains("with programs made for the other walk"),
                           throng::Error);
  }
  SUBCASE("work lists too small: the joints past them are left to the graphics pipeline") {
    // 300 sprites fit and 8,000 pixel entries (of ≈ 4,700 and ≈ 18,000): both limits are crossed,
    // one joint's reservation straddles the pixel capacity.
    SplatCase small = base;
    small.spriteCapacity = 300;
    small.pixelCapacity = 8000;
    checkSplatTwin(small);
  }
  SUBCASE("a bone mask and the LOD levels (long bones)") {
    synth::BodyParts parts = synth::describeBodyParts(clips.slow.skeleton);
    synth::setMeanCentres(parts, pair);
    const gpu_types::CoverageParts levels = synth::makeCoverageParts(parts, {});
    // Levels as a 1280x720 frame would pick them (a mix), splatted at 320x180.
    std::vector<synth::CoverageMask> masks(crowd.size());
    synth::coverageCpu(synth::coverageCamera(base.camera.view(), base.camera.fovYDegrees, 1280, 720,
                                             base.camera.nearPlane),
                       levels, joints, crowd, {}, masks, {});
    size_t perLevel[3] = {0, 0, 0};
    for (const synth::CoverageMask& m : masks) ++perLevel[m.level];
    MESSAGE("levels far/mid/near ", perLevel[0], "/", perLevel[1], "/", perLevel[2]);
    CHECK(perLevel[0] > 20);
    CHECK(perLevel[1] + perLevel[2] > 20);
    const auto offScreen =
        std::count_if(masks.begin(), masks.end(),
                      [](const synth::CoverageMask& m) { return (m.lo | m.hi) == 0u; });
    MESSAGE(offScreen, " characters off screen");
    CHECK(offScreen > 20);  // the on-screen list leaves them out
    SplatCase lod = base;
    lod.bones = parts.allMask & ~uint64_t(1 << 3);
    lod.masks = masks;
    lod.levels = &levels;
    checkSplatTwin(lod);
    // Far bodies up to 40 pixels tall in a 1280x720 frame: some boxes pass the 64 pixels
    // splatBody keeps as bits.
    SplatCase tall = lod;
    tall.farBodyPixels = 40.0f;
    tall.maxPixels = 48.0f;
    tall.width = 1280;
    tall.height = 720;
    checkSplatTwin(tall);
    // In chunks of 128 characters: each chunk's lists, dispatches and near joints.
    SplatCase chunked = lod;
    chunked.chunkCharacters = 128;
    checkSplatTwin(chunked);
  }
}
