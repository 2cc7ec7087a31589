#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The frame's coverage LOD pass (coverage.comp without the areas) over every group of a crowd in
// one dispatch, for frames that move characters between root motion and coverage (walls): each
// character's mask from its group's CoverageParts, the camera from this frame's CoverageView.
// Mirrors root_motion_groups_coverage.comp's coverage; CPU twin: synth::coverageCharacter.
#include "shared_types.h"
#include "synth_bindings.h"
#include "coverage_types.h"
#include "coverage_common.glsl"
#include "words64.glsl"

layout(local_size_x = 64) in;
layout(std140, binding = kCoverageGroupsBindingGroups) uniform Groups { SynthGroupTable table; };
layout(std140, binding = kCoverageGroupsBindingParts) uniform Parts { CoverageParts groupParts[kSynthMaxGroups]; };
layout(std140, binding = kCoverageGroupsBindingView) uniform View { CoverageView camera; };
layout(binding = kCoverageGroupsBindingPlacement) uniform samplerBuffer placementTexels;
layout(binding = kCoverageGroupsBindingMotion) uniform samplerBuffer motionTexels;
layout(std430, binding = kCoverageGroupsBindingMasks) buffer Masks { u64vec2 maskWords[]; };  // CoverageMask, in/out
layout(push_constant) uniform Push { uint characterCount; };
// coverage_mask.glsl reads `parts`: the character's group's.
uint coverageGroup = 0u;
#define parts groupParts[coverageGroup]
#include "coverage_mask.glsl"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= characterCount) return;
  [[unroll]] for (uint k = 1u; k < kSynthMaxGroups; ++k)
    if (k < table.counts.x && i >= table.groups[k].firstCharacter) coverageGroup = k;
  vec4 place = texelFetch(placementTexels, int(i));
  vec4 m = texelFetch(motionTexels, int(i));
  maskWords[i] = frameMaskWords(camera.view, camera.viewport, camera.frustum, place, m, maskWords[i]);
}
