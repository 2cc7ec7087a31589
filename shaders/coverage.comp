#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Coverage LOD pass, one invocation per character: its projected height picks a level (with
// hysteresis, changing at a cycle end) whose joints the pose pass synthesizes and the renderer
// draws; a sphere around the whole body tells whether any of it is on screen. The five part
// spheres of the paper's eqs. 1–9 (docs/design.md) are measured when the areas are asked for.
// CPU twin: synth::coverageCharacter (engine/synth/coverage.cpp), mirrored operation for
// operation (the math is in coverage_common.glsl).
#include "coverage_types.h"
#include "synth_bindings.h"
#include "coverage_common.glsl"

layout(local_size_x = 64) in;
layout(std140, binding = kCoverageBindingParts) uniform Parts { CoverageParts parts; };
// Per-character inputs as texels and the masks as 64-bit words: lavapipe moves a storage-buffer
// vector one component per lane in a loop (docs/design.md, "Decisions for CPU devices").
layout(binding = kCoverageBindingPlacement) uniform samplerBuffer placementTexels;
layout(binding = kCoverageBindingMotion) uniform samplerBuffer motionTexels;
layout(std430, binding = kCoverageBindingJoints) readonly buffer Joints { JointPoint joints[]; };  // the chunk's characters
layout(std430, binding = kCoverageBindingMasks) buffer Masks { u64vec2 maskWords[]; };  // CoverageMask, global index, in/out
layout(std430, binding = kCoverageBindingAreas) writeonly buffer Areas { float areas[]; };        // global index × 5
layout(push_constant) uniform Push { CoveragePush push; };
#include "coverage_mask.glsl"

// The five part spheres' areas (areas output) and on-screen bits (state bits 0..4). The level
// follows the projected height alone, so the frame's pass skips them; tests and figures ask.
uint measureParts(uint i, uint local, vec4 place, float scale, CoverageMask previous) {
  bool readJoints = (push.flags & kCoverageReadJoints) != 0u;
  float c = cos(place.w);
  float s = sin(place.w);
  uint onScreen = 0u;
  [[unroll]] for (uint k = 0u; k < kCoveragePartCount; ++k) {
    CoveragePart part = parts.parts[k];
    // A centre joint written by last frame's pose pass (active in last frame's mask) is read
    // from its point and its parent's; any other is estimated from the root.
    uint word = part.joint < 32u ? previous.lo : previous.hi;
    vec3 centre = readJoints && ((word >> (part.joint & 31u)) & 1u) != 0u
                      ? jointCentre(part, joints[local * push.jointCount + partBoneStart(part)].positionRadius,
                                    joints[local * push.jointCount + part.joint].positionRadius)
                      : estimatedCentre(part, place.xyz, c, s, scale);
    float area = sphereCoverage(push.view, push.viewport, push.frustum, centre, part.centre.w * scale);
    areas[i * kCoveragePartCount + k] = area;
    if (area > 0.0) onScreen |= 1u << k;
  }
  return onScreen;
}

void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= push.characterCount) return;
  uint i = push.firstCharacter + local;
  vec4 place = texelFetch(placementTexels, int(i));
  vec4 m = texelFetch(motionTexels, int(i));
  CoverageMask previous = unpackMask(maskWords[i]);
  float h;
  bool visible;
  bodyOnScreenHeight(push.view, push.viewport, push.frustum, place, m, h, visible);
  uint onScreen = (push.flags & kCoverageWriteAreas) != 0u ? measureParts(i, local, place, characterScale(m), previous) : 0u;
  maskWords[i] = nextMaskWords(previous, m, h, visible, onScreen);
}
