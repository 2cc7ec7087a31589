#include "render/camera_path.h"

#include <algorithm>

namespace throng::render {

Camera cameraAt(std::span<const CameraKey> path, float seconds, Camera base) {
  if (path.empty()) return base;
  // The first keyframe after `seconds`; before the first or after the last the camera holds.
  const auto next = std::upper_bound(path.begin(), path.end(), seconds,
                                     [](float t, const CameraKey& k) { return t < k.seconds; });
  const CameraKey& a = next == path.begin() ? path.front() : *(next - 1);
  const CameraKey& b = next == path.end() ? path.back() : *next;
  const float span = b.seconds - a.seconds;
  const float t = span > 0.0f ? std::clamp((seconds - a.seconds) / span, 0.0f, 1.0f) : 0.0f;
  base.eye = glm::mix(a.eye, b.eye, t);
  base.target = glm::mix(a.target, b.target, t);
  base.fovYDegrees = a.fovYDegrees + (b.fovYDegrees - a.fovYDegrees) * t;
  return base;
}

}  // namespace throng::render
