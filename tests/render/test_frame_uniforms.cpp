// The frame uniforms carry the skeleton's parents (a byte per joint), from which every render
// shader finds a joint's bone (joint_fetch.glsl jointParent); a draw whose parents do not match its
// joint count is refused before anything is recorded.
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

#include "core/error.h"
#include "render/crowd_renderer.h"

using namespace throng;

namespace {

// jointParent of joint_fetch.glsl, on the C++ side.
int parentOf(const gpu_types::FrameUniforms& frame, uint32_t j) {
  const uint32_t byte = (frame.jointParents[j / 16u][(j / 4u) % 4u] >> (8u * (j % 4u))) & 255u;
  return byte == gpu_types::kNoParent ? -1 : int(byte);
}

render::DrawParams drawOf(std::span<const int32_t> parents, uint32_t joints) {
  render::DrawParams params;
  params.width = 320;
  params.height = 180;
  params.characterCount = 10;
  params.jointCount = joints;
  params.jointParents = parents;
  return params;
}

}  // namespace

TEST_CASE("frame uniforms: every joint's parent, the root's as none") {
  std::vector<int32_t> parents(64);
  for (int32_t j = 0; j < 64; ++j) parents[size_t(j)] = j == 0 ? -1 : (j * 7) % j;
  const gpu_types::FrameUniforms frame = render::makeFrameUniforms(drawOf(parents, 64));
  for (uint32_t j = 0; j < 64; ++j) {
    CAPTURE(j);
    CHECK(parentOf(frame, j) == parents[j]);
  }
  const std::vector<int32_t> small = {-1, 0, 1, 1, 0};
  const gpu_types::FrameUniforms five = render::makeFrameUniforms(drawOf(small, 5));
  for (uint32_t j = 0; j < 5; ++j) CHECK(parentOf(five, j) == small[j]);
  for (uint32_t j = 5; j < 64; ++j) CHECK(parentOf(five, j) == -1);  // past the skeleton: none
}

TEST_CASE("frame uniforms: parents that do not match the joint count are refused") {
  const std::vector<int32_t> parents = {-1, 0, 1};
  CHECK_THROWS_WITH_AS(render::makeFrameUniforms(drawOf(parents, 4)),
                       doctest::Contains("3 joint parents for 4 joints"), throng::Error);
  CHECK_THROWS_WITH_AS(render::makeFrameUniforms(drawOf({}, 4)),
                       doctest::Contains("0 joint parents for 4 joints"), throng::Error);
  render::DrawParams ground = drawOf({}, 4);
  ground.characterCount = 0;  // nothing to draw: no skeleton needed
  CHECK_NOTHROW(render::makeFrameUniforms(ground));
}
