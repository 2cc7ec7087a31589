// The renderer composes cached characters' joints itself (A = M · P from the motion cache,
// shaders/joint_fetch.glsl), so synthesis writes no joint for them: the frame (near joints
// drawn as sprites, far ones splatted) must look the same as with every joint synthesized, and
// a far body placed from the far-body table (cache_fill.comp) the same as from its matrices.
#include <doctest/doctest.h>

#include "anim/default_clips.h"
#include "crowd/scenario.h"
#include "gpu/commands.h"
#include "gpu/timestamps.h"
#include "gpu_fixture.h"
#include "render/offscreen_target.h"
#include "render_frames.h"
#include "scene/frame.h"

using namespace throng;

namespace {
// One group of `crowd` animated by `pair`.
std::unique_ptr<scene::Scene> makeScene(const anim::MotionPair& pair, const crowd::Crowd& crowd,
                                        const synth::MotionCacheOptions& cache,
                                        const synth::LodOptions& lod = {}) {
  scene::SceneSetup setup;
  setup.crowd = crowd;
  setup.pairs.push_back(pair);
  setup.groupFirst = {0, uint32_t(crowd.size())};
  return std::make_unique<scene::Scene>(test::gpuContext(), std::move(setup), cache, lod);
}

// One still frame of `scene` as it stands, drawn with `params`, read back.
ImageRgba8 drawNow(gpu::Context& ctx, render::CrowdRenderer& renderer,
                   const render::OffscreenTarget& target, const render::DrawParams& params) {
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    renderer.record(cmd, render::offscreenFrameTargets(target), params);
    render::recordReadback(cmd, target);
  });
  return render::readbackImage(target);
}

}  // namespace

TEST_CASE("cached draw: the frame equals the frame with every joint synthesized") {
  gpu::Context& ctx = test::gpuContext();
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  synth::MotionCacheOptions cache;
  cache.enabled = true;
  crowd::ScenarioOptions scenario;
  scenario.characters = 300;
  scenario.seed = 11;
  crowd::Crowd crowd = crowd::makeScenario(scenario);
  // The cache poses at the bucket's speed: give the plain path the same speeds.
  for (glm::vec4& m : crowd.motion) m.y = m.z = synth::quantizeSpeed(m.y, cache.bucketWidth);
  render::Camera camera = render::cameraPreset("street", crowd::scenarioExtent(scenario));
  {
    std::unique_ptr<scene::Scene> cached = makeScene(pair, crowd, cache);
    std::unique_ptr<scene::Scene> plain = makeScene(pair, crowd, {});
    ImageRgba8 a = test::renderFrames(ctx, *cached, camera, 3);
    ImageRgba8 b = test::renderFrames(ctx, *plain, camera, 3);
    ImageDiff diff = compareImages(a, b, 24);
    MESSAGE("cached vs synthesized frame: mean ", diff.meanAbsError, ", max ", diff.maxError);
    // A cached pose is the nearest of 480 stored rows per second of cycle, not the continuous
    // sample itself (within 1/960 s of phase): limbs may move by a pixel at an edge.
    CHECK(diff.fractionDifferent < 0.005);
    CHECK(diff.meanAbsError < 0.2);
    // And the cached characters really took the composed path.
    auto sources = gpu::readback<uint32_t>(ctx, cached->synth().poseSource, crowd.size());
    size_t composed = 0;
    for (uint32_t s : sources) composed += s != gpu_types::kPoseInJoints;
    CHECK(composed == crowd.size());
  }
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("cached draw: a far body from the far-body table equals one from its matrices") {
  // The wide camera over 2,000 runners with the LOD and the cache on: every character is a far
  // body a few pixels tall, and cached. Drawn as the frame draws it (each body placed from its
  // pose's FarBodyPose), then with the cached joints written out (the materialize pass, the
  // same A = M · P) and drawn from the joints buffer: the two frames are the same to the bit.
  gpu::Context& ctx = test::gpuContext();
  const anim::ClipPair clips = anim::defaultRunPair();
  synth::MotionCacheOptions cache;
  cache.enabled = true;
  crowd::ScenarioOptions scenario;
  scenario.characters = 2000;
  scenario.seed = 5;
  std::unique_ptr<scene::Scene> lodScene =
      makeScene(anim::makeMotionPair(clips.slow, clips.fast), crowd::makeScenario(scenario), cache,
                synth::LodOptions{true, {}, &clips.slow.skeleton, 0.0f});
  scene::Scene& scene = *lodScene;
  const render::Camera camera = render::cameraPreset("wide", crowd::scenarioExtent(scenario));
  test::renderFrames(ctx, scene, camera, 3, true, 480, 270);

  scene::FrameSettings settings;
  settings.camera = camera;
  settings.groundExtent = 20.0f;
  render::OffscreenTarget target = render::makeOffscreenTarget(ctx, 480, 270);
  settings.targets = render::offscreenFrameTargets(target);
  render::DrawParams table = scene::drawParams(scene, settings);
  table.stillView = true;  // both frames through the same resolve
  REQUIRE(table.cachedPoses.farBodyPoses != nullptr);
  render::CrowdRenderer renderer(ctx, render::kColorFormat, render::kDepthFormat);
  const ImageRgba8 fromTable = drawNow(ctx, renderer, target, table);

  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    synth::recordMaterializeCachedPoses(cmd, scene.programs(), scene.synth(),
                                        ctx.info().maxStorageBufferRange);
  });
  render::DrawParams matrices = table;
  matrices.cachedPoses = {};  // every joint from the joints buffer
  const ImageRgba8 fromMatrices = drawNow(ctx, renderer, target, matrices);

  auto sources = gpu::readback<uint32_t>(ctx, scene.synth().poseSource, scenario.characters);
  size_t cached = 0;
  for (uint32_t s : sources) cached += s != gpu_types::kPoseInJoints;
  CHECK(cached == scenario.characters);
  // The bodies are there: the frame is not the bare ground.
  ImageRgba8 bare = drawNow(ctx, renderer, target, [&] {
    render::DrawParams none = matrices;
    none.characterCount = 0;
    return none;
  }());
  const ImageDiff crowdArea = compareImages(fromTable, bare, 0);
  MESSAGE("pixels of far bodies: ", crowdArea.fractionDifferent * 480 * 270);
  CHECK(crowdArea.fractionDifferent > 0.005);
  CHECK(compareImages(fromTable, fromMatrices, 0).maxError == 0);
  CHECK(ctx.validationMessageCount() == 0);
}
