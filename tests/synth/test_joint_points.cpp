// Joint points (gpu_types::JointPoint) and the draw matrices their readers rebuild
// (gpu_types::boneMatrix, synth::jointMatrices): the bone's ellipsoid must be the one a draw
// matrix A = M·O·F of the same bone gives, whatever two cross axes the rebuild picks.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "anim/default_clips.h"
#include "anim/reference_synth.h"
#include "core/rng.h"
#include "synth/joint_points.h"

using namespace throng;

namespace {

glm::vec3 column(const synth::JointMatrix& a, int c) {
  return {a.row0[c], a.row1[c], a.row2[c]};
}

// B·Bᵀ of the unit-sphere map (joint_sprite.glsl: B = [x, y/2, z]): the ellipsoid itself, the
// same for every choice of cross axes.
glm::mat3 ellipsoidForm(const synth::JointMatrix& a) {
  const glm::vec3 x = column(a, 0), y = 0.5f * column(a, 1), z = column(a, 2);
  return glm::outerProduct(x, x) + glm::outerProduct(y, y) + glm::outerProduct(z, z);
}

// The form of a bone from `start` along `axis`, round about it with radius r.
glm::mat3 expectedForm(glm::vec3 axis, float r) {
  const float length = glm::length(axis);
  const glm::vec3 n = axis / length;
  return r * r * (glm::mat3(1.0f) - glm::outerProduct(n, n)) +
         0.25f * length * length * glm::outerProduct(n, n);
}

float maxDifference(const glm::mat3& a, const glm::mat3& b) {
  float worst = 0.0f;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) worst = std::max(worst, std::abs(a[c][r] - b[c][r]));
  return worst;
}

}  // namespace

TEST_CASE("boneMatrix: the bone from the parent's point to the joint's, round about it") {
  Rng rng(11);
  float worstForm = 0.0f, worstAxes = 0.0f;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 parent(rng.uniform(-50.0f, 50.0f), rng.uniform(0.0f, 2.0f),
                           rng.uniform(-50.0f, 50.0f));
    glm::vec3 axis(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f));
    if (i % 7 == 0) axis = glm::vec3(0.0f, 0.0f, -0.3f);  // straight down -z: the basis's seam
    if (i % 11 == 0) axis = glm::vec3(0.0f, 0.4f, 0.0f);
    if (glm::length(axis) < 0.05f) continue;
    const float r = rng.uniform(0.01f, 0.1f);
    const synth::JointMatrix a =
        gpu_types::boneMatrix(glm::vec4(parent, 0.07f), glm::vec4(parent + axis, r), false);
    CHECK(column(a, 3) == parent);  // the bone starts at the parent
    CHECK(glm::length(column(a, 1) - axis) <= 1e-5f * (1.0f + glm::length(parent)));
    const glm::vec3 x = column(a, 0), z = column(a, 2), n = glm::normalize(axis);
    worstAxes = std::max({worstAxes, std::abs(glm::dot(x, n)), std::abs(glm::dot(z, n)),
                          std::abs(glm::dot(x, z)), std::abs(glm::length(x) - r),
                          std::abs(glm::length(z) - r)});
    worstForm = std::max(worstForm, maxDifference(ellipsoidForm(a), expectedForm(axis, r)));
    const glm::vec3 end =
        gpu_types::bonePoint(glm::vec4(parent, 0.07f), glm::vec4(parent + axis, r), false, 1.0f);
    CHECK(glm::length(end - (parent + axis)) <= 1e-5f * (1.0f + glm::length(parent)));
  }
  MESSAGE("cross axes off by at most ", worstAxes, "; ellipsoid form off by at most ", worstForm);
  CHECK(worstAxes <= 4e-6f);
  CHECK(worstForm <= 4e-6f);
}

TEST_CASE("boneMatrix: the root is a sphere around its point; a radius of 0 draws nothing") {
  const glm::vec4 root(3.0f, 0.9f, -2.0f, 0.12f);
  const synth::JointMatrix a = gpu_types::boneMatrix(root, root, true);
  CHECK(maxDifference(ellipsoidForm(a), glm::mat3(0.12f * 0.12f)) <= 1e-7f);
  CHECK(gpu_types::bonePoint(root, root, true, 0.5f) == glm::vec3(root));
  CHECK(gpu_types::bonePoint(root, root, true, 0.0f) == glm::vec3(3.0f, 0.9f - 0.12f, -2.0f));
  // A joint point of radius 0 (a zero-length bone): no cross axes, the sprite is never visible.
  const synth::JointMatrix none = gpu_types::boneMatrix(glm::vec4(1.0f, 1.0f, 1.0f, 0.1f),
                                                        glm::vec4(1.0f, 1.5f, 1.0f, 0.0f), false);
  CHECK(column(none, 0) == glm::vec3(0.0f));
  CHECK(column(none, 2) == glm::vec3(0.0f));
}

TEST_CASE("jointMatrices: a synthesized pose's bones run between its joints' positions") {
  const anim::ClipPair clips = anim::defaultRunPair();
  const anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  const size_t joints = size_t(pair.jointCount());
  std::vector<synth::JointPoint> points(2 * joints);
  const glm::vec4 placements[2] = {{4.0f, 0.0f, -7.0f, 0.8f}, {-30.0f, 0.0f, 12.0f, -2.4f}};
  const glm::vec4 motions[2] = {{0.3f, 0.2f, 0.2f, 1.1f}, {0.85f, 0.9f, 0.9f, 0.95f}};
  for (size_t c = 0; c < 2; ++c)
    anim::poseCharacter(pair, placements[c], motions[c],
                        std::span<glm::vec4>(&points[c * joints].positionRadius, joints));
  const std::vector<synth::JointMatrix> matrices = synth::jointMatrices(points, pair.parents);
  REQUIRE(matrices.size() == points.size());
  size_t drawn = 0;
  for (size_t c = 0; c < 2; ++c)
    for (size_t j = 0; j < joints; ++j) {
      const glm::vec4 point = points[c * joints + j].positionRadius;
      const synth::JointMatrix& a = matrices[c * joints + j];
      const int parent = pair.parents[j];
      const glm::vec3 start = parent < 0
                                  ? glm::vec3(point) - glm::vec3(0.0f, point.w, 0.0f)
                                  : glm::vec3(points[c * joints + size_t(parent)].positionRadius);
      CHECK(glm::length(column(a, 3) - start) <= 1e-5f);
      CHECK(glm::length(column(a, 3) + column(a, 1) -
                        (parent < 0 ? start + glm::vec3(0.0f, 2.0f * point.w, 0.0f)
                                    : glm::vec3(point))) <= 1e-4f);
      CHECK(glm::length(column(a, 0)) == doctest::Approx(point.w).epsilon(1e-5));
      drawn += point.w > 0.0f ? 1 : 0;
    }
  CHECK(drawn >= joints);  // both characters draw most of their bones
  CHECK_THROWS(synth::jointMatrices(std::span(points).first(joints + 1), pair.parents));
}
