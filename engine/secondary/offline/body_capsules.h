#pragma once
// The body the cloth collides with: capsules on the skeleton's bones, found by joint name so
// the same list serves the built-in gait, CMU and Bandai Namco skeletons.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "secondary/secondary_types.h"

namespace throng::secondary {

// A capsule on the bone from `joint`'s parent to `joint`.
struct BoneCapsule {
  std::string joint;
  float radius = 0.0f;
};
// Torso, neck, head, clavicles, arms and legs of the built-in 25-joint gait skeleton (radii
// of a slim adult, metres), plus the same bones under their CMU and Bandai Namco names.
std::vector<BoneCapsule> defaultBodyCapsules();

// A capsule on the graph's joints: segment from joint a to joint b.
struct Capsule {
  uint32_t a = 0, b = 0;
  float radius = 0.0f;
};
// Names the skeleton lacks are skipped; a root joint (no parent) gives a sphere on it.
std::vector<Capsule> resolveCapsules(const PrimaryGraph& graph,
                                     const std::vector<BoneCapsule>& bones);

// Capsule end points at a node, character space.
struct CapsuleShape {
  glm::vec3 a{0.0f}, b{0.0f};
  float radius = 0.0f;
};
std::vector<CapsuleShape> capsulesAt(const PrimaryGraph& graph,
                                     const std::vector<Capsule>& capsules, uint32_t node);
// Distance from p to the capsule's axis segment.
float segmentDistance(glm::vec3 p, glm::vec3 a, glm::vec3 b);

// Joints the top of a garment hangs from: names holding neck, shoulder, clavicle or collar.
std::vector<uint32_t> neckShoulderJoints(const PrimaryGraph& graph);

}  // namespace throng::secondary
