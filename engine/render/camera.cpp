#include "render/camera.h"

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"

namespace throng::render {

glm::mat4 Camera::view() const {
  return glm::lookAtRH(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 Camera::projection(float aspect) const {
  glm::mat4 p = glm::perspectiveRH_ZO(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
  p[1][1] *= -1.0f;  // Vulkan's clip space has y pointing down
  return p;
}

float Camera::focalLengthPixels(float height) const {
  return 0.5f * height / std::tan(0.5f * glm::radians(fovYDegrees));
}

Camera cameraPreset(const std::string& name, float extent) {
  Camera c;
  extent = std::max(extent, 5.0f);
  if (name == "wide") {
    c.eye = glm::vec3(0.0f, 0.62f * extent + 6.0f, -1.05f * extent - 6.0f);
    c.target = glm::vec3(0.0f, 0.0f, -0.15f * extent);
  } else if (name == "top") {
    c.eye = glm::vec3(0.0f, 2.4f * extent + 10.0f, -0.02f * extent - 0.5f);
    c.target = glm::vec3(0.0f);
  } else if (name == "street") {
    c.eye = glm::vec3(0.0f, 1.7f, -extent - 4.0f);
    c.target = glm::vec3(0.0f, 1.2f, 0.0f);
    c.fovYDegrees = 60.0f;
  } else if (name == "closeup") {
    c.eye = glm::vec3(3.0f, 2.2f, -7.0f);
    c.target = glm::vec3(0.0f, 0.9f, 0.0f);
    c.fovYDegrees = 40.0f;
  } else {
    fail("unknown camera preset '", name, "': expected wide, top, street or closeup");
  }
  c.farPlane = std::max(500.0f, 6.0f * extent);
  return c;
}

Camera overheadCamera(float extent, float groundShare, float aspect) {
  THRONG_CHECK(extent > 0.0f && groundShare > 0.0f && aspect > 0.0f,
               "overhead camera: extent, share and aspect must be positive");
  Camera c;
  // The ground seen from height h is 2·h·tan(fov/2) tall and aspect times that wide.
  const float halfTan = std::tan(0.5f * glm::radians(c.fovYDegrees));
  const float height = extent * std::sqrt(groundShare / aspect) / halfTan;
  // Not quite straight down: the view's up vector is +y.
  c.eye = glm::vec3(0.0f, height, -0.01f * height);
  c.target = glm::vec3(0.0f);
  c.farPlane = std::max(500.0f, 2.0f * height);
  return c;
}

glm::vec3 parseVec3(const std::string& text, const std::string& what) {
  glm::vec3 v;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &tail) != 3 ||
      !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    fail(what, ": expected three numbers 'x,y,z', got '", text, "'");
  return v;
}

}  // namespace throng::render
