// The viewer's camera moves: orbit keeps the target and distance, pan moves eye and target
// together by the pixel footprint at the target, zoom scales the distance within limits, and
// flight follows the view direction.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "render/camera_control.h"

using namespace throng;
using render::Camera;

namespace {
Camera sample() {
  Camera c;
  c.eye = {10.0f, 20.0f, -30.0f};
  c.target = {1.0f, 0.0f, 2.0f};
  c.fovYDegrees = 45.0f;
  return c;
}
}  // namespace

TEST_CASE("orbit: target and distance stay, yaw follows the horizontal drag, pitch the vertical") {
  Camera c = sample();
  const Camera before = c;
  render::orbitCamera(c, 100.0f, 0.0f);
  CHECK(c.target == before.target);
  CHECK(render::cameraDistance(c) == doctest::Approx(render::cameraDistance(before)).epsilon(1e-5));
  CHECK(render::cameraPitchDegrees(c) ==
        doctest::Approx(render::cameraPitchDegrees(before)).epsilon(1e-4));
  float yaw =
      std::remainder(render::cameraYawDegrees(c) - render::cameraYawDegrees(before), 360.0f);
  CHECK(yaw == doctest::Approx(-100.0f * render::kOrbitDegreesPerPixel));
  render::orbitCamera(c, 0.0f, 20.0f);
  CHECK(render::cameraPitchDegrees(c) ==
        doctest::Approx(render::cameraPitchDegrees(before) + 20.0f * render::kOrbitDegreesPerPixel)
            .epsilon(1e-4));
}

TEST_CASE("orbit: the pitch never flips over the pole") {
  Camera c = sample();
  render::orbitCamera(c, 0.0f, 10000.0f);
  CHECK(render::cameraPitchDegrees(c) == doctest::Approx(render::kMaxPitchDegrees).epsilon(1e-3));
  render::orbitCamera(c, 0.0f, -20000.0f);
  CHECK(render::cameraPitchDegrees(c) == doctest::Approx(-render::kMaxPitchDegrees).epsilon(1e-3));
  CHECK(std::isfinite(c.eye.x));
  CHECK(std::isfinite(c.eye.y));
}

TEST_CASE("pan: eye and target move by the same vector, one pixel = the footprint at the target") {
  Camera c = sample();
  const Camera before = c;
  const float height = 720.0f;
  render::panCamera(c, 36.0f, 0.0f, height);
  glm::vec3 moved = c.eye - before.eye;
  CHECK(glm::length(moved - (c.target - before.target)) < 1e-4f);
  float metresPerPixel =
      2.0f * render::cameraDistance(before) * std::tan(glm::radians(22.5f)) / height;
  CHECK(glm::length(moved) == doctest::Approx(36.0f * metresPerPixel).epsilon(1e-4));
  // Perpendicular to the view direction: the view itself is unchanged.
  CHECK(std::abs(glm::dot(moved, glm::normalize(before.target - before.eye))) < 1e-4f);
  render::panCamera(c, 10.0f, 10.0f, 0.0f);  // a zero-height viewport does nothing
  CHECK(glm::length(c.eye - before.eye - moved) < 1e-5f);
}

TEST_CASE("zoom: distance × 0.85 per step, clamped, direction kept") {
  Camera c = sample();
  const float d0 = render::cameraDistance(c);
  glm::vec3 dir0 = glm::normalize(c.eye - c.target);
  render::zoomCamera(c, 2.0f);
  CHECK(render::cameraDistance(c) == doctest::Approx(d0 * 0.85f * 0.85f).epsilon(1e-5));
  CHECK(glm::dot(glm::normalize(c.eye - c.target), dir0) > 0.999999f);
  render::zoomCamera(c, 500.0f);
  CHECK(render::cameraDistance(c) == doctest::Approx(render::kMinDistance).epsilon(1e-4));
  render::zoomCamera(c, -5000.0f);
  CHECK(render::cameraDistance(c) == doctest::Approx(0.5f * c.farPlane).epsilon(1e-4));
}

TEST_CASE("fly: forward follows the view, up is world up, speed scales with distance") {
  Camera c = sample();
  const Camera before = c;
  render::flyCamera(c, {0.0f, 0.0f, 1.0f}, 0.5f);
  glm::vec3 moved = c.eye - before.eye;
  CHECK(glm::length(moved) == doctest::Approx(0.5f * render::flySpeed(before)).epsilon(1e-4));
  CHECK(glm::dot(glm::normalize(moved), glm::normalize(before.target - before.eye)) > 0.99999f);
  CHECK(glm::length((c.target - before.target) - moved) < 1e-4f);

  Camera up = before;
  render::flyCamera(up, {0.0f, 1.0f, 0.0f}, 1.0f, 4.0f);
  CHECK(up.eye.x == doctest::Approx(before.eye.x));
  CHECK(up.eye.y - before.eye.y == doctest::Approx(4.0f * render::flySpeed(before)).epsilon(1e-4));

  Camera still = before;
  render::flyCamera(still, {1.0f, 0.0f, 0.0f}, 0.0f);  // no time, no motion
  CHECK(still.eye == before.eye);
}

namespace {
bool finite(const Camera& c) {
  return std::isfinite(c.eye.x) && std::isfinite(c.eye.y) && std::isfinite(c.eye.z) &&
         std::isfinite(c.target.x) && std::isfinite(c.target.y) && std::isfinite(c.target.z);
}
}  // namespace

TEST_CASE("camera moves: huge or non-finite inputs never make the camera NaN") {
  const float inf = std::numeric_limits<float>::infinity();
  const float huge[] = {1e30f, -1e30f, 3e38f, inf, -inf, std::nanf("")};
  for (float v : huge) {
    INFO(v);
    Camera c = sample();
    render::orbitCamera(c, v, 2.0f);
    CHECK(finite(c));
    render::orbitCamera(c, 2.0f, v);
    CHECK(finite(c));
    render::panCamera(c, v, v, 720.0f);
    CHECK(finite(c));
    render::zoomCamera(c, v);
    CHECK(finite(c));
    render::flyCamera(c, {1.0f, 0.0f, 1.0f}, v, 1.0f);
    CHECK(finite(c));
    CHECK(render::cameraDistance(c) > 0.0f);
  }
  // A large finite orbit keeps the distance and turns by the drag modulo whole turns.
  Camera c = sample();
  render::orbitCamera(c, 1e9f, 0.0f);
  CHECK(render::cameraDistance(c) ==
        doctest::Approx(render::cameraDistance(sample())).epsilon(1e-4));
}
