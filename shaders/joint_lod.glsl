// Which joints of a character are drawn and with which matrix: a placement's bone never (the
// push's bone mask), a joint outside the LOD mask never; with the LOD levels, only the level's
// drawn joints, a joint whose parent is not drawn as a long bone from its nearest drawn
// ancestor (limbs as single bones far away). Needs joint_fetch.glsl first. CPU twin:
// render::drawnJointMatrices (engine/render/joint_lod_cpu.cpp).
#ifndef THRONG_JOINT_LOD_GLSL
#define THRONG_JOINT_LOD_GLSL
#include "coverage_types.h"
#include "render_bindings.h"

layout(std140, binding = kRenderBindingLodLevels) uniform LodLevels { CoverageParts lodParts; };  // kDrawLodLevels

bool bitOf(uvec2 bits, uint j) { return ((j < 32u ? bits.x >> j : bits.y >> (j - 32u)) & 1u) != 0u; }

uint boneFromOf(uint level, uint j) {
  uint at = level * 64u + j;
  return (lodParts.boneFrom[at / 16u][(at / 4u) % 4u] >> (8u * (at % 4u))) & 255u;
}

float boneRadiusOf(uint level, uint j) {
  uint at = level * 64u + j;
  return lodParts.boneRadius[at / 4u][at % 4u];
}

// The bone from `start` to the end of joint matrix a, as thick as a's times radiusScale.
JointMatrix longBone(vec3 start, JointMatrix a, float radiusScale) {
  vec3 end = vec3(a.row0.y + a.row0.w, a.row1.y + a.row1.w, a.row2.y + a.row2.w);
  vec3 axis = end - start;
  vec3 x = vec3(a.row0.x, a.row1.x, a.row2.x);
  vec3 z = vec3(a.row0.z, a.row1.z, a.row2.z);
  float r = length(x) * radiusScale;
  float len = length(axis);
  if (len <= 1e-6 || r <= 0.0) return JointMatrix(vec4(0.0), vec4(0.0), vec4(0.0));
  vec3 y = axis / len;
  vec3 side = x - dot(x, y) * y;
  if (dot(side, side) <= 1e-3 * dot(x, x)) side = z - dot(z, y) * y;
  side = normalize(side) * r;
  vec3 other = cross(y, side);
  return JointMatrix(vec4(side.x, axis.x, other.x, start.x), vec4(side.y, axis.y, other.y, start.y),
                     vec4(side.z, axis.z, other.z, start.z));
}

// chunkJoint indexes the chunk's joints binding, j is the joint within the character.
bool drawnPoseJoint(uint chunkJoint, CharacterPose pose, uint j, uint flags, uvec4 mask, uvec2 bones, out JointMatrix a) {
  a = JointMatrix(vec4(0.0), vec4(0.0), vec4(0.0));
  if (!bitOf(bones, j)) return false;
  if ((flags & kDrawUseMasks) == 0u) {
    a = fetchPoseJoint(pose, chunkJoint, j);
    return true;
  }
  if (!bitOf(mask.xy, j)) return false;
  bool levels = (flags & kDrawLodLevels) != 0u;
  uint level = min(mask.z, kLevelCount - 1u);
  if (levels && !bitOf(uvec2(lodParts.levels[level].drawLo, lodParts.levels[level].drawHi), j)) return false;
  a = fetchPoseJoint(pose, chunkJoint, j);
  uint from = levels ? boneFromOf(level, j) : 255u;
  if (from == 255u) return true;
  JointMatrix b = fetchPoseJoint(pose, chunkJoint - j + from, from);
  float point = from == 0u ? 0.5 : 1.0;  // the root's matrix is a sphere around it
  vec3 start = vec3(b.row0.y * point + b.row0.w, b.row1.y * point + b.row1.w, b.row2.y * point + b.row2.w);
  a = longBone(start, a, boneRadiusOf(level, j));
  return true;
}

bool drawnJoint(uint chunkJoint, uint character, uint j, uint flags, uvec4 mask, uvec2 bones, out JointMatrix a) {
  return drawnPoseJoint(chunkJoint, characterPose(character, flags), j, flags, mask, bones, a);
}

#endif
