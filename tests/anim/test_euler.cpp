// Euler → quaternion: every channel order against matrices built from glm::rotate.
#include <array>
#include <vector>

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "anim/euler.h"
#include "core/error.h"
#include "core/math.h"
#include "core/rng.h"

using throng::anim::Channel;
using throng::anim::channelsToQuat;

namespace {

glm::vec3 axisOf(Channel c) {
  switch (c) {
    case Channel::Xrotation: return {1, 0, 0};
    case Channel::Yrotation: return {0, 1, 0};
    default: return {0, 0, 1};
  }
}

// R = R(first) * R(second) * R(third), as BVH defines it.
glm::mat3 referenceMatrix(const std::array<Channel, 3>& order, const std::array<float, 3>& deg) {
  glm::mat4 m(1.0f);
  for (int i = 0; i < 3; ++i) m = glm::rotate(m, glm::radians(deg[i]), axisOf(order[i]));
  return glm::mat3(m);
}

glm::mat3 quatMatrix(glm::vec4 q) { return glm::mat3_cast(throng::toQuat(q)); }

float maxDiff(const glm::mat3& a, const glm::mat3& b) {
  float d = 0.0f;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  return d;
}

const std::array<std::array<Channel, 3>, 6> kOrders = {{
    {Channel::Xrotation, Channel::Yrotation, Channel::Zrotation},
    {Channel::Xrotation, Channel::Zrotation, Channel::Yrotation},
    {Channel::Yrotation, Channel::Xrotation, Channel::Zrotation},
    {Channel::Yrotation, Channel::Zrotation, Channel::Xrotation},
    {Channel::Zrotation, Channel::Xrotation, Channel::Yrotation},
    {Channel::Zrotation, Channel::Yrotation, Channel::Xrotation},
}};

glm::vec4 quatOf(const std::array<Channel, 3>& order, const std::array<float, 3>& deg) {
  return channelsToQuat(order, deg);
}

}  // namespace

TEST_CASE("a single 90 degree rotation about each axis turns the next axis into the one after") {
  const float s = std::sqrt(0.5f);
  glm::vec4 qx = throng::anim::axisRotation(Channel::Xrotation, 90.0f);
  glm::vec4 qy = throng::anim::axisRotation(Channel::Yrotation, 90.0f);
  glm::vec4 qz = throng::anim::axisRotation(Channel::Zrotation, 90.0f);
  CHECK(qx.x == doctest::Approx(s));
  CHECK(qx.w == doctest::Approx(s));
  CHECK(qy.y == doctest::Approx(s));
  CHECK(qz.z == doctest::Approx(s));
  // Right-handed: X: y → z, Y: z → x, Z: x → y.
  glm::vec3 a = throng::quatRotate(qx, {0, 1, 0});
  glm::vec3 b = throng::quatRotate(qy, {0, 0, 1});
  glm::vec3 c = throng::quatRotate(qz, {1, 0, 0});
  CHECK(glm::length(a - glm::vec3(0, 0, 1)) < 1e-6f);
  CHECK(glm::length(b - glm::vec3(1, 0, 0)) < 1e-6f);
  CHECK(glm::length(c - glm::vec3(0, 1, 0)) < 1e-6f);
  // Position channels rotate nothing.
  CHECK(throng::anim::axisRotation(Channel::Xposition, 90.0f) == glm::vec4(0, 0, 0, 1));
}

TEST_CASE("the first-listed axis is the outermost rotation") {
  // Xrotation Zrotation Yrotation with X = Z = 90: R = Rx * Rz, so x → (Rz) y → (Rx) z.
  glm::vec4 xz = quatOf({Channel::Xrotation, Channel::Zrotation, Channel::Yrotation}, {90, 90, 0});
  CHECK(glm::length(throng::quatRotate(xz, {1, 0, 0}) - glm::vec3(0, 0, 1)) < 1e-6f);
  // Zrotation Xrotation Yrotation with Z = X = 90: R = Rz * Rx, so x → (Rx) x → (Rz) y.
  glm::vec4 zx = quatOf({Channel::Zrotation, Channel::Xrotation, Channel::Yrotation}, {90, 90, 0});
  CHECK(glm::length(throng::quatRotate(zx, {1, 0, 0}) - glm::vec3(0, 1, 0)) < 1e-6f);
  // And y under Rz * Rx: y → z → z.
  CHECK(glm::length(throng::quatRotate(zx, {0, 1, 0}) - glm::vec3(0, 0, 1)) < 1e-6f);
}

TEST_CASE("all six channel orders match glm::rotate compositions") {
  const std::vector<std::array<float, 3>> angleSets = {
      {90, 0, 0}, {0, 90, 0}, {0, 0, 90}, {90, 90, 0}, {0, 90, 90}, {90, 90, 90},
      {30, -45, 60}, {-170, 80, 15}, {12.5f, 200, -95}, {720, -361, 45}};
  for (const auto& order : kOrders) {
    for (const auto& deg : angleSets) {
      glm::vec4 q = quatOf(order, deg);
      CAPTURE(int(order[0]));
      CAPTURE(int(order[1]));
      CAPTURE(deg[0]);
      CAPTURE(deg[1]);
      CAPTURE(deg[2]);
      CHECK(glm::length(q) == doctest::Approx(1.0f).epsilon(1e-6));
      CHECK(maxDiff(quatMatrix(q), referenceMatrix(order, deg)) < 1e-5f);
    }
  }
}

TEST_CASE("the six orders give six different rotations for the same angles") {
  std::vector<glm::mat3> results;
  for (const auto& order : kOrders) results.push_back(quatMatrix(quatOf(order, {30, 45, 60})));
  for (size_t i = 0; i < results.size(); ++i)
    for (size_t j = i + 1; j < results.size(); ++j) CHECK(maxDiff(results[i], results[j]) > 0.05f);
}

TEST_CASE("random angles in every order: unit length and the reference matrix") {
  throng::Rng rng(1234);
  for (int i = 0; i < 2000; ++i) {
    const auto& order = kOrders[size_t(i) % kOrders.size()];
    std::array<float, 3> deg;
    for (float& d : deg) d = rng.uniform(-720.0f, 720.0f);
    glm::vec4 q = quatOf(order, deg);
    REQUIRE(std::abs(glm::length(q) - 1.0f) < 1e-6f);
    REQUIRE(maxDiff(quatMatrix(q), referenceMatrix(order, deg)) < 2e-5f);
  }
}

TEST_CASE("position channels are skipped wherever they appear") {
  const std::array<Channel, 6> channels = {Channel::Xposition, Channel::Yposition,
                                           Channel::Zposition, Channel::Zrotation,
                                           Channel::Yrotation, Channel::Xrotation};
  const std::array<float, 6> values = {100, -250, 3e4f, 10, 20, 30};
  glm::vec4 q = channelsToQuat(channels, values);
  glm::mat3 expected =
      referenceMatrix({Channel::Zrotation, Channel::Yrotation, Channel::Xrotation}, {10, 20, 30});
  CHECK(maxDiff(quatMatrix(q), expected) < 1e-5f);
  // Mismatched spans are a checked error, not a read past the end.
  CHECK_THROWS_AS(channelsToQuat(channels, std::span<const float>(values.data(), 5)),
                  throng::Error);
}
