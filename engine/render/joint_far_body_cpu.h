#pragma once
// CPU twin of the far body (shaders/joint_far_body.glsl, splatBody in
// joint_splat_reserve.glsl): a far-level character under kSplatFarBodyPixels tall on screen
// splatted as one ellipsoid, shaded once, instead of its joints. Feeds the splat tests and the
// far tolerance test.
#include <cstdint>
#include <span>
#include <vector>

#include "shaders/render_bindings.h"
#include "synth/coverage.h"

namespace throng::render {

// The body ellipsoid of one character's joint points as a joint draw matrix (farBodyMatrix in
// the shader); a zero matrix where the joints give no scale.
synth::JointMatrix farBodyMatrix(std::span<const synth::JointPoint> character,
                                 const synth::CoverageParts& parts,
                                 float width = gpu_types::kFarBodyWidth);

struct FarBodyCpu {
  uint32_t character = 0;
  synth::JointMatrix body;
};

// What joint_splat.comp and joint_splat_walk.comp splat: `joints` (points, as
// drawnJointMatrices takes them) as drawnJointMatrices draws them, with nothing for the characters
// drawn as their far body (masks and levels given, far level, the body under farBodyPixels tall and
// at most maxPixels wide), which are in `bodies`. farBodyPixels 0: no far bodies.
struct SplatInputsCpu {
  std::vector<synth::JointMatrix> joints;
  std::vector<FarBodyCpu> bodies;
};
SplatInputsCpu splatInputsCpu(std::span<const synth::JointPoint> joints,
                              std::span<const int32_t> parents, uint64_t drawnBones,
                              std::span<const synth::CoverageMask> masks,
                              const synth::CoverageParts* levels,
                              const gpu_types::FrameUniforms& frame, float maxPixels,
                              float farBodyPixels = gpu_types::kSplatFarBodyPixels);

// Adds the bodies to a visibility buffer (width × height, see splatJointsCpu) as splatBody
// does: each covers the pixels whose ray meets it, in one colour and depth (its centre's),
// tinted by characterTint.
void splatFarBodiesCpu(std::span<const FarBodyCpu> bodies, const gpu_types::FrameUniforms& frame,
                       uint32_t width, uint32_t height, std::vector<uint64_t>& visibility);

}  // namespace throng::render
