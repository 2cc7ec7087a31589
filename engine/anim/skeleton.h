#pragma once
// Offline animation data (ozz style): what the BVH importer produces and the clip
// preparation steps consume. Joints are stored parents-first (parent index < own index).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace throng::anim {

enum class Channel : uint8_t { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

struct Joint {
  std::string name;
  int parent = -1;                  // -1 for the root
  glm::vec3 offset{0.0f};           // from the parent, in the parent's frame
  std::vector<Channel> channels;    // as written in the file (3 or 6 for a BVH joint)
  std::optional<glm::vec3> endSite; // BVH "End Site" offset, when the joint has one
};

struct Skeleton {
  std::vector<Joint> joints;

  int jointCount() const { return static_cast<int>(joints.size()); }
  std::vector<int32_t> parents() const;
  int findJoint(const std::string& name) const;  // -1 when absent
  // Same joint count and parent array (names may differ): clips can be blended.
  bool sameTopology(const Skeleton& other) const;
};

}  // namespace throng::anim
