// The far body (shaders/joint_far_body.glsl): far characters a few pixels tall splatted as one
// ellipsoid instead of their far level's joints. How far the picture moves is bounded here
// against the per-joint path, with the CPU twins (test_joint_splat.cpp ties them to the GPU).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "anim/default_clips.h"
#include "anim/pair_placement.h"
#include "core/image.h"
#include "crowd/scenario.h"
#include "gpu_fixture.h"
#include "render/crowd_renderer.h"
#include "render/joint_far_body_cpu.h"
#include "render/joint_splat.h"
#include "render/joint_splat_cpu.h"
#include "render_frames.h"
#include "synth/cpu_synth.h"

using namespace throng;

namespace {

constexpr Rgba8 kGround{150, 150, 145, 255};

// The splat's colours over a plain ground (the frame's resolve without the ground's shading).
ImageRgba8 imageOf(const std::vector<uint64_t>& visibility, int width, int height) {
  ImageRgba8 image(width, height, kGround);
  for (size_t i = 0; i < visibility.size(); ++i) {
    if (visibility[i] == render::kEmptyPixel) continue;
    const uint32_t c = uint32_t(visibility[i]);
    image.pixels[i] = Rgba8{uint8_t(c), uint8_t(c >> 8), uint8_t(c >> 16), 255};
  }
  return image;
}

// Means over blocks of `side`² pixels: the crowd as seen from further away, where single
// pixels no longer count.
ImageRgba8 blockMeans(const ImageRgba8& image, int side) {
  ImageRgba8 out(image.width / side, image.height / side);
  for (int by = 0; by < out.height; ++by)
    for (int bx = 0; bx < out.width; ++bx) {
      int sum[3] = {0, 0, 0};
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
          const Rgba8& p = image.at(bx * side + x, by * side + y);
          sum[0] += p.r;
          sum[1] += p.g;
          sum[2] += p.b;
        }
      const int n = side * side;
      out.at(bx, by) = Rgba8{uint8_t(sum[0] / n), uint8_t(sum[1] / n), uint8_t(sum[2] / n), 255};
    }
  return out;
}

struct FarComparison {
  size_t bodies = 0;                       // characters drawn as their far body
  float shortest = 0, tallest = 0;         // their bodies' heights on screen, pixels
  size_t jointPixels = 0, bodyPixels = 0;  // pixels covered, per-joint path and far bodies
  ImageDiff pixels, blocks;                // the two frames, and their 8×8 block means
};

FarComparison compareFar(uint32_t characters, const std::string& preset, uint32_t width,
                         uint32_t height) {
  const anim::ClipPair clips = anim::defaultRunPair();
  const anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  synth::BodyParts parts = synth::describeBodyParts(clips.slow.skeleton);
  synth::setMeanCentres(parts, pair);
  const synth::CoverageParts levels = synth::makeCoverageParts(parts, {});
  const uint64_t bones = anim::drawnBoneMask(anim::placementJoints(pair));
  const uint32_t n = uint32_t(pair.jointCount());
  crowd::ScenarioOptions scenario;
  scenario.characters = characters;
  scenario.seed = 5;
  const crowd::Crowd crowd = crowd::makeScenario(scenario);
  std::vector<synth::JointPoint> joints(crowd.size() * n);
  synth::poseCrowdCpu(pair, crowd, joints, 2);
  const render::Camera camera = render::cameraPreset(preset, crowd::scenarioExtent(scenario));
  std::vector<synth::CoverageMask> masks(crowd.size());
  synth::coverageCpu(
      synth::coverageCamera(camera.view(), camera.fovYDegrees, width, height, camera.nearPlane),
      levels, n, crowd, {}, masks, {});
  render::DrawParams params;
  params.camera = camera;
  params.width = width;
  params.height = height;
  const gpu_types::FrameUniforms frame = render::makeFrameUniforms(params);
  const float maxPixels = 24.0f;
  const render::SplatInputsCpu perJoint =
      render::splatInputsCpu(joints, pair.parents, bones, masks, &levels, frame, maxPixels, 0.0f);
  const render::SplatInputsCpu withBodies =
      render::splatInputsCpu(joints, pair.parents, bones, masks, &levels, frame, maxPixels);
  FarComparison out;
  out.bodies = withBodies.bodies.size();
  out.shortest = 1e9f;
  for (const render::FarBodyCpu& body : withBodies.bodies) {
    const render::JointSpriteCpu s = render::jointSpriteCpu(body.body, frame);
    out.shortest = std::min(out.shortest, s.hi.y - s.lo.y);
    out.tallest = std::max(out.tallest, s.hi.y - s.lo.y);
  }
  const auto a =
      render::splatJointsCpu(perJoint.joints, frame, n, maxPixels, width, height).visibility;
  auto b = render::splatJointsCpu(withBodies.joints, frame, n, maxPixels, width, height).visibility;
  render::splatFarBodiesCpu(withBodies.bodies, frame, width, height, b);
  for (size_t i = 0; i < a.size(); ++i) {
    out.jointPixels += a[i] != render::kEmptyPixel;
    out.bodyPixels += b[i] != render::kEmptyPixel;
  }
  const ImageRgba8 ia = imageOf(a, int(width), int(height));
  const ImageRgba8 ib = imageOf(b, int(width), int(height));
  out.pixels = compareImages(ib, ia, 24);
  out.blocks = compareImages(blockMeans(ib, 8), blockMeans(ia, 8), 24);
  MESSAGE(preset, " camera, ", characters, " characters at ", width, "x", height, ": ", out.bodies,
          " far bodies ", out.shortest, "..", out.tallest, " px tall; pixels covered ",
          out.jointPixels, " per joint, ", out.bodyPixels, " with the bodies; per pixel mean ",
          out.pixels.meanAbsError, " (", 100.0 * out.pixels.fractionDifferent,
          "% over 24), 8x8 blocks mean ", out.blocks.meanAbsError, " (",
          100.0 * out.blocks.fractionDifferent, "% over 24)");
  return out;
}

}  // namespace

// The bound: the bodies cover as many pixels as the joints they stand for (-15% to +15%), and
// seen as 8×8 blocks the frame is the same (mean error at most 3.5 levels of 255, no more than
// 0.1% of blocks off by more than 24). Single pixels do move (a body is not its limbs, and it
// is shaded once): the per-pixel mean error is at most 10 levels. Measured with the CPU twins,
// 100,000 characters at 1280x720 (the bench's whole frame): wide camera 74,052 bodies
// 2.4..5.5 px tall, coverage +4.4%, blocks mean 2.88 (0.007% over 24), pixels mean 8.47;
// street camera 73,532 bodies, coverage equal, blocks mean 0.05, pixels mean 0.09.
TEST_CASE("far body: the crowd far away looks as with every far joint splatted") {
  for (const char* preset : {"wide", "street"}) {
    CAPTURE(preset);
    const FarComparison f = compareFar(100000, preset, 1280, 720);
    CHECK(f.bodies > 50000);
    CHECK(f.tallest < gpu_types::kSplatFarBodyPixels);
    const double coverage = double(f.bodyPixels) / double(std::max<size_t>(f.jointPixels, 1));
    CHECK(coverage > 0.85);
    CHECK(coverage < 1.15);
    CHECK(f.blocks.meanAbsError <= 3.5);
    CHECK(f.blocks.fractionDifferent <= 0.001);
    CHECK(f.pixels.meanAbsError <= 10.0);
  }
}

TEST_CASE("far body: its pixels reach the frame through both resolves alike") {
  gpu::Context& ctx = test::gpuContext();
  if (!ctx.info().int64Atomics) {
    MESSAGE("SKIPPED: device lacks 64-bit buffer atomics (no splat)");
    return;
  }
  const anim::ClipPair clips = anim::defaultRunPair();
  const anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  crowd::ScenarioOptions scenario;
  scenario.characters = 3000;
  scenario.seed = 5;
  const crowd::Crowd crowd = crowd::makeScenario(scenario);
  const render::Camera camera = render::cameraPreset("wide", crowd::scenarioExtent(scenario));
  synth::LodOptions lod;
  lod.enabled = true;
  lod.skeleton = &clips.slow.skeleton;
  const std::array<ImageRgba8, 2> images = test::renderBothResolves(ctx, crowd, pair, camera, lod);
  const ImageDiff diff = compareImages(images[1], images[0], 2);
  MESSAGE(
      "wide, 3000 characters at 320x180 with LOD: splat over the ground's words vs full-screen "
      "pass: mean ",
      diff.meanAbsError, ", max ", diff.maxError);
  CHECK(diff.maxError <= 2);
  CHECK(diff.meanAbsError < 0.05);
  CHECK(ctx.validationMessageCount() == 0);
}
