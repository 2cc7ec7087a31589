#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Coverage LOD pass, one invocation per character: its projected height picks a level (with
// hysteresis, changing at a cycle end) whose joints the pose pass synthesizes and the renderer
// draws; a sphere around the whole body tells whether any of it is on screen (the five part
// spheres of the paper's eqs. 1–9, docs/design.md are still measured, for the areas output and the state's bits).
// CPU twin: synth::coverageCharacter (engine/synth/coverage.cpp), mirrored operation for
// operation (the math is in coverage_common.glsl).
#include "coverage_types.h"
#include "synth_bindings.h"
#include "coverage_common.glsl"

layout(local_size_x = 64) in;
layout(std140, binding = kCoverageBindingParts) uniform Parts { CoverageParts parts; };
layout(std430, binding = kCoverageBindingPlacement) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = kCoverageBindingMotion) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = kCoverageBindingJoints) readonly buffer Joints { JointMatrix joints[]; };  // the chunk's characters
layout(std430, binding = kCoverageBindingMasks) buffer Masks { CoverageMask masks[]; };           // global index, in/out
layout(std430, binding = kCoverageBindingAreas) writeonly buffer Areas { float areas[]; };        // global index × 5
layout(push_constant) uniform Push { CoveragePush push; };

void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= push.characterCount) return;
  uint i = push.firstCharacter + local;
  vec4 place = placement[i];
  vec4 m = motion[i];
  float scale = characterScale(m);
  CoverageMask previous = masks[i];
  bool readJoints = (push.flags & kCoverageReadJoints) != 0u;
  float c = cos(place.w);
  float s = sin(place.w);
  uint onScreen = 0u;
  [[unroll]] for (uint k = 0u; k < kCoveragePartCount; ++k) {
    CoveragePart part = parts.parts[k];
    // A centre joint written by last frame's pose pass (active in last frame's mask) is read
    // from its matrix; any other is estimated from the root.
    uint word = part.joint < 32u ? previous.lo : previous.hi;
    vec3 centre = readJoints && ((word >> (part.joint & 31u)) & 1u) != 0u
                      ? jointCentre(joints[local * push.jointCount + part.joint], part.bonePoint)
                      : estimatedCentre(part, place.xyz, c, s, scale);
    float area = sphereCoverage(push.view, push.viewport, push.frustum, centre, part.centre.w * scale);
    if ((push.flags & kCoverageWriteAreas) != 0u) areas[i * kCoveragePartCount + k] = area;
    if (area > 0.0) onScreen |= 1u << k;
  }
  float h = projectedHeight(push.view, push.viewport, place.xyz, parts.body.x * scale);
  bool visible = bodyOnScreen(push.view, push.viewport, push.frustum, place.xyz, parts.body.x * scale);
  uvec2 levelState = nextLevel(parts, previous, m, h, visible);
  CoverageLevel level = parts.levels[levelState.x];
  uvec2 synthesized = visible ? uvec2(level.synthLo, level.synthHi) : uvec2(parts.baseLo, parts.baseHi);
  masks[i] = CoverageMask(synthesized.x, synthesized.y, levelState.x, levelState.y | onScreen);
}
