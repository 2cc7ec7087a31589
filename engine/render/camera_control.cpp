#include "render/camera_control.h"

#include <algorithm>
#include <cmath>

namespace throng::render {
namespace {

struct Basis {
  glm::vec3 forward, right, up;
};

Basis viewBasis(const Camera& camera) {
  glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  glm::vec3 side = glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f));
  // Looking straight up or down: any horizontal right vector will do.
  glm::vec3 right = glm::length(side) > 1e-6f ? glm::normalize(side) : glm::vec3(1.0f, 0.0f, 0.0f);
  return {forward, right, glm::cross(right, forward)};
}

// A move that would leave the camera non-finite (or past float range) is dropped.
bool finiteMove(const Camera& camera, glm::vec3 delta) {
  const glm::vec3 eye = camera.eye + delta, target = camera.target + delta;
  return std::isfinite(eye.x) && std::isfinite(eye.y) && std::isfinite(eye.z) &&
         std::isfinite(target.x) && std::isfinite(target.y) && std::isfinite(target.z) &&
         eye != target;
}

}  // namespace

float cameraDistance(const Camera& camera) {
  return glm::length(camera.eye - camera.target);
}

float cameraPitchDegrees(const Camera& camera) {
  glm::vec3 offset = camera.eye - camera.target;
  return glm::degrees(std::asin(std::clamp(offset.y / glm::length(offset), -1.0f, 1.0f)));
}

float cameraYawDegrees(const Camera& camera) {
  glm::vec3 offset = camera.eye - camera.target;
  return glm::degrees(std::atan2(offset.x, offset.z));
}

void orbitCamera(Camera& camera, float dxPixels, float dyPixels) {
  if (!std::isfinite(dxPixels) || !std::isfinite(dyPixels)) return;
  float distance = cameraDistance(camera);
  // Whole turns dropped first: a huge drag keeps the angle's precision (and stays finite).
  const float turn = std::fmod(dxPixels * kOrbitDegreesPerPixel, 360.0f);
  float yaw = glm::radians(cameraYawDegrees(camera) - turn);
  float pitch =
      glm::radians(std::clamp(cameraPitchDegrees(camera) + dyPixels * kOrbitDegreesPerPixel,
                              -kMaxPitchDegrees, kMaxPitchDegrees));
  glm::vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                   std::cos(pitch) * std::cos(yaw));
  camera.eye = camera.target + distance * offset;
}

void panCamera(Camera& camera, float dxPixels, float dyPixels, float viewportHeight) {
  if (viewportHeight <= 0.0f) return;
  Basis b = viewBasis(camera);
  float metresPerPixel = 2.0f * cameraDistance(camera) *
                         std::tan(0.5f * glm::radians(camera.fovYDegrees)) / viewportHeight;
  glm::vec3 delta = (-dxPixels * b.right + dyPixels * b.up) * metresPerPixel;
  if (!finiteMove(camera, delta)) return;
  camera.eye += delta;
  camera.target += delta;
}

void zoomCamera(Camera& camera, float steps) {
  if (!std::isfinite(steps)) return;
  glm::vec3 offset = camera.eye - camera.target;
  float distance = glm::length(offset);
  float wanted = std::clamp(distance * std::pow(kZoomPerStep, steps), kMinDistance,
                            std::max(kMinDistance, 0.5f * camera.farPlane));
  camera.eye = camera.target + offset * (wanted / distance);
}

float flySpeed(const Camera& camera) {
  return std::max(4.0f, 0.6f * cameraDistance(camera));
}

void flyCamera(Camera& camera, glm::vec3 axes, float seconds, float speedFactor) {
  if (seconds <= 0.0f || axes == glm::vec3(0.0f)) return;
  Basis b = viewBasis(camera);
  glm::vec3 direction =
      axes.x * b.right + axes.y * glm::vec3(0.0f, 1.0f, 0.0f) + axes.z * b.forward;
  glm::vec3 delta = direction * (flySpeed(camera) * speedFactor * seconds);
  if (!finiteMove(camera, delta)) return;
  camera.eye += delta;
  camera.target += delta;
}

}  // namespace throng::render
