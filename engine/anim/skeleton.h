#pragma once
// Offline animation data (ozz style): what the BVH importer produces and the clip
// preparation steps consume. Joints are stored parents-first (parent index < own index).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace throng::anim {

enum class Channel : uint8_t { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

struct Joint {
  std::string name;
  int parent = -1;                   // -1 for the root
  glm::vec3 offset{0.0f};            // from the parent, in the parent's frame
  std::vector<Channel> channels;     // as written in the file (3 or 6 for a BVH joint)
  std::optional<glm::vec3> endSite;  // BVH "End Site" offset, when the joint has one
};

struct Skeleton {
  std::vector<Joint> joints;

  int jointCount() const { return static_cast<int>(joints.size()); }
  std::vector<int32_t> parents() const;
  int findJoint(const std::string& name) const;  // -1 when absent
  // Same joint count and parent array (names may differ): clips can be blended.
  bool sameTopology(const Skeleton& other) const;
  // Per joint: true when its offset is a placement, not a limb, so no bone is drawn for it
  // (placementJoints below, applied to the rest pose and the channels).
  std::vector<bool> placementJoints() const;
};

// Which joints' offsets place the body rather than shape it. A root is a placement when it only
// translates, or when it sits at ground level under the body: at or below the level of the
// lowest other joint plus a tenth of the body's height (Bandai Namco's joint_Root lies on the
// floor, 0.94 m under its child Hips; a CMU or built-in root is the pelvis, well above the
// feet). A child of such a root is a placement too when its offset is long (over a quarter of
// the body's height): the segment from the floor to the pelvis is no bone. `positions` is
// any pose of the joints (rest or animated, y up); `translationOnly` may be empty.
std::vector<bool> placementJoints(std::span<const int32_t> parents,
                                  std::span<const glm::vec3> positions,
                                  const std::vector<bool>& translationOnly = {});

// Bit j set: joint j's bone is drawn (it is not a placement); joints past 64 are left out.
uint64_t drawnBoneMask(const std::vector<bool>& placement);

}  // namespace throng::anim
