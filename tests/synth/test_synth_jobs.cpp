#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>
#include "anim/default_clips.h"
#include "core/error.h"
#include "crowd/scenario.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "synth/cpu_synth.h"
#include "synth/crowd_synth.h"
#include "synth/synth_jobs.h"
#include "synth_fixtures.h"
#include "test_support.h"

using namespace throng;

namespace {

struct GpuCrowdRun {
  synth::GpuMotionPair motion;
  crowd::CrowdBuffers crowd;
  gpu::Buffer joints;
};

// Steps and poses `frames` times on the GPU and the CPU twin, returning the worst joint-matrix
// and placement differences over all frames.
struct Comparison {
  float joints = 0.0f;
  float placement = 0.0f;
};

Comparison compareGpuWithCpu(const anim::MotionPair& pair, crowd::Crowd cpuCrowd, int frames,
                             float dt) {
  gpu::Context& ctx = test::gpuContext();
  synth::SynthPrograms programs(ctx, pair);
  GpuCrowdRun run{synth::uploadMotionPair(ctx, pair), crowd::uploadCrowd(ctx, cpuCrowd), {}};
  const size_t jointCount = cpuCrowd.size() * pair.jointCount();
  run.joints = gpu::Buffer(ctx, jointCount * sizeof(synth::JointPoint), gpu::kStorageUsage,
                           gpu::MemoryUse::DeviceLocal);
  std::vector<synth::JointPoint> cpuJoints(jointCount);
  Comparison worst;
  for (int f = 0; f < frames; ++f) {
    synth::RootMotionJob root{&run.motion, &pair, &run.crowd, 0, 0, dt, cpuCrowd.steering};
    synth::PoseJob pose{&run.motion, &run.crowd, &run.joints};
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      root.record(cmd, programs);
      gpu::computeToComputeBarrier(cmd);
      pose.record(cmd, programs);
    });
    synth::stepCrowdCpu(pair, cpuCrowd, dt, 2);
    synth::poseCrowdCpu(pair, cpuCrowd, cpuJoints, 2);
    auto gpuJoints = gpu::readback<synth::JointPoint>(ctx, run.joints, jointCount);
    crowd::Crowd gpuCrowd;
    crowd::downloadCrowd(ctx, run.crowd, gpuCrowd);
    worst.joints = std::max(worst.joints,
                            test::maxAbsDifference(&gpuJoints[0].positionRadius.x,
                                                   &cpuJoints[0].positionRadius.x, jointCount * 4));
    worst.placement = std::max(
        worst.placement, test::maxAbsDifference(&gpuCrowd.placement[0].x, &cpuCrowd.placement[0].x,
                                                cpuCrowd.size() * 4));
  }
  CHECK(ctx.validationMessageCount() == 0);
  return worst;
}

}  // namespace

TEST_CASE("PoseJob: validity") {
  synth::PoseJob job;
  auto problems = job.validate();
  REQUIRE(problems.size() == 3);
  CHECK(problems[0].find("'motion'") != std::string::npos);
  CHECK(problems[1].find("'crowd'") != std::string::npos);
  CHECK(problems[2].find("'joints'") != std::string::npos);
  CHECK_THROWS_WITH_AS(
      job.record(VK_NULL_HANDLE,
                 synth::SynthPrograms(test::gpuContext(), test::syntheticPair(3, 4, 4, 1))),
      doctest::Contains("PoseJob is invalid"), Error);
}

TEST_CASE("PoseJob: an output buffer too small for the chunk is reported") {
  gpu::Context& ctx = test::gpuContext();
  anim::MotionPair pair = test::syntheticPair(8, 12, 10, 3);
  synth::GpuMotionPair motion = synth::uploadMotionPair(ctx, pair);
  crowd::Crowd crowd;
  crowd.resize(10);
  crowd::CrowdBuffers buffers = crowd::uploadCrowd(ctx, crowd);
  gpu::Buffer small(ctx, sizeof(synth::JointPoint) * 8 * 5, gpu::kStorageUsage,
                    gpu::MemoryUse::DeviceLocal);
  synth::PoseJob job{&motion, &buffers, &small};
  auto problems = job.validate();
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].find("holds 640 bytes") != std::string::npos);
  job.characterCount = 5;
  CHECK(job.validate().empty());
  job.firstCharacter = 8;
  CHECK(!job.validate().empty());
}

TEST_CASE("RootMotionJob: validity") {
  synth::RootMotionJob job;
  job.dt = -1.0f;
  auto problems = job.validate();
  REQUIRE(problems.size() == 4);
  CHECK(problems[3].find("dt must be >= 0") != std::string::npos);
}

TEST_CASE("GPU vs CPU twin: 1000 random characters on a synthetic pair, several frames") {
  anim::MotionPair pair = test::syntheticPair(25, 30, 24, 7);
  crowd::ScenarioOptions options;
  options.characters = 1000;
  options.seed = 11;
  Comparison worst = compareGpuWithCpu(pair, crowd::makeScenario(options), 6, 1.0f / 30.0f);
  MESSAGE("max |GPU - CPU|: joints ", worst.joints, ", placement ", worst.placement);
  CHECK(worst.joints <= 1e-4f);
  CHECK(worst.placement <= 1e-4f);
}

namespace {
// GPU vs CPU twin on a random crowd of `characters` over `frames` frames at 30 fps.
Comparison randomCrowdDifference(const anim::MotionPair& pair, uint32_t characters, uint64_t seed,
                                 int frames) {
  crowd::ScenarioOptions options;
  options.characters = characters;
  options.seed = seed;
  return compareGpuWithCpu(pair, crowd::makeScenario(options), frames, 1.0f / 30.0f);
}
}  // namespace

TEST_CASE(
    "fixed bones (offsets folded into the pose pass) and blended bones both match the CPU twin") {
  anim::MotionPair pair = test::syntheticPair(12, 20, 16, 9);
  auto setOffset = [](anim::MotionTexture& clip, int joint, glm::vec3 offset) {
    for (int f = 0; f < clip.frameCount; ++f)
      clip.texels[size_t(f) * clip.width() + size_t(2 * joint + 1)] = glm::vec4(offset, 0.0f);
  };
  setOffset(pair.fast, 3,
            pair.slow.offset(0, 3) * 1.5f + glm::vec3(0.02f, 0.0f, 0.0f));  // blended by w
  setOffset(pair.slow, 5, glm::vec3(0.0f));  // a zero-length bone, fixed and not drawn
  setOffset(pair.fast, 5, glm::vec3(0.0f));
  setOffset(pair.slow, 6, glm::vec3(0.0f, -0.3f, 0.0f));  // straight down
  setOffset(pair.fast, 6, glm::vec3(0.0f, -0.3f, 0.0f));
  std::vector<bool> fixed = synth::fixedBones(pair);
  CHECK_FALSE(fixed[0]);  // the root is never a bone
  CHECK_FALSE(fixed[3]);
  CHECK(fixed[5]);
  CHECK(fixed[6]);
  CHECK(randomCrowdDifference(pair, 500, 4, 4).joints <= 1e-4f);
}

TEST_CASE(
    "motion texels in uniform buffers (small clips on a CPU device) and in storage buffers agree "
    "with the twin") {
  const uint32_t capacity = synth::uniformTexelCapacity(test::gpuContext());
  for (int frames : {20, 120}) {  // 25 joints × 2 × 120 frames = 6,000 texels: more than 64 KiB
    CAPTURE(frames);
    anim::MotionPair pair = test::syntheticPair(25, frames, frames - 4, 3);
    const bool inUniform = synth::texelsFitUniform(pair, capacity);
    if (test::gpuContext().info().isCpu()) CHECK(inUniform == (frames == 20));
    CHECK(randomCrowdDifference(pair, 300, 8, 3).joints <= 1e-4f);
  }
}

TEST_CASE("GPU vs CPU twin: circle scenario steers identically") {
  anim::MotionPair pair = test::syntheticPair(12, 20, 16, 5);
  crowd::ScenarioOptions options;
  options.name = "circle";
  options.characters = 300;
  Comparison worst = compareGpuWithCpu(pair, crowd::makeScenario(options), 5, 1.0f / 20.0f);
  CHECK(worst.joints <= 1e-4f);
  CHECK(worst.placement <= 1e-4f);
}

namespace {
// 1,000 random characters over four frames on a real-capture pair prepared by the engine.
void compareOnCapture(const std::string& folder, const std::string& slow, const std::string& fast,
                      uint64_t seed) {
  if (!test::haveSharedData(folder)) return;
  auto dir = test::sharedDataDir() / folder;
  anim::ClipPair clips = anim::loadClipPair(dir / slow, dir / fast);
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  crowd::ScenarioOptions options;
  options.characters = 1000;
  options.seed = seed;
  Comparison worst = compareGpuWithCpu(pair, crowd::makeScenario(options), 4, 1.0f / 30.0f);
  MESSAGE(clips.description, ": max |GPU - CPU| joints ", worst.joints);
  CHECK(worst.joints <= 1e-4f);
  CHECK(worst.placement <= 1e-4f);
}
}  // namespace

TEST_CASE("GPU vs CPU twin on real capture: Bandai Namco run + dash (the paper's setup)") {
  compareOnCapture("bvh/bandai_namco", "dataset-1_run_normal_001.bvh",
                   "dataset-1_dash_normal_001.bvh", 1);
}

TEST_CASE(
    "GPU vs CPU twin on real capture: CMU 35_17 run/jog + 09_01 run (loops cut from raw capture)") {
  compareOnCapture("bvh/cmu", "cmu_35_17_runjog.bvh", "cmu_09_01_run.bvh", 5);
}

namespace {
// The built-in run pair and a random scenario crowd of n characters on it.
struct RunCrowd {
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  crowd::Crowd crowd;
  explicit RunCrowd(uint32_t n) {
    crowd::ScenarioOptions options;
    options.characters = n;
    crowd = crowd::makeScenario(options);
  }
};
}  // namespace

TEST_CASE("recordSynthesis (the frame orchestrator) matches the CPU twin on the built-in pair") {
  gpu::Context& ctx = test::gpuContext();
  RunCrowd run(500);
  auto& [clips, pair, crowd] = run;
  synth::SynthPrograms programs(ctx, pair);
  synth::CrowdSynth gpuSynth = synth::makeCrowdSynth(ctx, pair, crowd);
  // A small binding limit forces several pose chunks.
  const VkDeviceSize chunkBytes = VkDeviceSize(128) * pair.jointCount() * sizeof(synth::JointPoint);
  for (int f = 0; f < 3; ++f) {
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      synth::recordSynthesis(cmd, programs, gpuSynth, 1 / 30.0f, chunkBytes);
    });
    synth::stepCrowdCpu(pair, crowd, 1 / 30.0f, 2);
  }
  std::vector<synth::JointPoint> cpuJoints(crowd.size() * pair.jointCount());
  synth::poseCrowdCpu(pair, crowd, cpuJoints, 2);
  auto gpuJoints = gpu::readback<synth::JointPoint>(ctx, gpuSynth.joints, cpuJoints.size());
  float worst = test::maxAbsDifference(&gpuJoints[0].positionRadius.x,
                                       &cpuJoints[0].positionRadius.x, cpuJoints.size() * 4);
  MESSAGE("orchestrated synthesis: max |GPU - CPU| ", worst);
  CHECK(worst <= 1e-4f);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE(
    "speed changes every T seconds: new targets drawn per epoch, applied at cycle end (GPU = "
    "CPU)") {
  gpu::Context& ctx = test::gpuContext();
  RunCrowd run(800);
  auto& [clips, pair, crowd] = run;
  synth::SynthPrograms programs(ctx, pair);
  synth::CrowdSynth gpuSynth = synth::makeCrowdSynth(ctx, pair, crowd);
  synth::SpeedSchedule gpuSchedule{0.5f, 9, 0.2f, 0.8f, 0.1f}, cpuSchedule = gpuSchedule;
  const float dt = 1 / 30.0f;
  int epochs = 0;
  for (int f = 0; f < 44; ++f) {  // 1.47 s: changes at 0.5 s and 1.0 s
    anim::SpeedRetarget r = gpuSchedule.advance(dt);
    epochs += r.epoch > 0;
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      synth::recordSynthesis(cmd, programs, gpuSynth, dt, 1u << 27, r);
    });
    synth::stepCrowdCpu(pair, crowd, dt, 2, cpuSchedule.advance(dt));
  }
  CHECK(epochs == 2);
  crowd::Crowd gpuCrowd;
  crowd::downloadCrowd(ctx, gpuSynth.crowd, gpuCrowd);
  size_t changed = 0;
  for (size_t i = 0; i < crowd.size(); ++i) {
    REQUIRE(gpuCrowd.motion[i].z == crowd.motion[i].z);  // same target, exactly
    REQUIRE(gpuCrowd.motion[i].y == crowd.motion[i].y);
    CHECK(crowd.motion[i].z >= 0.2f - 1e-6f);
    CHECK(crowd.motion[i].z <= 0.8f + 1e-6f);
    CHECK(std::abs(crowd.motion[i].z * 10.0f - std::round(crowd.motion[i].z * 10.0f)) <
          1e-4f);  // bucketed
    changed += crowd.motion[i].y == crowd.motion[i].z;
  }
  CHECK(test::maxAbsDifference(&gpuCrowd.placement[0].x, &crowd.placement[0].x, crowd.size() * 4) <=
        1e-4f);
  CHECK(changed > crowd.size() / 2);  // most characters finished a cycle since the last change
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE(
    "coverage LOD in the synthesis: thresholds 0 equal the full path; masked joints are skipped") {
  gpu::Context& ctx = test::gpuContext();
  RunCrowd run(600);
  auto& [clips, pair, crowd] = run;
  synth::SynthPrograms programs(ctx, pair);
  glm::mat4 view = glm::lookAt(glm::vec3(0, 20, -40), glm::vec3(0), glm::vec3(0, 1, 0));
  synth::CoverageCamera camera = synth::coverageCamera(view, 45.0f, 1280, 720, 0.1f);
  synth::CrowdSynth plain = synth::makeCrowdSynth(ctx, pair, crowd);
  synth::CrowdSynth allJoints = synth::makeCrowdSynth(
      ctx, pair, crowd, {}, {true, synth::CoverageThresholds::uniform(0.0f), &clips.slow.skeleton});
  synth::CrowdSynth lod =
      synth::makeCrowdSynth(ctx, pair, crowd, {}, {true, {}, &clips.slow.skeleton});
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, lod.joints.get(), 0, VK_WHOLE_SIZE,
                    0u);  // to see which joints get written
    gpu::computeToComputeBarrier(cmd);
    synth::recordSynthesis(cmd, programs, plain, 1 / 30.0f, 1u << 27);
    synth::recordSynthesis(cmd, programs, allJoints, 1 / 30.0f, 1u << 27, {}, &camera);
    synth::recordSynthesis(cmd, programs, lod, 1 / 30.0f, 1u << 27, {}, &camera);
  });
  const size_t joints = pair.jointCount(), n = crowd.size() * joints;
  auto a = gpu::readback<synth::JointPoint>(ctx, plain.joints, n);
  auto b = gpu::readback<synth::JointPoint>(ctx, allJoints.joints, n);
  auto c = gpu::readback<synth::JointPoint>(ctx, lod.joints, n);
  auto masks = gpu::readback<synth::CoverageMask>(ctx, lod.masks, crowd.size());
  CHECK(test::maxAbsDifference(&a[0].positionRadius.x, &b[0].positionRadius.x, n * 4) == 0.0f);
  size_t skipped = 0, levels[3] = {0, 0, 0};
  for (size_t i = 0; i < crowd.size(); ++i) {
    uint64_t mask = synth::maskBits(masks[i]);
    REQUIRE(synth::parentsBeforeChildren(mask, pair.parents));
    levels[std::min(masks[i].level, 2u)]++;
    for (size_t j = 0; j < joints; ++j) {
      const float* got = &c[i * joints + j].positionRadius.x;
      if (mask >> j & 1) {
        REQUIRE(test::maxAbsDifference(got, &a[i * joints + j].positionRadius.x, 4) == 0.0f);
      } else {
        ++skipped;
        REQUIRE(test::maxAbsDifference(got, std::vector<float>(4, 0.0f).data(), 4) ==
                0.0f);  // never written
      }
    }
  }
  MESSAGE("LOD levels far/mid/near: ", levels[0], "/", levels[1], "/", levels[2],
          "; joints skipped ", skipped, " of ", n);
  // Far characters synthesize 21 of the built-in 25 joints (every level keeps four limbs), so a
  // crowd mostly far skips about a sixth of the joints.
  CHECK(skipped > n / 8);
  CHECK(levels[0] + levels[1] > 0);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("coverage LOD done by the root motion pass equals the coverage pass, mask for mask") {
  gpu::Context& ctx = test::gpuContext();
  RunCrowd run(900);
  auto& [clips, pair, crowd] = run;
  synth::SynthPrograms programs(ctx, pair);
  const synth::LodOptions lodOptions{true, {}, &clips.slow.skeleton};
  synth::CrowdSynth separate = synth::makeCrowdSynth(ctx, pair, crowd, {}, lodOptions);
  synth::CrowdSynth fused = synth::makeCrowdSynth(ctx, pair, crowd, {}, lodOptions);
  const synth::SynthPrograms* one[] = {&programs};
  size_t levelChanges = 0;
  std::vector<synth::CoverageMask> before(crowd.size());
  for (int f = 0; f < 45; ++f) {
    // The camera walks in and turns, so characters change level and leave or enter the view.
    const glm::vec3 eye(4.0f * std::sin(0.1f * f), 20.0f - 0.3f * f, -40.0f + 0.6f * f);
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.3f * f, 0, 0), glm::vec3(0, 1, 0));
    const synth::CoverageCamera camera = synth::coverageCamera(view, 45.0f, 1280, 720, 0.1f);
    bool covered = false;
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      CHECK(!synth::recordRootMotionPasses(cmd, one, separate, 1 / 30.0f));
      synth::recordPosePasses(cmd, one, separate, 1u << 27, &camera);
      covered = synth::recordRootMotionPasses(cmd, one, fused, 1 / 30.0f, {}, &camera);
      synth::recordPosePasses(cmd, one, fused, 1u << 27, &camera, nullptr, covered);
    });
    REQUIRE(covered);
    auto a = gpu::readback<synth::CoverageMask>(ctx, separate.masks, crowd.size());
    auto b = gpu::readback<synth::CoverageMask>(ctx, fused.masks, crowd.size());
    REQUIRE(std::memcmp(a.data(), b.data(), a.size() * sizeof(synth::CoverageMask)) == 0);
    for (size_t i = 0; i < crowd.size(); ++i)
      levelChanges += f > 0 && a[i].level != before[i].level;
    before = a;
  }
  // The joints this frame's masks asked for (the others hold whatever was there before).
  const size_t joints = pair.jointCount(), n = crowd.size() * joints;
  auto a = gpu::readback<synth::JointPoint>(ctx, separate.joints, n);
  auto b = gpu::readback<synth::JointPoint>(ctx, fused.joints, n);
  size_t compared = 0, different = 0;
  for (size_t i = 0; i < crowd.size(); ++i)
    for (size_t j = 0; j < joints; ++j)
      if (synth::maskBits(before[i]) >> j & 1) {
        ++compared;
        different += std::memcmp(&a[i * joints + j], &b[i * joints + j], sizeof(a[0])) != 0;
      }
  CHECK(compared > n / 4);
  CHECK(different == 0);
  MESSAGE("45 frames of a moving camera: ", levelChanges, " level changes, masks equal");
  CHECK(levelChanges > 50);
  CHECK(ctx.validationMessageCount() == 0);
}
