#pragma once
// A keyframed camera: eye, target and field of view at increasing times, interpolated linearly
// between keyframes and held before the first and after the last.
#include <span>

#include <glm/glm.hpp>

#include "render/camera.h"

namespace throng::render {

struct CameraKey {
  float seconds = 0.0f;
  glm::vec3 eye{0.0f}, target{0.0f};
  float fovYDegrees = 45.0f;
};

// `base` with the path's eye, target and field of view at `seconds` (base itself when the path is
// empty). Keyframe times must increase.
Camera cameraAt(std::span<const CameraKey> path, float seconds, Camera base);

}  // namespace throng::render
