#pragma once
// CPU twin of the far body (shaders/joint_far_body.glsl): a far-level character under
// kSplatFarBodyPixels tall on screen splatted as one ellipsoid instead of its joints. Feeds
// splatJointsCpu in the splat tests and the far tolerance test.
#include <cstdint>
#include <span>
#include <vector>

#include "shaders/render_bindings.h"
#include "synth/coverage.h"

namespace throng::render {

// The body ellipsoid of one character's joints as a joint draw matrix (farBodyMatrix in the
// shader); a zero matrix where the joints give no scale.
synth::JointMatrix farBodyMatrix(std::span<const synth::JointMatrix> character,
                                 const synth::CoverageParts& parts,
                                 float width = gpu_types::kFarBodyWidth);

// The matrices joint_splat.comp splats, in drawnJointMatrices's layout: each character's drawn
// joints, or, for a character drawn as its far body (masks and levels given, far level, the body
// under farBodyPixels tall and at most maxPixels wide), the body in its joint 0's slot and
// nothing else. farBodyPixels 0: drawnJointMatrices itself.
std::vector<synth::JointMatrix> splattedJointMatrices(
    std::span<const synth::JointMatrix> joints, uint32_t jointCount, uint64_t drawnBones,
    std::span<const synth::CoverageMask> masks, const synth::CoverageParts* levels,
    const gpu_types::FrameUniforms& frame, float maxPixels,
    float farBodyPixels = gpu_types::kSplatFarBodyPixels);

}  // namespace throng::render
