#pragma once
// A perspective camera (Vulkan clip space: y down, depth 0..1) and the named presets.
#include <string>

#include <glm/glm.hpp>

namespace throng::render {

struct Camera {
  glm::vec3 eye{0.0f, 40.0f, -60.0f};
  glm::vec3 target{0.0f};
  float fovYDegrees = 45.0f;
  float nearPlane = 0.1f;
  float farPlane = 2000.0f;

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  glm::mat4 viewProjection(float aspect) const { return projection(aspect) * view(); }
  // Focal length in pixels for a viewport `height` pixels tall (the paper's eq. 9, docs/design.md's
  // f).
  float focalLengthPixels(float height) const;
};

// "wide" (high, top-down-ish view of the whole crowd), "street" (eye height inside the crowd),
// "closeup" (a few characters fill the frame). `extent` is the crowd's half-size in metres.
// Throws Error naming the valid presets for anything else.
Camera cameraPreset(const std::string& name, float extent);

// Looking down on the middle of a crowd `extent` metres in half-size from the height at which
// the view (fovYDegrees 45, `aspect` = width / height) covers `groundShare` of its square: the
// bench's view of a big crowd of which only a part is on screen.
Camera overheadCamera(float extent, float groundShare, float aspect);

// "x,y,z" → vector; throws Error naming `what` on malformed text.
glm::vec3 parseVec3(const std::string& text, const std::string& what);

}  // namespace throng::render
