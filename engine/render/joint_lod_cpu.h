#pragma once
// CPU twin of drawnJoint (shaders/joint_lod.glsl): the matrix each joint is drawn with, a zero
// matrix (never visible) where it is not drawn. Feeds splatJointsCpu and the LOD tests.
#include <cstdint>
#include <span>
#include <vector>

#include "synth/coverage.h"

namespace throng::render {

// `joints`: characters × jointCount points (jointCount = parents.size(), the skeleton's parents).
// `masks` empty: every joint with a drawn bone; else one CoverageMask per character, and with
// `levels` the level's drawn joints and long bones.
std::vector<synth::JointMatrix> drawnJointMatrices(std::span<const synth::JointPoint> joints,
                                                   std::span<const int32_t> parents,
                                                   uint64_t drawnBones,
                                                   std::span<const synth::CoverageMask> masks = {},
                                                   const synth::CoverageParts* levels = nullptr);

}  // namespace throng::render
