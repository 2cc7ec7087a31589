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
  bool animated = false;
  for (int j = 1; j < jointCount; ++j) {
    for (Channel c : raw.skeleton.joints[size_t(j)].channels) animated = animated || !isRotation(c);
  }
  if (animated) clip.animatedOffsets.reserve(size_t(raw.frameCount) * size_t(jointCount));
  for (int f = 0; f < raw.frameCount; ++f) {
    const float* frame = raw.values.data() + size_t(f) * size_t(channelCount);
    for (int j = 0; j < jointCount; ++j) {
      const Joint& joint = raw.skeleton.joints[size_t(j)];
      const float* values = frame + firstChannel[size_t(j)];
      clip.rotations.push_back(channelsToQuat(joint.channels, {values, joint.channels.size()}));
      if (j == 0) {
        // Root: offset + position channels (every capture here has a zero root OFFSET).
        glm::vec3 position = joint.offset;
        for (size_t c = 0; c < joint.channels.size(); ++c) {
          if (!isRotation(joint.channels[c])) position[channelAxis(joint.channels[c])] += values[c];
        }
        clip.rootPositions.push_back(position);
      }
      if (!animated) continue;
      // Other joints: the channel values are the translation itself (Bandai Namco writes the
      // OFFSET again for every bone, and the hips' real height and sway per frame). The
      // root's entry stays its OFFSET: rootPositions holds its translation.
      glm::vec3 offset = joint.offset;
      for (size_t c = 0; j > 0 && c < joint.channels.size(); ++c) {
        if (!isRotation(joint.channels[c])) offset[channelAxis(joint.channels[c])] = values[c];
      }
      clip.animatedOffsets.push_back(offset);
    }
  }
  return clip;
}

}  // namespace throng::anim
