#include <doctest/doctest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "synth/coverage.h"

// The closed-form sphere coverage (the paper's eqs. 1–9, docs/design.md) against pixels counted by ray casting.
using namespace throng;

namespace {

constexpr uint32_t kW = 1280, kH = 720;

synth::CoverageCamera lookCamera(glm::vec3 eye, glm::vec3 target) {
  return synth::coverageCamera(glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f)), 45.0f, kW, kH, 0.1f);
}

// Ray-casts every pixel centre of a W×H image against the sphere (camera space looking down +z,
// principal point at the image centre) and counts hits. `edge` tells whether a border pixel was
// hit (the sphere is then partly off screen).
uint64_t bruteForcePixels(glm::dvec3 o, double r, double f, bool& edge) {
  uint64_t hits = 0;
  edge = false;
  const double c = glm::dot(o, o) - r * r;
  for (uint32_t py = 0; py < kH; ++py) {
    for (uint32_t px = 0; px < kW; ++px) {
      glm::dvec3 d((px + 0.5 - 0.5 * kW) / f, (py + 0.5 - 0.5 * kH) / f, 1.0);
      double b = glm::dot(d, o), dd = glm::dot(d, d);
      double disc = b * b - dd * c;
      if (disc < 0.0 || b + std::sqrt(disc) <= 0.0) continue;
      ++hits;
      edge = edge || px == 0 || py == 0 || px == kW - 1 || py == kH - 1;
    }
  }
  return hits;
}

}  // namespace

TEST_CASE("sphere coverage: closed-form ellipse area against a brute-force pixel count") {
  // A camera away from the origin and tilted, so the view matrix is exercised too.
  synth::CoverageCamera camera = lookCamera(glm::vec3(3.0f, 2.0f, -5.0f), glm::vec3(0.0f, 1.0f, 10.0f));
  synth::CoveragePush push = synth::makeCoveragePush(camera, 1, 0, 1, 0);
  const glm::mat4 toWorld = glm::inverse(camera.view);
  const double f = camera.focalPixels;
  const float depths[] = {1.6f, 3.0f, 7.0f, 15.0f, 40.0f, 120.0f, 300.0f};
  const glm::vec2 spots[] = {{0.0f, 0.0f}, {0.5f, 0.3f}, {-0.7f, 0.55f}, {0.35f, -0.75f}, {-0.85f, -0.8f}, {0.9f, 0.1f}};
  const float radii[] = {0.25f, 0.6f};
  float worstLarge = 0.0f, worstMid = 0.0f, worstSmallPixels = 0.0f;
  int compared = 0, offScreen = 0;
  for (float z : depths) {
    for (glm::vec2 s : spots) {
      for (float r : radii) {
        // Camera space (x right, y down, +z forward) → world through the lookAt's inverse.
        glm::vec3 o(s.x * z * 0.5f * kW / float(f), s.y * z * 0.5f * kH / float(f), z);
        glm::vec3 world = glm::vec3(toWorld * glm::vec4(o.x, -o.y, -o.z, 1.0f));
        bool edge = false;
        double counted = double(bruteForcePixels(glm::dvec3(o), r, f, edge));
        float area = synth::sphereCoveragePixels(push, world, r);
        if (edge) {
          ++offScreen;
          CHECK(area >= float(counted));  // partly off screen: the full ellipse is counted
          continue;
        }
        ++compared;
        float err = float(std::abs(area - counted) / counted);
        if (counted >= 400.0) {
          worstLarge = std::max(worstLarge, err);
          CHECK_MESSAGE(err <= 0.05f, "z ", z, " spot ", s.x, ",", s.y, " r ", r, ": ", area, " vs ", counted);
        } else if (counted >= 20.0) {
          worstMid = std::max(worstMid, err);
          CHECK_MESSAGE(err <= 0.15f, "z ", z, " r ", r, ": ", area, " vs ", counted);
        } else {
          worstSmallPixels = std::max(worstSmallPixels, float(std::abs(area - counted)));
          CHECK_MESSAGE(std::abs(area - counted) <= 6.0, "z ", z, " r ", r, ": ", area, " vs ", counted);
        }
      }
    }
  }
  MESSAGE("closed form vs brute force over ", compared, " on-screen spheres (", offScreen,
          " partly off screen): worst relative error ", worstLarge, " (>= 400 px), ", worstMid,
          " (20-400 px); worst absolute ", worstSmallPixels, " px (< 20 px)");
  CHECK(compared >= 60);
  CHECK(offScreen >= 4);
}

TEST_CASE("sphere coverage: behind, containing, straddling, clipped and off-screen spheres") {
  synth::CoverageCamera camera = lookCamera(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
  synth::CoveragePush push = synth::makeCoveragePush(camera, 1, 0, 1, 0);
  const float screen = float(kW) * float(kH);
  // lookAt towards +z: camera x is world −x, camera depth is world +z.
  CHECK(synth::sphereCoveragePixels(push, {0.0f, 0.0f, -5.0f}, 1.0f) == 0.0f);   // behind
  CHECK(synth::sphereCoveragePixels(push, {0.0f, 0.0f, -0.5f}, 0.4f) == 0.0f);   // behind, close
  CHECK(synth::sphereCoveragePixels(push, {0.2f, 0.1f, 0.3f}, 1.0f) == screen);  // contains the camera
  CHECK(synth::sphereCoveragePixels(push, {0.0f, 0.0f, 0.05f}, 0.06f) == screen);
  CHECK(synth::sphereCoveragePixels(push, {0.0f, 0.0f, 0.5f}, 1.0f) == screen);  // straddles (contains too)
  CHECK(synth::sphereCoveragePixels(push, {0.0f, 1.2f, 0.5f}, 1.0f) == screen);  // straddles, camera outside
  CHECK(synth::sphereCoveragePixels(push, {0.0f, 0.0f, 0.03f}, 0.02f) == 0.0f);  // wholly nearer than near
  CHECK(synth::sphereCoveragePixels(push, {40.0f, 0.0f, 10.0f}, 1.0f) == 0.0f);  // off to a side
  CHECK(synth::sphereCoveragePixels(push, {0.0f, -30.0f, 10.0f}, 1.0f) == 0.0f); // below
  CHECK(synth::sphereCoveragePixels(push, {-6.0f, 0.0f, 10.0f}, 2.0f) > 0.0f);   // straddles the right edge
  CHECK(synth::sphereCoveragePixels(push, {0.0f, 0.0f, 1.5f}, 1.4f) == screen);  // huge ellipse: clamped
  // On the axis the closed form is the disc seen through the tangent cone: π f² r²/(z² − r²).
  const float f = camera.focalPixels;
  CHECK(synth::sphereCoveragePixels(push, {0.0f, 0.0f, 20.0f}, 0.5f) ==
        doctest::Approx(3.14159265f * f * f * 0.25f / (400.0f - 0.25f)).epsilon(1e-5));
}
