#include "render/joint_lod_cpu.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "synth/joint_points.h"

namespace throng::render {
namespace {

bool bitOf(uint64_t bits, uint32_t j) {
  return j < 64 && ((bits >> j) & 1u) != 0u;
}

uint32_t boneFromOf(const synth::CoverageParts& parts, uint32_t level, uint32_t j) {
  const uint32_t at = level * 64u + j;
  return (parts.boneFrom[at / 16u][(at / 4u) % 4u] >> (8u * (at % 4u))) & 255u;
}

// Mirrors longBone in joint_lod.glsl.
synth::JointMatrix longBone(glm::vec3 start, const synth::JointMatrix& a, float radiusScale) {
  const glm::vec3 end(a.row0.y + a.row0.w, a.row1.y + a.row1.w, a.row2.y + a.row2.w);
  const glm::vec3 axis = end - start;
  const glm::vec3 x(a.row0.x, a.row1.x, a.row2.x), z(a.row0.z, a.row1.z, a.row2.z);
  const float r = glm::length(x) * radiusScale;
  const float len = glm::length(axis);
  if (len <= 1e-6f || r <= 0.0f) return {};
  const glm::vec3 y = axis / len;
  glm::vec3 side = x - glm::dot(x, y) * y;
  if (glm::dot(side, side) <= 1e-3f * glm::dot(x, x)) side = z - glm::dot(z, y) * y;
  side = glm::normalize(side) * r;
  const glm::vec3 other = glm::cross(y, side);
  return {glm::vec4(side.x, axis.x, other.x, start.x), glm::vec4(side.y, axis.y, other.y, start.y),
          glm::vec4(side.z, axis.z, other.z, start.z)};
}

}  // namespace

std::vector<synth::JointMatrix> drawnJointMatrices(std::span<const synth::JointPoint> joints,
                                                   std::span<const int32_t> parents,
                                                   uint64_t drawnBones,
                                                   std::span<const synth::CoverageMask> masks,
                                                   const synth::CoverageParts* levels) {
  const uint32_t jointCount = uint32_t(parents.size());
  if (jointCount == 0 || joints.size() % jointCount != 0)
    fail("drawnJointMatrices: ", joints.size(), " points are not whole characters of ", jointCount,
         " joints");
  const size_t characters = joints.size() / jointCount;
  if (!masks.empty() && masks.size() != characters)
    fail("drawnJointMatrices: ", masks.size(), " masks for ", characters, " characters");
  std::vector<synth::JointMatrix> out(joints.size(), synth::JointMatrix{});
  std::vector<synth::JointMatrix> own(jointCount);
  for (size_t c = 0; c < characters; ++c) {
    // Every joint's bone, as joint_fetch.glsl rebuilds it; a joint outside the mask was not
    // written, and its matrix is never used.
    for (uint32_t j = 0; j < jointCount; ++j)
      own[j] = synth::jointMatrixAt(joints.subspan(c * jointCount, jointCount), parents, j);
    for (uint32_t j = 0; j < jointCount; ++j) {
      if (!bitOf(drawnBones, j)) continue;
      if (masks.empty()) {
        out[c * jointCount + j] = own[j];
        continue;
      }
      if (!bitOf(synth::maskBits(masks[c]), j)) continue;
      const uint32_t level = std::min(masks[c].level, gpu_types::kLevelCount - 1u);
      if (levels) {
        const gpu_types::CoverageLevel& l = levels->levels[level];
        if (!bitOf(uint64_t(l.drawLo) | (uint64_t(l.drawHi) << 32), j)) continue;
      }
      const uint32_t from = levels ? boneFromOf(*levels, level, j) : 255u;
      if (from == 255u || from >= jointCount) {
        out[c * jointCount + j] = own[j];
        continue;
      }
      const synth::JointMatrix& b = own[from];
      const float point = from == 0u ? 0.5f : 1.0f;
      const glm::vec3 start(b.row0.y * point + b.row0.w, b.row1.y * point + b.row1.w,
                            b.row2.y * point + b.row2.w);
      const uint32_t at = level * 64u + j;
      out[c * jointCount + j] = longBone(start, own[j], levels->boneRadius[at / 4u][at % 4u]);
    }
  }
  return out;
}

}  // namespace throng::render
