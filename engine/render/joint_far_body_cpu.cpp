#include "render/joint_far_body_cpu.h"

#include <algorithm>
#include "render/joint_lod_cpu.h"
#include "render/joint_splat_cpu.h"

namespace throng::render {
namespace {

glm::vec3 partPoint(const synth::JointMatrix& a, float bonePoint) {
  return {a.row0.y * bonePoint + a.row0.w, a.row1.y * bonePoint + a.row1.w,
          a.row2.y * bonePoint + a.row2.w};
}

}  // namespace

synth::JointMatrix farBodyMatrix(std::span<const synth::JointMatrix> character,
                                 const synth::CoverageParts& parts, float width) {
  const gpu_types::CoveragePart& torso = parts.parts[gpu_types::kPartTorso];
  const gpu_types::CoveragePart& left = parts.parts[gpu_types::kPartLeftLeg];
  const gpu_types::CoveragePart& right = parts.parts[gpu_types::kPartRightLeg];
  const glm::vec3 spine = partPoint(character[torso.joint], torso.bonePoint);
  const glm::vec3 knees = 0.5f * (partPoint(character[left.joint], left.bonePoint) +
                                  partPoint(character[right.joint], right.bonePoint));
  const float meanSpan = torso.centre.y - 0.5f * (left.centre.y + right.centre.y);
  const float scale = meanSpan > 0.0f ? (spine.y - knees.y) / meanSpan : 0.0f;
  if (!(scale > 0.0f)) return {};
  const float height = parts.body.x * scale;
  const float radius = width * height;
  const glm::vec3 bottom = spine - glm::vec3(0.0f, torso.centre.y * scale, 0.0f);
  return {glm::vec4(radius, 0.0f, 0.0f, bottom.x), glm::vec4(0.0f, height, 0.0f, bottom.y),
          glm::vec4(0.0f, 0.0f, radius, bottom.z)};
}

std::vector<synth::JointMatrix> splattedJointMatrices(std::span<const synth::JointMatrix> joints,
                                                      uint32_t jointCount, uint64_t drawnBones,
                                                      std::span<const synth::CoverageMask> masks,
                                                      const synth::CoverageParts* levels,
                                                      const gpu_types::FrameUniforms& frame,
                                                      float maxPixels, float farBodyPixels) {
  std::vector<synth::JointMatrix> out =
      drawnJointMatrices(joints, jointCount, drawnBones, masks, levels);
  if (masks.empty() || !levels || farBodyPixels <= 0.0f) return out;
  for (size_t c = 0; c < masks.size(); ++c) {
    const synth::CoverageMask& mask = masks[c];
    if (mask.level != gpu_types::kLevelFar || (mask.lo | mask.hi) == 0u) continue;
    const synth::JointMatrix body =
        farBodyMatrix(joints.subspan(c * jointCount, jointCount), *levels);
    const JointSpriteCpu s = jointSpriteCpu(body, frame);
    if (!s.visible || !(s.hi.y - s.lo.y < farBodyPixels) || s.sizePx > maxPixels) continue;
    std::fill_n(out.begin() + std::ptrdiff_t(c * jointCount), jointCount, synth::JointMatrix{});
    out[c * jointCount] = body;
  }
  return out;
}

}  // namespace throng::render
