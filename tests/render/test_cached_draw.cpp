// The renderer composes cached characters' joints itself (A = M · P from the motion cache,
// shaders/joint_fetch.glsl), so synthesis writes no joint for them: the frame (near joints
// drawn as sprites, far ones splatted) must look the same as with every joint synthesized.
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
                                        const synth::MotionCacheOptions& cache) {
  scene::SceneSetup setup;
  setup.crowd = crowd;
  setup.pairs.push_back(pair);
  setup.groupFirst = {0, uint32_t(crowd.size())};
  return std::make_unique<scene::Scene>(test::gpuContext(), std::move(setup), cache,
                                        synth::LodOptions{});
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
