#include "render/joint_far_body_cpu.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include "render/joint_lod_cpu.h"
#include "render/joint_splat_cpu.h"

namespace throng::render {
namespace {

// Mirrors partPoint in joint_far_body.glsl.
glm::vec3 partPoint(std::span<const synth::JointPoint> character,
                    const gpu_types::CoveragePart& part) {
  const glm::vec4 point = character[part.joint].positionRadius;
  const glm::vec4 parent = character[gpu_types::partBoneStart(part)].positionRadius;
  return gpu_types::bonePoint(parent, point, part.parent < 0, part.bonePoint);
}

}  // namespace

synth::JointMatrix farBodyMatrix(std::span<const synth::JointPoint> character,
                                 const synth::CoverageParts& parts, float width) {
  const gpu_types::CoveragePart& torso = parts.parts[gpu_types::kPartTorso];
  const gpu_types::CoveragePart& left = parts.parts[gpu_types::kPartLeftLeg];
  const gpu_types::CoveragePart& right = parts.parts[gpu_types::kPartRightLeg];
  const glm::vec3 spine = partPoint(character, torso);
  const glm::vec3 knees = 0.5f * (partPoint(character, left) + partPoint(character, right));
  const float meanSpan = torso.centre.y - 0.5f * (left.centre.y + right.centre.y);
  const float scale = meanSpan > 0.0f ? (spine.y - knees.y) / meanSpan : 0.0f;
  if (!(scale > 0.0f)) return {};
  const float height = parts.body.x * scale;
  const float radius = width * height;
  const glm::vec3 bottom = spine - glm::vec3(0.0f, torso.centre.y * scale, 0.0f);
  return {glm::vec4(radius, 0.0f, 0.0f, bottom.x), glm::vec4(0.0f, height, 0.0f, bottom.y),
          glm::vec4(0.0f, 0.0f, radius, bottom.z)};
}

SplatInputsCpu splatInputsCpu(std::span<const synth::JointPoint> joints,
                              std::span<const int32_t> parents, uint64_t drawnBones,
                              std::span<const synth::CoverageMask> masks,
                              const synth::CoverageParts* levels,
                              const gpu_types::FrameUniforms& frame, float maxPixels,
                              float farBodyPixels) {
  const size_t jointCount = parents.size();
  SplatInputsCpu out{drawnJointMatrices(joints, parents, drawnBones, masks, levels), {}};
  if (masks.empty() || !levels || farBodyPixels <= 0.0f) return out;
  for (size_t c = 0; c < masks.size(); ++c) {
    const synth::CoverageMask& mask = masks[c];
    if (mask.level != gpu_types::kLevelFar || (mask.lo | mask.hi) == 0u) continue;
    const synth::JointMatrix body =
        farBodyMatrix(joints.subspan(c * jointCount, jointCount), *levels);
    const JointSpriteCpu s = jointSpriteCpu(body, frame);
    if (!s.visible || !(s.hi.y - s.lo.y < farBodyPixels) || s.sizePx > maxPixels) continue;
    std::fill_n(out.joints.begin() + std::ptrdiff_t(c * jointCount), jointCount,
                synth::JointMatrix{});
    out.bodies.push_back({uint32_t(c), body});
  }
  return out;
}

void splatFarBodiesCpu(std::span<const FarBodyCpu> bodies, const gpu_types::FrameUniforms& frame,
                       uint32_t width, uint32_t height, std::vector<uint64_t>& visibility) {
  const glm::vec3 eye(frame.eye);
  const glm::vec2 viewport(frame.viewport.x, frame.viewport.y);
  const auto ray = [&](glm::vec2 pixel) {
    const glm::vec2 ndc = pixel / viewport * 2.0f - 1.0f;
    return glm::vec3(frame.rayForward) + ndc.x * glm::vec3(frame.rayRight) +
           ndc.y * glm::vec3(frame.rayDown);
  };
  for (const FarBodyCpu& b : bodies) {
    const JointSpriteCpu s = jointSpriteCpu(b.body, frame);
    const glm::ivec2 lo = glm::max(glm::ivec2(glm::ceil(s.lo - 0.5f)), glm::ivec2(0));
    const glm::ivec2 hi =
        glm::min(glm::ivec2(glm::floor(s.hi - 0.5f)), glm::ivec2(int(width) - 1, int(height) - 1));
    const glm::mat3 inv = glm::transpose(
        glm::mat3(glm::vec3(s.inverse[0]), glm::vec3(s.inverse[1]), glm::vec3(s.inverse[2])));
    const glm::vec3 o = inv * eye + glm::vec3(s.inverse[0].w, s.inverse[1].w, s.inverse[2].w);
    // farBodyShade: the hit of the ray through the box's centre (its nearest approach on a miss).
    const glm::vec3 dir = glm::normalize(ray(0.5f * (s.lo + s.hi)));
    const glm::vec3 d = inv * dir;
    const float a = glm::dot(d, d), bq = glm::dot(o, d);
    const float t = (-bq - std::sqrt(std::max(unitSphereDiscriminantCpu(o, d), 0.0f))) / a;
    const glm::vec3 n = glm::normalize(glm::transpose(inv) * (o + t * d));
    const glm::vec4 clip = frame.viewProjection * glm::vec4(eye + t * dir, 1.0f);
    const float depth = std::clamp(clip.z / clip.w, 0.0f, 1.0f);
    uint32_t depthBits;
    std::memcpy(&depthBits, &depth, sizeof(depthBits));
    const uint64_t packed =
        (uint64_t(depthBits) << 32) |
        shadeJointCpu(characterTintCpu(b.character), n, dir, glm::vec3(frame.lightDirection));
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        const glm::vec3 dp = inv * ray(glm::vec2(x, y) + 0.5f);  // farBodyPixel
        if (!(glm::dot(o, dp) < 0.0f && unitSphereDiscriminantCpu(o, dp) >= 0.0f)) continue;
        uint64_t& pixel = visibility[size_t(y) * width + x];
        pixel = std::min(pixel, packed);
      }
  }
}

}  // namespace throng::render
