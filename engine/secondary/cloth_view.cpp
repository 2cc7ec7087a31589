#include "secondary/cloth_view.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "shaders/shared_types.h"

namespace throng::secondary {

gpu_types::ClothView makeClothView(const render::Camera& camera, uint32_t width, uint32_t height,
                                   const ClothLod& lod, const ClothLodSettings& settings,
                                   bool splat) {
  THRONG_CHECK(width > 0 && height > 0, "empty viewport");
  gpu_types::ClothView v{};
  v.viewProjection = camera.viewProjection(float(width) / float(height));
  // Gribb–Hartmann planes of Vulkan clip space: -w ≤ x, y ≤ w and 0 ≤ z ≤ w.
  const glm::mat4 m = glm::transpose(v.viewProjection);
  const glm::vec4 planes[6] = {m[3] + m[0], m[3] - m[0], m[3] + m[1],
                               m[3] - m[1], m[2],        m[3] - m[2]};
  for (int p = 0; p < 6; ++p) v.planes[p] = planes[p] / glm::length(glm::vec3(planes[p]));
  v.eye = glm::vec4(camera.eye, camera.focalLengthPixels(float(height)));
  v.lod = glm::vec4(settings.level0Pixels, settings.level1Pixels, settings.level2Pixels,
                    settings.enabled ? 1.0f : 0.0f);
  v.bounds = glm::vec4(lod.center, lod.radius);
  v.light = glm::vec4(glm::normalize(glm::vec3(0.45f, 0.8f, -0.35f)), lod.shapeRadius);
  v.viewport = glm::vec4(float(width), float(height), splat ? 1.0f : 0.0f, 0.0f);
  return v;
}

glm::vec3 placeClothVertex(glm::vec4 placement, float scale, glm::vec3 p) {
  const float c = std::cos(placement.w), s = std::sin(placement.w);
  p *= scale;
  return glm::vec3(placement) + glm::vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
}

uint32_t clothLevel(const gpu_types::ClothView& view, glm::vec4 placement, float scale) {
  const glm::vec3 centre = placeClothVertex(placement, scale, glm::vec3(view.bounds));
  const float radius = scale * view.bounds.w;
  for (const glm::vec4& plane : view.planes)
    if (glm::dot(glm::vec3(plane), centre) + plane.w < -radius) return gpu_types::kClothNone;
  if (view.lod.w == 0.0f) return 0;
  const float distance = std::max(glm::length(centre - glm::vec3(view.eye)), 1e-3f);
  const float diameter = 2.0f * view.eye.w * scale * view.light.w / distance;
  return diameter >= view.lod.x   ? 0u
         : diameter >= view.lod.y ? 1u
         : diameter >= view.lod.z ? 2u
                                  : 3u;
}

uint32_t shownState(const PlaybackTables& t, const ClothCharacter& c, uint32_t level) {
  if (level < gpu_types::kClothSharedLevel) return c.state;
  const uint32_t first = t.firstStateAtNode[c.node];
  return first == kNoClothState ? c.state : first;
}

bool showsBlend(const ClothCharacter& c, uint32_t level) {
  return level < gpu_types::kClothSharedLevel && c.countdown > 0 && c.blendSource != kNoClothState;
}

ClothMarks markCharacters(const gpu_types::ClothView& view, const PlaybackTables& tables,
                          uint32_t stateCount, std::span<const ClothCharacter> characters,
                          std::span<const glm::vec4> placement, std::span<const glm::vec4> motion) {
  ClothMarks marks;
  marks.stateLevel.assign(stateCount, gpu_types::kClothNone);
  auto mark = [&](uint32_t state, uint32_t level) {
    uint32_t& l = marks.stateLevel[state];
    if (l == gpu_types::kClothNone) ++marks.usedStates;
    l = std::min(l, level);
  };
  for (uint32_t i = 0; i < characters.size(); ++i) {
    const ClothCharacter& c = characters[i];
    if (c.state == kNoClothState) continue;
    const uint32_t level = clothLevel(view, placement[i], gpu_types::characterScale(motion[i]));
    if (level == gpu_types::kClothNone) continue;
    mark(shownState(tables, c, level), level);
    if (showsBlend(c, level)) mark(c.blendSource, level);
    marks.drawLists[level].push_back(i);
  }
  return marks;
}

}  // namespace throng::secondary
