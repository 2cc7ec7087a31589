#include "secondary/cloth_splat_cpu.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "shaders/shared_types.h"

namespace throng::secondary {

glm::vec3 clothTint(uint32_t character) {
  uint32_t h = character * 747796405u + 2891336453u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  glm::vec3 random(float(h & 255u), float((h >> 8) & 255u), float((h >> 16) & 255u));
  return glm::mix(glm::vec3(0.55f, 0.1f, 0.12f), random / 255.0f, 0.35f);
}

glm::vec3 clothLevelTint(uint32_t level) {
  static const glm::vec3 tints[4] = {
      {0.2f, 0.75f, 0.3f}, {0.95f, 0.8f, 0.2f}, {0.95f, 0.5f, 0.15f}, {0.9f, 0.2f, 0.2f}};
  return tints[std::min(level, 3u)];
}

namespace {
float edge(glm::vec2 a, glm::vec2 b, glm::vec2 p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

constexpr int kNone = 0x3FFFFFFF;  // an empty box's corner (cloth_splat.comp)

uint32_t packColour(glm::vec4 c) {
  uint32_t out = 0;
  for (int i = 0; i < 4; ++i)
    out |= uint32_t(std::round(std::clamp(c[i], 0.0f, 1.0f) * 255.0f)) << (8 * i);
  return out;
}
}  // namespace

void splatCapesCpu(const SplatInputs& in, std::span<const uint32_t> splatted,
                   std::span<uint64_t> visibility) {
  const gpu_types::ClothView& view = *in.view;
  const int width = int(view.viewport.x), height = int(view.viewport.y);
  THRONG_CHECK(visibility.size() >= size_t(width) * height,
               "visibility buffer smaller than the view");
  const uint32_t level = gpu_types::kClothSplatLevel;
  const ClothLod& lod = *in.lod;
  const uint32_t n = lod.levelVertices[level];
  const uint32_t triangles = lod.indexCount[level] / 3;
  std::vector<glm::vec3> local(n), world(n), screen(n);
  std::vector<glm::vec3> plane0(triangles), plane1(triangles), planeZ(triangles);
  std::vector<float> r0(triangles), r1(triangles), rz(triangles);
  std::vector<uint32_t> colour(triangles);
  for (uint32_t character : splatted) {
    const ClothCharacter& c = in.characters[character];
    const uint32_t state = shownState(*in.tables, c, level);
    const uint32_t decodedAt = in.stateLevel[state];
    decodeStateSubset(*in.decoded, state, lod.order, lod.levelBases[decodedAt], local);
    const glm::vec4 place = in.placement[character];
    const float scale = gpu_types::characterScale(in.motion[character]);
    const glm::vec2 heading = scale * glm::vec2(std::cos(place.w), std::sin(place.w));
    for (uint32_t k = 0; k < n; ++k) {
      const glm::vec3 p = local[k];
      world[k] = glm::vec3(place) + glm::vec3(heading.x * p.x + heading.y * p.z, scale * p.y,
                                              -heading.y * p.x + heading.x * p.z);
      glm::vec4 clip = view.viewProjection * glm::vec4(world[k], 1.0f);
      screen[k] = glm::vec3((glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(view.viewport),
                            clip.z / clip.w);
    }
    const glm::vec3 base = view.viewport.w != 0.0f ? clothLevelTint(level) : clothTint(character);
    // Per triangle: planes a·x + b·y + c of b0, b1 and depth over the screen, its colour, and the
    // cape's pixel box (the union of the triangles' boxes); skipped triangles never cover.
    glm::ivec4 cape(kNone, kNone, -kNone, -kNone);
    for (uint32_t t = 0; t < triangles; ++t) {
      const uint32_t* tri = &lod.indices[lod.firstIndex[level] + 3 * t];
      const glm::vec3 p0 = screen[tri[0]], p1 = screen[tri[1]], p2 = screen[tri[2]];
      const float area = edge(glm::vec2(p0), glm::vec2(p1), glm::vec2(p2));
      const glm::vec2 lo = glm::min(glm::min(glm::vec2(p0), glm::vec2(p1)), glm::vec2(p2));
      const glm::vec2 hi = glm::max(glm::max(glm::vec2(p0), glm::vec2(p1)), glm::vec2(p2));
      const glm::ivec2 from = glm::max(glm::ivec2(glm::ceil(lo - 0.5f)), glm::ivec2(0));
      const glm::ivec2 to =
          glm::min(glm::ivec2(glm::floor(hi - 0.5f)), glm::ivec2(width, height) - 1);
      const bool skip = std::abs(area) < 1e-8f || from.x > to.x || from.y > to.y;
      if (!skip)
        cape =
            glm::ivec4(glm::min(glm::ivec2(cape), from), glm::max(glm::ivec2(cape.z, cape.w), to));
      const float inverse = 1.0f / area;
      const glm::vec2 e0 = glm::vec2(p1.y - p2.y, p2.x - p1.x) * inverse;
      const glm::vec2 e1 = glm::vec2(p2.y - p0.y, p0.x - p2.x) * inverse;
      const glm::vec3 b0(e0, -(e0.x * p1.x + e0.y * p1.y)), b1(e1, -(e1.x * p2.x + e1.y * p2.y));
      plane0[t] = skip ? glm::vec3(0.0f, 0.0f, -1.0f) : b0;
      plane1[t] = skip ? glm::vec3(0.0f, 0.0f, -1.0f) : b1;
      planeZ[t] = skip ? glm::vec3(0.0f, 0.0f, 2.0f)
                       : b0 * (p0.z - p2.z) + b1 * (p1.z - p2.z) + glm::vec3(0.0f, 0.0f, p2.z);
      glm::vec3 normal =
          glm::normalize(glm::cross(world[tri[1]] - world[tri[0]], world[tri[2]] - world[tri[0]]));
      if (glm::dot(normal, glm::vec3(view.eye) - world[tri[0]]) < 0.0f) normal = -normal;
      const float light = 0.35f + 0.65f * std::max(glm::dot(normal, glm::vec3(view.light)), 0.0f);
      colour[t] = packColour(glm::vec4(base * light, 1.0f));
    }
    // The cape's box once, every triangle per pixel (planes stepped along the row); the nearest
    // covering triangle (the first on equal depth) goes to the pixel.
    for (int y = cape.y; y <= cape.w; ++y) {
      const glm::vec2 start = glm::vec2(float(cape.x), float(y)) + 0.5f;
      for (uint32_t t = 0; t < triangles; ++t) {
        r0[t] = plane0[t].x * start.x + plane0[t].y * start.y + plane0[t].z;
        r1[t] = plane1[t].x * start.x + plane1[t].y * start.y + plane1[t].z;
        rz[t] = planeZ[t].x * start.x + planeZ[t].y * start.y + planeZ[t].z;
      }
      for (int x = cape.x; x <= cape.z; ++x) {
        float nearest = 2.0f;
        uint32_t nearestColour = 0;
        for (uint32_t t = 0; t < triangles; ++t) {
          const float b0 = r0[t], b1 = r1[t], z = rz[t];
          const float b2 = 1.0f - b0 - b1;
          if (std::min(std::min(b0, b1), b2) >= 0.0f && z >= 0.0f && z <= 1.0f && z < nearest) {
            nearest = z;
            nearestColour = colour[t];
          }
          r0[t] = b0 + plane0[t].x;
          r1[t] = b1 + plane1[t].x;
          rz[t] = z + planeZ[t].x;
        }
        if (nearest > 1.0f) continue;
        uint32_t depthBits;
        std::memcpy(&depthBits, &nearest, 4);
        uint64_t& pixel = visibility[size_t(y) * width + x];
        pixel = std::min(pixel, (uint64_t(depthBits) << 32) | nearestColour);
      }
    }
  }
}

}  // namespace throng::secondary
