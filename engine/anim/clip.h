#pragma once
// A clip as BVH stores it (raw channel values) and as the engine uses it (unit quaternions
// per joint per frame, the root's position and, when the file animates them, the other
// joints' translations), ready to bake into motion textures.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/skeleton.h"

namespace throng::anim {

struct RawClip {
  std::string sourceName;       // file name, for messages
  Skeleton skeleton;
  int frameCount = 0;
  float frameTime = 0.0f;       // seconds per frame
  int channelCount = 0;         // sum of all joints' channel counts
  std::vector<float> values;    // frameCount × channelCount, as in the file (degrees, units)
};

struct Clip {
  std::string name;
  Skeleton skeleton;
  int frameCount = 0;
  float frameTime = 0.0f;
  // frameCount × jointCount unit quaternions (x,y,z,w), local rotation of each joint.
  std::vector<glm::vec4> rotations;
  // frameCount root positions (the root's global position at that frame), in file units
  // after toClip and in metres after scaleToMetres.
  std::vector<glm::vec3> rootPositions;
  // frameCount × jointCount local translations (joint j's offset from its parent at frame f,
  // in the parent's frame, same units as rootPositions) when any non-root joint has position
  // channels, else empty: the skeleton's offsets then hold for every frame. The root's
  // entries are unused (rootPositions is the root's translation). Bandai Namco animates the
  // hips this way: its root only slides along the ground.
  std::vector<glm::vec3> animatedOffsets;
  // For a cyclic clip, the root's displacement over one whole cycle: frame `frameCount`
  // is frame 0 moved by this much. Zero for clips that are not cycles.
  glm::vec3 cycleTravel{0.0f};

  int jointCount() const { return skeleton.jointCount(); }
  glm::vec4 rotation(int frame, int joint) const { return rotations[size_t(frame) * jointCount() + joint]; }
  // Joint j's translation from its parent at `frame` (the root: its global position).
  glm::vec3 offset(int frame, int joint) const {
    if (joint == 0) return rootPositions[size_t(frame)];
    if (animatedOffsets.empty()) return skeleton.joints[size_t(joint)].offset;
    return animatedOffsets[size_t(frame) * size_t(jointCount()) + size_t(joint)];
  }
  float duration() const { return frameCount * frameTime; }
};

// Converts the raw Euler channels into quaternions honouring each joint's channel order.
// The root's position is its OFFSET plus its position channels. A non-root joint's position
// channels replace the OFFSET components they name, frame by frame (animatedOffsets); its
// other components, and joints without position channels, keep the OFFSET.
Clip toClip(const RawClip& raw);

}  // namespace throng::anim
