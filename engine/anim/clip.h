#pragma once
// A clip as BVH stores it (raw channel values) and as the engine uses it (unit quaternions
// per joint per frame plus the root's position), ready to bake into motion textures.
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
  // frameCount root positions in metres (the root's global position at that frame).
  std::vector<glm::vec3> rootPositions;
  // For a cyclic clip, the root's displacement over one whole cycle: frame `frameCount`
  // is frame 0 moved by this much. Zero for clips that are not cycles.
  glm::vec3 cycleTravel{0.0f};

  int jointCount() const { return skeleton.jointCount(); }
  glm::vec4 rotation(int frame, int joint) const { return rotations[size_t(frame) * jointCount() + joint]; }
  float duration() const { return frameCount * frameTime; }
};

// Converts the raw Euler channels into quaternions honouring each joint's channel order.
// Position channels of non-root joints replace that joint's offset only when present in the
// data and are ignored otherwise (the usual BVH convention).
Clip toClip(const RawClip& raw);

}  // namespace throng::anim
