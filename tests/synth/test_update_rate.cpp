// The update-rate LOD (synth/update_rate.h): validity of the schedule job and of the options,
// the interval and due rules, then the scheduled root motion with its coverage on the GPU
// against its CPU twin step by step, under a camera that comes from far (characters a few
// pixels tall, moved every few steps) to near (moved every step).
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/default_clips.h"
#include "anim/reference_synth.h"
#include "core/error.h"
#include "crowd/scenario.h"
#include "crowd/spatial_order.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "synth/crowd_synth.h"
#include "synth/update_rate.h"
#include "synth_fixtures.h"
#include "test_support.h"

using namespace throng;

namespace {

bool anyContains(const std::vector<std::string>& problems, const std::string& text) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("update-rate LOD: the schedule job and the options say what is wrong") {
  gpu::Context& ctx = test::gpuContext();
  synth::UpdateScheduleJob empty;
  const std::vector<std::string> problems = empty.validate();
  CHECK(anyContains(problems, "'chunkState' is missing"));
  CHECK(anyContains(problems, "'chunkList' is missing"));
  CHECK(anyContains(problems, "'dispatchArgs' is missing"));
  CHECK(anyContains(problems, "chunkCount must be > 0"));
  CHECK(anyContains(problems, "the lag must be > 0 pixels"));
  CHECK_THROWS_WITH_AS(empty.record(VK_NULL_HANDLE, gpu::ComputeProgram()),
                       doctest::Contains("UpdateScheduleJob is invalid"), Error);
  const synth::UpdateRateParams params =
      synth::makeUpdateRateParams(test::builtInRunPair(), 1.5f, 2.0f);
  synth::GpuUpdateRate rate = synth::makeGpuUpdateRate(ctx, 1000, params);
  synth::UpdateScheduleJob job{&rate.chunkState, &rate.chunkList, &rate.dispatchArgs,
                               rate.chunkCount};
  job.sinceSeconds.fill(1 / 30.0f);
  job.params = params;
  CHECK(job.validate().empty());
  job.chunkCount = rate.chunkCount + 1;
  CHECK(anyContains(job.validate(), "buffer 'chunkState' holds 128 bytes, 136 needed"));
  job.chunkCount = rate.chunkCount;
  job.params.maxInterval = 9;
  CHECK(anyContains(job.validate(), "maxInterval must be 1 to 8 steps, got 9"));
  job.params.maxInterval = 0;
  CHECK(anyContains(job.validate(), "maxInterval must be 1 to 8 steps, got 0"));
  job.params.maxInterval = 3;
  CHECK(job.validate().empty());
  job.params.maxInterval = 8;
  job.sinceSeconds[0] = -1.0f;
  CHECK(anyContains(job.validate(), "sinceSeconds must be seconds >= 0, got -1"));
  CHECK_THROWS_WITH_AS(synth::makeUpdateRateParams(test::builtInRunPair(), 1.5f, -1.0f),
                       doctest::Contains("the lag must be a number of pixels >= 0"), Error);
  CHECK_THROWS_WITH_AS(synth::makeUpdateRateParams(test::builtInRunPair(), 0.0f, 1.0f),
                       doctest::Contains("standing height must be > 0"), Error);
  // The schedule needs the coverage LOD (its heights) and one clip set.
  crowd::ScenarioOptions scenario;
  scenario.characters = 300;
  const crowd::Crowd crowd = crowd::makeScenario(scenario);
  synth::LodOptions noLod{false, {}, &test::builtInRunSkeleton(), 2.0f};
  CHECK_THROWS_WITH_AS(synth::makeCrowdSynth(ctx, test::builtInRunPair(), crowd, {}, noLod),
                       doctest::Contains("needs the coverage LOD on"), Error);
  const anim::MotionPair* pairs[] = {&test::builtInRunPair(), &test::builtInRunPair()};
  const uint32_t first[] = {0, 100, 300};
  synth::LodOptions lod{true, {}, &test::builtInRunSkeleton(), 2.0f};
  CHECK_THROWS_WITH_AS(synth::makeCrowdSynth(ctx, pairs, first, crowd, {}, lod),
                       doctest::Contains("needs a crowd of one clip set, this one has 2"), Error);
  // Root motion with a schedule but no coverage has no heights to give it.
  const synth::CrowdSynth synth =
      synth::makeCrowdSynth(ctx, test::builtInRunPair(), crowd, {}, lod);
  synth::RootMotionJob root{
      &synth.front().motion, &test::builtInRunPair(), &synth.crowd, 0, 0, 1 / 30.0f};
  root.updateRate = &*synth.updateRate;
  root.scheduledProgram = &synth.scheduledRootMotion;
  CHECK(anyContains(root.validate(), "the update-rate schedule needs the coverage"));
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("update-rate LOD: intervals follow the projected height, chunks are staggered") {
  using gpu_types::updateDue;
  using gpu_types::updateInterval;
  // A joint point moves 0.25 px per step per pixel of height; at most 1 px of lag.
  CHECK(updateInterval(0.5f, 0.25f, 1.0f, 8) == 8);  // 7 · 0.125 ≤ 1
  CHECK(updateInterval(1.0f, 0.25f, 1.0f, 8) == 5);  // 4 · 0.25 ≤ 1 < 5 · 0.25
  CHECK(updateInterval(1.2f, 0.25f, 1.0f, 8) == 4);  // 3 · 0.3 ≤ 1 < 4 · 0.3
  CHECK(updateInterval(3.0f, 0.25f, 1.0f, 8) == 2);
  CHECK(updateInterval(5.0f, 0.25f, 1.0f, 8) == 1);  // a step alone lags 1.25 px
  CHECK(updateInterval(0.5f, 0.25f, 1.0f, 2) == 2);  // the cap
  CHECK(updateInterval(0.5f, 0.25f, 1.0f, 3) == 3);
  CHECK(updateInterval(std::bit_cast<float>(synth::initialChunkState().x), 0.25f, 1.0f, 8) == 1);
  // With an interval of 4, each chunk moves every 4th step, a quarter of them at each step.
  synth::UpdateScheduleCpu schedule(64 * 64);
  synth::UpdateRateParams params;
  params.maxLagPixels = 1.0f;
  params.speedPerHeight = 7.5f;  // 0.25 px per step of 1/30 s per pixel of height
  std::vector<uint32_t> moves(64, 0);
  for (int step = 0; step < 17; ++step) {
    const std::vector<synth::ChunkMove> moved = schedule.schedule(params, 1 / 30.0f);
    if (step == 0) CHECK(moved.size() == 64);  // every chunk moves first
    if (step > 0) CHECK(moved.size() == 16);
    for (const synth::ChunkMove& m : moved) {
      ++moves[m.chunk];
      if (step >= 4) CHECK(m.elapsed == 4);
      if (step >= 4) CHECK(m.seconds == doctest::Approx(4 / 30.0f));
      schedule.raiseHeight(m.chunk, 1.2f);
    }
  }
  CHECK(std::all_of(moves.begin(), moves.end(), [](uint32_t m) { return m >= 4 && m <= 5; }));
  // An interval of 5, not a power of two: a fifth of the 32 blocks at each step.
  synth::UpdateScheduleCpu fifths(64 * 64);
  for (int step = 0; step < 16; ++step) {
    const std::vector<synth::ChunkMove> moved = fifths.schedule(params, 1 / 30.0f);
    if (step > 0) CHECK(moved.size() >= 12);
    if (step > 0) CHECK(moved.size() <= 14);  // blocks of two chunks
    for (const synth::ChunkMove& m : moved) {
      if (step >= 5) CHECK(m.elapsed == 5);
      fifths.raiseHeight(m.chunk, 1.0f);
    }
  }
  // An interval that grows waits for its slot or for the interval since the last move.
  CHECK(!updateDue(10, 9, 1, 2, 0));  // one step since, and 10 + 1 is odd: not its slot
  CHECK(!updateDue(10, 9, 1, 4, 0));  // one step since, not its slot
  CHECK(updateDue(10, 6, 1, 4, 0));   // four steps since
  CHECK(updateDue(11, 10, 1, 4, 0));  // its slot
  // Blocks of 4 chunks share a slot: chunks 4..7 are block 1.
  CHECK(updateDue(11, 10, 5, 4, 2));
  CHECK(updateDue(11, 10, 7, 4, 2));
  CHECK(!updateDue(11, 10, 3, 4, 2));
  // At least 32 blocks, at most 256 chunks a block.
  CHECK(synth::updateBlockShift(47) == 0);
  CHECK(synth::updateBlockShift(64) == 1);
  CHECK(synth::updateBlockShift(1563) == 5);   // 100,000 characters
  CHECK(synth::updateBlockShift(15625) == 8);  // 1,000,000
  CHECK(synth::updateBlockShift(1u << 20) == 8);
}

TEST_CASE("update-rate LOD: a move by several steps lands where moving every step does") {
  const anim::MotionPair& pair = test::builtInRunPair();
  // Within a cycle the root integrates exactly: four steps of dt and one of 4 dt agree.
  glm::vec4 placement(1.0f, 0.0f, 2.0f, 0.7f),
      motion = gpu_types::makeMotion(0.1f, 0.4f, 0.4f, 1.1f);
  glm::vec4 once = placement, onceMotion = motion;
  const float dt = 1 / 30.0f;
  for (int s = 0; s < 4; ++s)
    anim::stepCharacter(pair, placement, motion, dt, anim::Steering::KeepHeading);
  anim::stepCharacter(pair, once, onceMotion, 4 * dt, anim::Steering::KeepHeading);
  CHECK(glm::length(glm::vec3(placement - once)) < 1e-5f);
  CHECK(std::abs(motion.x - onceMotion.x) < 1e-5f);
  // The fastest joint point of the run pair: its bone ends swing faster than the body runs.
  const float fastest = synth::fastestJointSpeed(pair);
  const float run = glm::length(pair.fast.cycleTravel) / pair.fast.duration();
  MESSAGE("run pair: body ", run, " m/s, fastest joint point ", fastest, " m/s");
  CHECK(fastest > run);
  CHECK(fastest < 4.0f * run);
}

TEST_CASE("update-rate LOD: scheduled root motion and coverage equal the CPU twin step by step") {
  gpu::Context& ctx = test::gpuContext();
  const anim::MotionPair& pair = test::builtInRunPair();
  crowd::ScenarioOptions scenario;
  scenario.characters = 4500;  // 71 chunks: staggered in blocks of two
  crowd::Crowd cpu = crowd::makeScenario(scenario);
  cpu.steering = anim::Steering::Circle;
  const synth::LodOptions lod{true, {}, &test::builtInRunSkeleton(), 2.0f};
  synth::CrowdSynth gpuSynth = synth::makeCrowdSynth(ctx, pair, cpu, {}, lod);
  synth::SynthPrograms programs(ctx, pair);
  const synth::SynthPrograms* used[] = {&programs};
  const synth::CoverageParts parts =
      *static_cast<const synth::CoverageParts*>(gpuSynth.front().coverageParts.mapped());
  std::vector<synth::CoverageMask> masks(cpu.size(), synth::CoverageMask{});
  synth::UpdateScheduleCpu twin(uint32_t(cpu.size()));
  size_t skippedSteps = 0, everyChunkSteps = 0;
  float worstPlacement = 0.0f, worstMotion = 0.0f;
  size_t maskMismatches = 0;
  for (int step = 0; step < 24; ++step) {
    // From 400 m away (characters ~3 px tall) to 20 m (every chunk moves every step).
    const float distance = 400.0f * std::pow(0.88f, float(step));
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 0.3f * distance, -distance), glm::vec3(0.0f),
                                       glm::vec3(0, 1, 0));
    const synth::CoverageCamera camera = synth::coverageCamera(view, 45.0f, 1280, 720, 0.1f);
    // Steps of varying length, two of them paused: a move advances by the skipped steps' sum.
    const float dt = step == 5 || step == 6 ? 0.0f : (1.0f + 0.3f * std::sin(1.7f * step)) / 30.0f;
    const anim::SpeedRetarget retarget =
        step == 9 ? anim::SpeedRetarget{1, 7, 0.0f, 1.0f, 0.0f} : anim::SpeedRetarget{};
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      CHECK(synth::recordRootMotionPasses(cmd, used, gpuSynth, dt, retarget, &camera));
    });
    const uint32_t moved = synth::readMovedChunks(ctx, *gpuSynth.updateRate);
    synth::stepScheduledCpu(pair, cpu, masks, camera, parts, dt, retarget,
                            gpuSynth.updateRate->params, twin);
    skippedSteps += moved < twin.state.size();
    everyChunkSteps += moved == twin.state.size();
    crowd::Crowd gpuCrowd;
    crowd::downloadCrowd(ctx, gpuSynth.crowd, gpuCrowd);
    worstPlacement = std::max(
        worstPlacement,
        test::maxAbsDifference(&gpuCrowd.placement[0].x, &cpu.placement[0].x, cpu.size() * 4));
    worstMotion = std::max(worstMotion, test::maxAbsDifference(&gpuCrowd.motion[0].x,
                                                               &cpu.motion[0].x, cpu.size() * 4));
    const auto gpuMasks = gpu::readback<synth::CoverageMask>(ctx, gpuSynth.masks, cpu.size());
    for (size_t i = 0; i < cpu.size(); ++i)
      maskMismatches += gpuMasks[i].lo != masks[i].lo || gpuMasks[i].hi != masks[i].hi ||
                        gpuMasks[i].level != masks[i].level;
    const auto chunks =
        gpu::readback<glm::uvec2>(ctx, gpuSynth.updateRate->chunkState, twin.state.size());
    for (size_t c = 0; c < chunks.size(); ++c) {
      REQUIRE(chunks[c].y == twin.state[c].y);  // the same chunks moved at the same steps
      const float a = std::bit_cast<float>(chunks[c].x), b = std::bit_cast<float>(twin.state[c].x);
      REQUIRE(std::abs(a - b) <= 1e-4f * std::max(a, b));
    }
  }
  MESSAGE("24 steps: ", skippedSteps, " with chunks left unmoved, ", everyChunkSteps,
          " with every chunk moved; max |GPU - CPU| placement ", worstPlacement, ", motion ",
          worstMotion, "; ", maskMismatches, " masks differ");
  CHECK(skippedSteps >= 5);
  CHECK(everyChunkSteps >= 4);
  CHECK(worstPlacement <= 1e-4f);
  CHECK(worstMotion <= 1e-4f);
  CHECK(maskMismatches == 0);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE(
    "update-rate LOD: chunks off screen wait the longest interval; none walks into view lagging") {
  gpu::Context& ctx = test::gpuContext();
  const anim::MotionPair& pair = test::builtInRunPair();
  crowd::ScenarioOptions scenario;
  scenario.characters = 64 * 48;  // a square 28 m wide, dense: chunks are patches 4 m wide
  scenario.density = 4.0f;
  crowd::Crowd everyStep = crowd::makeScenario(scenario);
  everyStep = crowd::permuted(everyStep, crowd::spatialOrder(everyStep));
  const synth::LodOptions lod{true, {}, &test::builtInRunSkeleton(), 2.0f};
  synth::CrowdSynth gpuSynth = synth::makeCrowdSynth(ctx, pair, everyStep, {}, lod);
  synth::SynthPrograms programs(ctx, pair);
  const synth::SynthPrograms* used[] = {&programs};
  const synth::CoverageParts parts =
      *static_cast<const synth::CoverageParts*>(gpuSynth.front().coverageParts.mapped());
  const uint32_t chunks = gpuSynth.updateRate->chunkCount;
  const float dt = 1 / 30.0f;
  size_t checked = 0, lagging = 0, laggingAfterTurn = 0;
  uint32_t fewestMoved = chunks, totalMoved = 0;
  for (int step = 0; step < 40; ++step) {
    // From the middle of the crowd at head height, along +x, then (a turn) along -x: everything
    // on screen is near enough to move every step, everything behind waits. Characters walk
    // into view all the time at the sides; after the turn, the chunks now in view catch up
    // within one interval.
    const float look = step < 20 ? 1.0f : -1.0f;
    const glm::mat4 view =
        glm::lookAt(glm::vec3(0.0f, 1.7f, 0.0f), glm::vec3(look, 1.5f, 0.2f), glm::vec3(0, 1, 0));
    const synth::CoverageCamera camera = synth::coverageCamera(view, 45.0f, 1280, 720, 0.1f);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      CHECK(synth::recordRootMotionPasses(cmd, used, gpuSynth, dt, {}, &camera));
    });
    const uint32_t moved = synth::readMovedChunks(ctx, *gpuSynth.updateRate);
    if (step > 0) fewestMoved = std::min(fewestMoved, moved);
    if (step > 0) totalMoved += moved;
    for (size_t i = 0; i < everyStep.size(); ++i)
      anim::stepCharacter(pair, everyStep.placement[i], everyStep.motion[i], dt,
                          anim::Steering::KeepHeading);
    crowd::Crowd gpuCrowd;
    crowd::downloadCrowd(ctx, gpuSynth.crowd, gpuCrowd);
    // Every character whose body is on screen where moving every step puts it is drawn there.
    const synth::CoveragePush push = synth::makeCoveragePush(camera, 1, 0, 1, 0u);
    for (size_t i = 0; i < everyStep.size(); ++i) {
      const float height = parts.body.x * gpu_types::characterScale(everyStep.motion[i]);
      const glm::vec3 middle = synth::cameraSpace(
          push, glm::vec3(everyStep.placement[i]) + glm::vec3(0.0f, 0.5f * height, 0.0f));
      if (!synth::sphereInFrustum(push, middle, 0.8f * height)) continue;
      const bool lags =
          glm::length(glm::vec3(gpuCrowd.placement[i] - everyStep.placement[i])) > 1e-3f;
      if (step >= 20 && step < 20 + int(synth::kUpdateMaxInterval)) {
        laggingAfterTurn += lags;
        continue;
      }
      ++checked;
      lagging += lags;
    }
  }
  MESSAGE(checked, " bodies on screen checked over 32 steps, ", lagging,
          " drawn away from where moving every step puts them (", laggingAfterTurn,
          " in the 8 steps after the turn); ", totalMoved, " chunk moves in 39 steps of ", chunks,
          " chunks, at least ", fewestMoved, " a step");
  CHECK(checked > 10000);
  CHECK(lagging == 0);
  CHECK(totalMoved < chunks * 39 * 3 / 4);  // the chunks behind the camera wait
  CHECK(fewestMoved > chunks / 8);          // the ones in view move every step
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("update-rate LOD: a crowd near the camera moves every step, as without the schedule") {
  gpu::Context& ctx = test::gpuContext();
  const anim::MotionPair& pair = test::builtInRunPair();
  crowd::ScenarioOptions scenario;
  scenario.characters = 1000;
  const crowd::Crowd crowd = crowd::makeScenario(scenario);
  const synth::LodOptions plainLod{true, {}, &test::builtInRunSkeleton()};
  const synth::LodOptions scheduledLod{true, {}, &test::builtInRunSkeleton(), 1.0f};
  // With the motion cache: the scheduled classify covers the listed chunks (here every chunk).
  synth::MotionCacheOptions cache;
  cache.enabled = true;
  const synth::CrowdSynth plain = synth::makeCrowdSynth(ctx, pair, crowd, cache, plainLod);
  const synth::CrowdSynth scheduled = synth::makeCrowdSynth(ctx, pair, crowd, cache, scheduledLod);
  REQUIRE(scheduled.scheduledClassify.has_value());
  synth::SynthPrograms programs(ctx, pair);
  const synth::SynthPrograms* used[] = {&programs};
  const glm::mat4 view =
      glm::lookAt(glm::vec3(0.0f, 8.0f, -40.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  const synth::CoverageCamera camera = synth::coverageCamera(view, 45.0f, 1280, 720, 0.1f);
  uint32_t fewestMoved = UINT32_MAX;
  // Two steps per command buffer: the second's schedule waits for the first's reads.
  for (int step = 0; step < 10; step += 2) {
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      for (int twice = 0; twice < 2; ++twice) {
        synth::recordSynthesis(cmd, used, plain, 1 / 30.0f, 1u << 27, {}, &camera);
        synth::recordSynthesis(cmd, used, scheduled, 1 / 30.0f, 1u << 27, {}, &camera);
      }
    });
    fewestMoved = std::min(fewestMoved, synth::readMovedChunks(ctx, *scheduled.updateRate));
  }
  crowd::Crowd a, b;
  crowd::downloadCrowd(ctx, plain.crowd, a);
  crowd::downloadCrowd(ctx, scheduled.crowd, b);
  const auto masksA = gpu::readback<synth::CoverageMask>(ctx, plain.masks, crowd.size());
  const auto masksB = gpu::readback<synth::CoverageMask>(ctx, scheduled.masks, crowd.size());
  CHECK(fewestMoved == scheduled.updateRate->chunkCount);
  CHECK(test::maxAbsDifference(&a.placement[0].x, &b.placement[0].x, crowd.size() * 4) == 0.0f);
  CHECK(test::maxAbsDifference(&a.motion[0].x, &b.motion[0].x, crowd.size() * 4) == 0.0f);
  CHECK(std::memcmp(masksA.data(), masksB.data(), masksA.size() * sizeof(masksA[0])) == 0);
  const auto sourceA = gpu::readback<uint32_t>(ctx, plain.poseSource, crowd.size());
  const auto sourceB = gpu::readback<uint32_t>(ctx, scheduled.poseSource, crowd.size());
  CHECK(sourceA == sourceB);
  CHECK(ctx.validationMessageCount() == 0);
}
