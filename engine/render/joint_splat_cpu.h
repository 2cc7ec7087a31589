#pragma once
// CPU twin of joint_splat.comp: the same sprite bounds, ray/ellipsoid hits, shading and
// nearest-hit packing, in plain C++. Tests compare it with the GPU pass.
#include <cstdint>
#include <span>
#include <vector>

#include "synth/gpu_types.h"

namespace throng::render {

struct SplatCpuResult {
  std::vector<uint64_t> visibility;   // width × height, kEmptyPixel where nothing was hit
  std::vector<uint32_t> nearJoints;   // joints too wide to splat, ascending
};

SplatCpuResult splatJointsCpu(std::span<const synth::JointMatrix> joints, const gpu_types::FrameUniforms& frame,
                              uint32_t jointCount, float maxPixels, uint32_t width, uint32_t height);

}  // namespace throng::render
