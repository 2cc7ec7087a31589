// RawClip (Euler channels as written) → Clip (unit quaternions + root position).
#include <filesystem>

#include "anim/bvh_channels.h"
#include "anim/clip.h"
#include "anim/euler.h"
#include "core/error.h"

namespace throng::anim {

Clip toClip(const RawClip& raw) {
  const int jointCount = raw.skeleton.jointCount();
  std::vector<int> firstChannel(size_t(jointCount), 0);
  int channelCount = 0;
  for (int j = 0; j < jointCount; ++j) {
    const Joint& joint = raw.skeleton.joints[size_t(j)];
    if (joint.parent >= j || joint.parent < -1 || (j == 0) != (joint.parent == -1)) {
      fail(raw.sourceName, ": joint '", joint.name, "' has parent ", joint.parent,
           ", expected parents stored before their children and one root first");
    }
    firstChannel[size_t(j)] = channelCount;
    channelCount += int(joint.channels.size());
  }
  if (jointCount == 0) fail(raw.sourceName, ": expected at least one joint");
  if (channelCount != raw.channelCount || raw.frameCount < 0 ||
      raw.values.size() != size_t(raw.frameCount) * size_t(channelCount)) {
    fail(raw.sourceName, ": expected ", raw.frameCount, " frames × ", channelCount,
         " channels of values, found ", raw.values.size(), " values (channelCount ",
         raw.channelCount, ")");
  }

  Clip clip;
  clip.name = std::filesystem::path(raw.sourceName).stem().string();
  clip.skeleton = raw.skeleton;
  clip.frameCount = raw.frameCount;
  clip.frameTime = raw.frameTime;
  clip.rotations.reserve(size_t(raw.frameCount) * size_t(jointCount));
  clip.rootPositions.reserve(size_t(raw.frameCount));
  const Joint& root = raw.skeleton.joints[0];
  for (int f = 0; f < raw.frameCount; ++f) {
    const float* frame = raw.values.data() + size_t(f) * size_t(channelCount);
    for (int j = 0; j < jointCount; ++j) {
      const Joint& joint = raw.skeleton.joints[size_t(j)];
      std::span<const float> values(frame + firstChannel[size_t(j)], joint.channels.size());
      clip.rotations.push_back(channelsToQuat(joint.channels, values));
    }
    // Root: offset + position channels, in file units (scaleToMetres converts later).
    // Position channels of other joints (Bandai Namco writes 6 on every joint) are not
    // used: the skeleton's offsets stand for the bones, and only rotations are blended.
    glm::vec3 position = root.offset;
    for (size_t c = 0; c < root.channels.size(); ++c) {
      if (!isRotation(root.channels[c])) position[channelAxis(root.channels[c])] += frame[c];
    }
    clip.rootPositions.push_back(position);
  }
  return clip;
}

}  // namespace throng::anim
