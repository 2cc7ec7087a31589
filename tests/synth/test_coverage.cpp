#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/default_clips.h"
#include "anim/gait.h"
#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/timestamps.h"
#include "gpu_fixture.h"
#include "synth/coverage.h"
#include "synth/cpu_synth.h"

using namespace throng;
using synth::CoverageMask;

namespace {

constexpr uint32_t kW = 1280, kH = 720;

synth::CoverageCamera lookCamera(glm::vec3 eye, glm::vec3 target) {
  return synth::coverageCamera(glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f)), 45.0f, kW, kH,
                               0.1f);
}

// The built-in pair and its body parts (mean centres from the motion).
struct DefaultBody {
  anim::MotionPair pair;
  synth::BodyParts parts;
  DefaultBody() {
    anim::ClipPair clips = anim::defaultRunPair();
    pair = anim::makeMotionPair(clips.slow, clips.fast);
    parts = synth::describeBodyParts(clips.slow.skeleton);
    synth::setMeanCentres(parts, pair);
  }
};
const DefaultBody& defaultBody() {
  static DefaultBody body;
  return body;
}

crowd::Crowd randomCrowd(uint32_t n, uint32_t seed, float nearZ, float farZ) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  crowd::Crowd c;
  c.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    float z = nearZ + (farZ - nearZ) * u(rng);
    c.placement[i] = glm::vec4((u(rng) - 0.5f) * 1.2f * std::abs(z) + (u(rng) - 0.5f) * 4.0f, 0.0f,
                               z, 6.2831853f * u(rng));
    float w = u(rng);
    c.motion[i] = glm::vec4(u(rng), w, w, 0.9f + 0.2f * u(rng));
  }
  return c;
}

struct GpuRun {
  std::vector<CoverageMask> masks;
  std::vector<float> areas;
};

// Runs coverage.comp over `crowd` in `chunks` dispatches (joints bound per chunk at an offset).
GpuRun runGpu(const synth::CoverageCamera& camera, const synth::CoverageParts& partsBlock,
              uint32_t jointCount, const crowd::Crowd& crowd,
              std::span<const synth::JointPoint> joints, std::span<const CoverageMask> previous,
              uint32_t chunks = 1) {
  gpu::Context& ctx = test::gpuContext();
  const uint32_t n = uint32_t(crowd.size());
  crowd::CrowdBuffers buffers = crowd::uploadCrowd(ctx, crowd);
  gpu::Buffer partsBuffer(ctx, sizeof(synth::CoverageParts), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                          gpu::MemoryUse::HostVisible);
  std::memcpy(partsBuffer.mapped(), &partsBlock, sizeof(partsBlock));
  gpu::Buffer jointsBuffer;
  if (!joints.empty()) jointsBuffer = gpu::makeStorageBuffer(ctx, joints);
  gpu::Buffer masks = gpu::makeStorageBuffer(ctx, previous);
  gpu::Buffer areas(ctx, VkDeviceSize(n) * 5 * sizeof(float), gpu::kStorageUsage,
                    gpu::MemoryUse::DeviceLocal);
  gpu::ComputeProgram program = synth::makeCoverageProgram(ctx);
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    const uint32_t per = (n + chunks - 1) / chunks;
    for (uint32_t first = 0; first < n; first += per) {
      synth::CoverageJob job{&buffers,
                             &partsBuffer,
                             joints.empty() ? nullptr : &jointsBuffer,
                             &masks,
                             &areas,
                             camera,
                             jointCount,
                             first,
                             std::min(per, n - first),
                             VkDeviceSize(first) * jointCount * sizeof(synth::JointPoint)};
      job.record(cmd, program);
    }
  });
  GpuRun run{gpu::readback<CoverageMask>(ctx, masks, n),
             gpu::readback<float>(ctx, areas, size_t(n) * 5)};
  CHECK(ctx.validationMessageCount() == 0);
  return run;
}

// Compares GPU and CPU twin outputs: identical masks, areas within 1e-3 relative.
void compareTwins(const GpuRun& gpuRun, std::span<const CoverageMask> cpuMasks,
                  std::span<const float> cpuAreas) {
  size_t maskDiffs = 0;
  float worst = 0.0f;
  for (size_t i = 0; i < cpuMasks.size(); ++i) {
    const CoverageMask &a = gpuRun.masks[i], &b = cpuMasks[i];
    maskDiffs += (a.lo != b.lo || a.hi != b.hi || a.level != b.level || a.state != b.state) ? 1 : 0;
  }
  for (size_t i = 0; i < cpuAreas.size(); ++i) {
    float scale = std::max({std::abs(cpuAreas[i]), std::abs(gpuRun.areas[i]), 1e-6f});
    worst = std::max(worst, std::abs(gpuRun.areas[i] - cpuAreas[i]) / scale);
  }
  MESSAGE("GPU vs CPU twin: ", maskDiffs, " of ", cpuMasks.size(),
          " masks differ; worst relative area difference ", worst);
  CHECK(maskDiffs == 0);
  CHECK(worst <= 1e-3f);
  // Not vacuous: a good share of the spheres is on screen.
  CHECK(std::count_if(cpuAreas.begin(), cpuAreas.end(), [](float a) { return a > 0.0f; }) >
        long(cpuAreas.size() / 5));
}

}  // namespace

TEST_CASE("CoverageJob: validity") {
  synth::CoverageJob job;
  auto problems = job.validate();
  REQUIRE(problems.size() == 4);
  CHECK(problems[0].find("'crowd'") != std::string::npos);
  CHECK(problems[1].find("'parts'") != std::string::npos);
  CHECK(problems[2].find("'masks'") != std::string::npos);
  CHECK(problems[3].find("jointCount must be 1..64, got 0") != std::string::npos);
  job.camera.focalPixels = -1.0f;
  job.camera.width = 0;
  problems = job.validate();
  CHECK(problems.size() == 6);
  gpu::ComputeProgram program = synth::makeCoverageProgram(test::gpuContext());
  CHECK_THROWS_WITH_AS(job.record(VK_NULL_HANDLE, program),
                       doctest::Contains("CoverageJob is invalid"), Error);
}

TEST_CASE("CoverageJob: buffers too small for the chunk are reported") {
  gpu::Context& ctx = test::gpuContext();
  crowd::Crowd crowd = randomCrowd(10, 1, 5.0f, 50.0f);
  crowd::CrowdBuffers buffers = crowd::uploadCrowd(ctx, crowd);
  gpu::Buffer parts(ctx, sizeof(synth::CoverageParts), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                    gpu::MemoryUse::HostVisible);
  gpu::Buffer masks(ctx, 16 * 8, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  gpu::Buffer joints(ctx, sizeof(synth::JointPoint) * 25 * 5, gpu::kStorageUsage,
                     gpu::MemoryUse::DeviceLocal);
  gpu::Buffer areas(ctx, 20 * 4, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  synth::CoverageJob job{&buffers, &parts, &joints, &masks, &areas};
  job.jointCount = 25;
  auto problems = job.validate();
  REQUIRE(problems.size() == 3);
  CHECK(problems[0].find("'masks' holds 128 bytes, characters up to 10 need 160") !=
        std::string::npos);
  CHECK(problems[1].find("'joints' holds 2000 bytes, the chunk needs 4000") != std::string::npos);
  CHECK(problems[2].find("'areas' holds 80 bytes") != std::string::npos);
  job.characterCount = 4;  // characters 0..3 fit everything
  CHECK(job.validate().empty());
  job.firstCharacter = 8;
  CHECK(!job.validate().empty());
}

TEST_CASE("coverage: GPU vs CPU twin on 1000 random characters (joint centres and estimates)") {
  const DefaultBody& body = defaultBody();
  const uint32_t jointCount = uint32_t(body.pair.jointCount());
  crowd::Crowd crowd = randomCrowd(1000, 42, -20.0f, 180.0f);
  std::vector<synth::JointPoint> joints(crowd.size() * jointCount);
  synth::poseCrowdCpu(body.pair, crowd, joints, 2);
  // Random previous masks: centres come from the joints where the centre joint was active.
  std::mt19937 rng(7);
  // Half of them with a level history (random level, timer and last phase): the transitions.
  std::vector<CoverageMask> previous(crowd.size());
  for (size_t i = 0; i < previous.size(); ++i) {
    const uint32_t r = uint32_t(rng());
    const uint32_t history = gpu_types::kStateInitialized | (r & 0xFFFF0000u) |
                             (((r >> 3) & 0x3FFu) << gpu_types::kStateTimerShift);
    previous[i] = {uint32_t(rng()), 0u, r % 3u, i % 2 == 0 ? 0u : history};
  }
  synth::CoverageCamera camera =
      lookCamera(glm::vec3(0.0f, 6.0f, -10.0f), glm::vec3(0.0f, 1.0f, 40.0f));
  synth::CoverageParts parts = synth::makeCoverageParts(body.parts, {});
  for (bool withJoints : {true, false}) {
    std::span<const synth::JointPoint> used = withJoints
                                                  ? std::span<const synth::JointPoint>(joints)
                                                  : std::span<const synth::JointPoint>();
    std::vector<CoverageMask> cpuMasks = previous;
    std::vector<float> cpuAreas(crowd.size() * 5);
    synth::coverageCpu(camera, parts, jointCount, crowd, used, cpuMasks, cpuAreas);
    GpuRun gpuRun = runGpu(camera, parts, jointCount, crowd, used, previous, withJoints ? 3 : 1);
    compareTwins(gpuRun, cpuMasks, cpuAreas);
    int levels[3] = {0, 0, 0};
    bool ordered = true;
    for (const CoverageMask& m : cpuMasks) {
      ++levels[std::min(m.level, 2u)];
      ordered = ordered && synth::parentsBeforeChildren(synth::maskBits(m), body.pair.parents);
    }
    MESSAGE(std::string(withJoints ? "joint centres" : "estimated centres"), ": far ", levels[0],
            ", mid ", levels[1], ", near ", levels[2]);
    CHECK(levels[0] > 50);
    CHECK(levels[1] > 50);
    CHECK(levels[2] > 20);
    CHECK(ordered);
  }
}

TEST_CASE(
    "coverage: a 45-joint skeleton uses the high mask word; chunked GPU matches the CPU twin") {
  anim::Skeleton s = anim::gaitSkeleton();
  int hand = s.findJoint("LeftHand"), head = s.findJoint("Head");
  for (int k = 0; k < 10; ++k)
    s.joints.push_back({concat("LeftHandExtra", k),
                        k == 0 ? hand : s.jointCount() - 1,
                        {0.0f, -0.02f, 0.0f},
                        {},
                        {}});
  for (int k = 0; k < 10; ++k)
    s.joints.push_back(
        {concat("HeadExtra", k), k == 0 ? head : s.jointCount() - 1, {0.0f, 0.01f, 0.0f}, {}, {}});
  synth::BodyParts body = synth::describeBodyParts(s);
  REQUIRE(body.jointCount == 45);
  CHECK((body.parts[0].activates >> 32) != 0);
  CHECK((body.parts[2].activates >> 32) != 0);
  const uint32_t jointCount = 45;
  crowd::Crowd crowd = randomCrowd(700, 9, 1.0f, 120.0f);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<synth::JointPoint> joints(crowd.size() * jointCount);
  for (size_t i = 0; i < crowd.size(); ++i)
    for (uint32_t j = 0; j < jointCount; ++j) {
      glm::vec3 p = glm::vec3(crowd.placement[i]) +
                    glm::vec3(0.4f * u(rng), 1.0f + 0.6f * u(rng), 0.4f * u(rng));
      joints[i * jointCount + j] = {glm::vec4(p, 0.05f + 0.02f * u(rng))};
    }
  std::vector<CoverageMask> previous(crowd.size());
  for (CoverageMask& m : previous) m = {uint32_t(rng()), uint32_t(rng()), 0u, 0u};
  synth::CoverageCamera camera =
      lookCamera(glm::vec3(0.0f, 1.6f, 0.0f), glm::vec3(0.0f, 1.6f, 1.0f));
  synth::CoverageParts parts = synth::makeCoverageParts(body, {});
  std::vector<CoverageMask> cpuMasks = previous;
  std::vector<float> cpuAreas(crowd.size() * 5);
  synth::coverageCpu(camera, parts, jointCount, crowd, joints, cpuMasks, cpuAreas);
  compareTwins(runGpu(camera, parts, jointCount, crowd, joints, previous, 4), cpuMasks, cpuAreas);
  std::vector<int32_t> parents = s.parents();
  int nearCount = 0;
  for (const CoverageMask& m : cpuMasks) {
    CHECK(synth::parentsBeforeChildren(synth::maskBits(m), parents));
    nearCount += m.level == gpu_types::kLevelNear ? 1 : 0;
    if (m.level == gpu_types::kLevelNear) CHECK(synth::countJoints(synth::maskBits(m)) == 45);
  }
  CHECK(nearCount > 0);
}

TEST_CASE("coverage: the three levels at 5 m, 15 m and 40 m (default camera and thresholds)") {
  const DefaultBody& body = defaultBody();
  const uint32_t jointCount = uint32_t(body.pair.jointCount());
  synth::CoverageCamera camera =
      lookCamera(glm::vec3(0.0f, 1.6f, 0.0f), glm::vec3(0.0f, 1.6f, 1.0f));
  synth::CoverageParts parts = synth::makeCoverageParts(body.parts, {});
  crowd::Crowd crowd;
  crowd.resize(3);
  const float distances[] = {5.0f, 15.0f, 40.0f};
  for (size_t i = 0; i < 3; ++i) {
    crowd.placement[i] = glm::vec4(0.0f, 0.0f, distances[i], 3.14159265f);  // facing the camera
    crowd.motion[i] = glm::vec4(0.3f, 0.5f, 0.5f, 1.0f);
  }
  std::vector<synth::JointPoint> joints(3 * jointCount);
  synth::poseCrowdCpu(body.pair, crowd, joints, 1);
  // Near: all 25; mid: all but the two fingers; far: also without the toes (drawn fewer still).
  const int expectedJoints[] = {25, 23, 21};
  const uint32_t expectedLevel[] = {gpu_types::kLevelNear, gpu_types::kLevelMid,
                                    gpu_types::kLevelFar};
  for (bool withJoints : {false, true}) {
    std::vector<CoverageMask> masks(3, CoverageMask{~0u, ~0u, 0u, 0u});
    std::vector<float> areas(15);
    synth::coverageCpu(camera, parts, jointCount, crowd,
                       withJoints ? std::span<const synth::JointPoint>(joints)
                                  : std::span<const synth::JointPoint>(),
                       masks, areas);
    GpuRun gpuRun = runGpu(camera, parts, jointCount, crowd,
                           withJoints ? std::span<const synth::JointPoint>(joints)
                                      : std::span<const synth::JointPoint>(),
                           std::vector<CoverageMask>(3, CoverageMask{~0u, ~0u, 0u, 0u}));
    for (size_t i = 0; i < 3; ++i) {
      CAPTURE(distances[i]);
      CHECK(synth::countJoints(synth::maskBits(masks[i])) == expectedJoints[i]);
      CHECK(masks[i].level == expectedLevel[i]);
      CHECK(gpuRun.masks[i].lo == masks[i].lo);
      CHECK(gpuRun.masks[i].level == masks[i].level);
    }
  }
  // Where the levels switch for a character facing this camera, with no history.
  auto levelAt = [&](float d) {
    crowd::Crowd one;
    one.resize(1);
    one.placement[0] = glm::vec4(0.0f, 0.0f, d, 3.14159265f);
    one.motion[0] = glm::vec4(0.3f, 0.5f, 0.5f, 1.0f);
    std::vector<CoverageMask> m(1);
    synth::coverageCpu(camera, parts, jointCount, one, {}, m, {});
    return m[0].level;
  };
  auto switchDistance = [&](uint32_t level) {
    float lo = 1.0f, hi = 500.0f;
    for (int it = 0; it < 40; ++it)
      (levelAt(0.5f * (lo + hi)) >= level ? lo : hi) = 0.5f * (lo + hi);
    return lo;
  };
  float mid = switchDistance(gpu_types::kLevelMid), near = switchDistance(gpu_types::kLevelNear);
  MESSAGE("default thresholds (1280x720, fovy 45, camera at 1.6 m, body ", body.parts.height,
          " m): far->mid at ", mid, " m, mid->near at ", near, " m");
  CHECK(mid == doctest::Approx(camera.focalPixels * body.parts.height / synth::kDefaultMidPixels)
                   .epsilon(0.02));
  CHECK(near == doctest::Approx(camera.focalPixels * body.parts.height / synth::kDefaultNearPixels)
                    .epsilon(0.02));
}

TEST_CASE(
    "coverage: with every threshold 0, every joint is active, even off screen or behind the "
    "camera") {
  const DefaultBody& body = defaultBody();
  const uint32_t jointCount = uint32_t(body.pair.jointCount());
  crowd::Crowd crowd = randomCrowd(300, 5, -100.0f, 400.0f);
  synth::CoverageCamera camera =
      lookCamera(glm::vec3(0.0f, 1.6f, 0.0f), glm::vec3(0.0f, 1.6f, 1.0f));
  synth::CoverageParts parts =
      synth::makeCoverageParts(body.parts, synth::CoverageThresholds::uniform(0.0f));
  std::vector<CoverageMask> masks(crowd.size());
  synth::coverageCpu(camera, parts, jointCount, crowd, {}, masks, {});
  GpuRun gpuRun =
      runGpu(camera, parts, jointCount, crowd, {}, std::vector<CoverageMask>(crowd.size()));
  for (size_t i = 0; i < crowd.size(); ++i) {
    REQUIRE(synth::maskBits(masks[i]) == body.parts.allMask);
    REQUIRE(masks[i].level == gpu_types::kLevelNear);
    REQUIRE(synth::maskBits(gpuRun.masks[i]) == body.parts.allMask);
  }
  CHECK_THROWS_WITH_AS(
      synth::makeCoverageParts(body.parts, synth::CoverageThresholds::uniform(-1.0f)),
      doctest::Contains("the mid and near heights must be >= 0 pixels"), Error);
}

TEST_CASE("coverage: GPU time for 100k characters (timestamps)") {
  gpu::Context& ctx = test::gpuContext();
  const DefaultBody& body = defaultBody();
  const uint32_t jointCount = uint32_t(body.pair.jointCount());
  const uint32_t n = 100000;
  crowd::Crowd crowd = randomCrowd(n, 8, -20.0f, 300.0f);
  crowd::CrowdBuffers buffers = crowd::uploadCrowd(ctx, crowd);
  synth::CoverageParts partsBlock = synth::makeCoverageParts(body.parts, {});
  gpu::Buffer parts(ctx, sizeof(partsBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                    gpu::MemoryUse::HostVisible);
  std::memcpy(parts.mapped(), &partsBlock, sizeof(partsBlock));
  const VkDeviceSize jointBytes = VkDeviceSize(n) * jointCount * sizeof(synth::JointPoint);
  const bool jointsFit = jointBytes <= ctx.info().maxStorageBufferRange;
  gpu::Buffer joints(ctx, jointsFit ? jointBytes : 16, gpu::kStorageUsage,
                     gpu::MemoryUse::DeviceLocal);
  gpu::Buffer masks(ctx, VkDeviceSize(n) * sizeof(CoverageMask), gpu::kStorageUsage,
                    gpu::MemoryUse::DeviceLocal);
  gpu::ComputeProgram program = synth::makeCoverageProgram(ctx);
  synth::CoverageCamera camera =
      lookCamera(glm::vec3(0.0f, 6.0f, -10.0f), glm::vec3(0.0f, 1.0f, 40.0f));
  gpu::TimestampPool timestamps(ctx, 8);
  for (int variant = 0; variant < (jointsFit ? 2 : 1); ++variant) {
    std::vector<double> ms;
    for (int rep = 0; rep < 4; ++rep) {
      timestamps.reset();
      gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        // Previous masks all set: every centre comes from the joint matrices (variant 1).
        vkCmdFillBuffer(cmd, masks.get(), 0, VK_WHOLE_SIZE, variant == 1 ? ~0u : 0u);
        if (variant == 1) vkCmdFillBuffer(cmd, joints.get(), 0, VK_WHOLE_SIZE, 0u);
      });
      gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        timestamps.write(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
        synth::CoverageJob job{&buffers,  &parts,  variant == 1 ? &joints : nullptr,
                               &masks,    nullptr, camera,
                               jointCount};
        job.record(cmd, program);
        timestamps.write(cmd);
      });
      ms.push_back(timestamps.millisecondsBetween(timestamps.fetch(), 0, 1));
    }
    std::sort(ms.begin(), ms.end());
    MESSAGE("coverage pass, 100k characters, ",
            std::string(variant == 1 ? "centres from joint matrices" : "estimated centres"), ": ",
            0.5 * (ms[1] + ms[2]), " ms GPU (median of 4, ", ctx.info().name, ")");
  }
  auto out = gpu::readback<CoverageMask>(ctx, masks, 1000);
  int nonBase = 0;
  for (const CoverageMask& m : out) nonBase += m.level != gpu_types::kLevelFar ? 1 : 0;
  CHECK(nonBase > 0);
  CHECK(ctx.validationMessageCount() == 0);
}
