#pragma once
// CPU twin of the joint splat's joints (joint_splat_walk.comp, joint_splat_pixels.comp): the same
// sprite bounds, ray/ellipsoid hits, shading and nearest-hit packing, in plain C++. The far
// bodies' twin is joint_far_body_cpu.h. Tests compare them with the GPU passes.
#include <cstdint>
#include <span>
#include <vector>

#include "synth/gpu_types.h"

namespace throng::render {

// jointSprite() of shaders/joint_sprite.glsl: a joint draw matrix's ellipsoid, its world →
// unit-sphere rows and its exact screen box.
struct JointSpriteCpu {
  glm::vec4 inverse[3];
  glm::vec2 lo{0.0f}, hi{0.0f};
  float sizePx = 0.0f;
  bool visible = false;
};
JointSpriteCpu jointSpriteCpu(const synth::JointMatrix& a, const gpu_types::FrameUniforms& frame);

// characterTint() and shadeJoint() (packed as the visibility buffer's colour) of
// joint_sprite.glsl.
glm::vec3 characterTintCpu(uint32_t character);
// unitSphereDiscriminant() of joint_sprite.glsl: ≥ 0 where the ray o + t·d meets the unit
// sphere, as |d|² − |o × d|² (the textbook form cancels to its rounding far from a thin bone).
float unitSphereDiscriminantCpu(glm::vec3 o, glm::vec3 d);
uint32_t shadeJointCpu(glm::vec3 tint, glm::vec3 n, glm::vec3 dir, glm::vec3 light);

struct SplatCpuResult {
  std::vector<uint64_t> visibility;  // width × height, kEmptyPixel where nothing was hit
  std::vector<uint32_t> nearJoints;  // joints too wide to splat, ascending
};

SplatCpuResult splatJointsCpu(std::span<const synth::JointMatrix> joints,
                              const gpu_types::FrameUniforms& frame, uint32_t jointCount,
                              float maxPixels, uint32_t width, uint32_t height);

}  // namespace throng::render
