// The draw: a cape decoded on the GPU lands where its CPU-placed vertices project, seen from the
// front and from behind (two-sided), and a cape decoded coarser than drawn (a full fine pool)
// still covers the same place through the remap.
#include <doctest/doctest.h>

#include "playback_gpu_fixtures.h"
#include "secondary/cloth_decoder.h"

using namespace throng;
using namespace throng::secondary;

namespace {
constexpr uint32_t kWidth = 160, kHeight = 120;

ImageRgba8 renderCape(test::ClothGpuRun& run, render::OffscreenTarget& target) {
  gpu::submitAndWait(test::gpuContext(), [&](VkCommandBuffer cmd) {
    run.advanceJob().record(cmd, *run.programs);
    gpu::computeToComputeBarrier(cmd);
    run.markJob().record(cmd, *run.programs);
    run.decodeJob().record(cmd, *run.programs);
    gpu::transitionImage(
        cmd, target.color().get(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    gpu::transitionImage(
        cmd, target.depth.get(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL_KHR, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
        VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    VkRenderingAttachmentInfoKHR color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
    color.imageView = target.color().view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{0.0f, 0.0f, 0.0f, 1.0f}};
    VkRenderingAttachmentInfoKHR depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
    depth.imageView = target.depth.view();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL_KHR;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfoKHR rendering{VK_STRUCTURE_TYPE_RENDERING_INFO_KHR};
    rendering.renderArea = {{0, 0}, {kWidth, kHeight}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRenderingKHR(cmd, &rendering);
    VkViewport viewport{0.0f, 0.0f, float(kWidth), float(kHeight), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {kWidth, kHeight}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    run.drawJob().record(cmd, *run.programs);
    vkCmdEndRenderingKHR(cmd);
    gpu::transitionImage(cmd, target.color().get(), VK_IMAGE_ASPECT_COLOR_BIT,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, render::readbackLayout(target),
                         VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT);
    render::recordReadback(cmd, target);
  });
  return render::readbackImage(target);
}

struct Box {
  float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
};

// Pixel box of the character's cape from the CPU decode and placement.
Box projectedBox(const test::ClothGpuRun& run, const ClothCharacter& c) {
  DecodedBases d = dequantize(*run.db);
  std::vector<glm::vec3> p(run.db->vertexCount);
  decodeState(d, c.state, p);
  Box box;
  for (const glm::vec3& q : p) {
    glm::vec4 clip =
        run.viewData.viewProjection *
        glm::vec4(placeClothVertex(run.crowd.placement[0], run.crowd.motion[0].w, q), 1.0f);
    float x = (clip.x / clip.w * 0.5f + 0.5f) * kWidth,
          y = (clip.y / clip.w * 0.5f + 0.5f) * kHeight;
    box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x), std::max(box.y1, y)};
  }
  return box;
}

// Covered pixels inside and outside the box (grown by 2 px).
std::pair<int, int> coverage(const ImageRgba8& image, const Box& box) {
  int inside = 0, outside = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Rgba8& px = image.at(x, y);
      if (px.r == 0 && px.g == 0 && px.b == 0) continue;
      bool in =
          x + 2.0f >= box.x0 && x - 2.0f <= box.x1 && y + 2.0f >= box.y0 && y - 2.0f <= box.y1;
      (in ? inside : outside)++;
    }
  return {inside, outside};
}

ClothDatabase capeDatabase() {
  PlaybackPrimary p = test::syntheticPrimary(0.5f, {6, 5, 4});
  ClothDatabase db =
      test::randomDatabase(p, test::syntheticGraph(p, 2), test::gridMesh(16, 12), 4, 3);
  // Small bases: the cape stays a sheet near its rest shape.
  for (QuantizedBasis& b : db.bases) {
    b.offset *= 0.05f;
    b.step *= 0.05f;
  }
  return db;
}
}  // namespace

TEST_CASE("draw: the cape covers its projected place from the front and from behind") {
  ClothDatabase db = capeDatabase();
  std::vector<glm::vec4> placement = {{0.0f, 0.0f, 0.0f, 0.3f}},
                         motion = {{0.3f, 0.5f, 0.5f, 1.0f}};
  test::ClothGpuRun run(db, placement, motion);
  render::OffscreenTarget target = render::makeOffscreenTarget(test::gpuContext(), kWidth, kHeight);
  for (float side : {-1.0f, 1.0f}) {
    render::Camera camera;
    camera.eye = {0.0f, 1.2f, 2.2f * side};
    camera.target = {0.0f, 1.1f, 0.0f};
    run.setCamera(camera, kWidth, kHeight, {true, 120.0f, 40.0f, 15.0f});
    ImageRgba8 image = renderCape(run, target);
    ClothCharacter c = run.characters()[0];
    REQUIRE(c.state != kNoClothState);
    Box box = projectedBox(run, c);
    auto [inside, outside] = coverage(image, box);
    CHECK(outside == 0);
    CHECK(inside > 0.4f * (box.x1 - box.x0) * (box.y1 - box.y0));
  }
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("draw: a state decoded coarser than its draw level is drawn through the remap") {
  ClothDatabase db = capeDatabase();
  std::vector<glm::vec4> placement = {{0.0f, 0.0f, 0.0f, 0.0f}},
                         motion = {{0.3f, 0.5f, 0.5f, 1.0f}};
  test::ClothGpuRun run(db, placement, motion, 12);  // no room for a fine state
  render::OffscreenTarget target = render::makeOffscreenTarget(test::gpuContext(), kWidth, kHeight);
  render::Camera camera;
  camera.eye = {0.0f, 1.2f, -2.2f};
  camera.target = {0.0f, 1.1f, 0.0f};
  run.setCamera(camera, kWidth, kHeight, {false, 0.0f, 0.0f, 0.0f});
  ImageRgba8 image = renderCape(run, target);
  CHECK(readClothStats(run.buffers).demoted == 1);
  Box box = projectedBox(run, run.characters()[0]);
  auto [inside, outside] = coverage(image, box);
  CHECK(outside == 0);
  CHECK(inside > 0.25f * (box.x1 - box.x0) * (box.y1 - box.y0));
  CHECK(test::gpuContext().validationMessageCount() == 0);
}
