// Aligning a slow/fast pair by left-foot contact so that blending frame f of one with frame f
// of the other mixes the same moment of the stride.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "anim/clip_prep.h"
#include "anim/clip_prep_util.h"
#include "core/error.h"
#include "core/text.h"

namespace throng::anim {
namespace {

// Frames whose foot height is within this fraction of the height range above the lowest one
// count as the contact; the middle of that run is the contact phase (the bottom of the
// stance is flat, so the single lowest frame would jitter by a frame or two).
constexpr float kContactBand = 0.15f;

bool isLeftName(const std::string& name) {
  std::string low = toLower(name);
  if (low.find("left") != std::string::npos) return true;
  if (low.rfind("l_", 0) == 0 || low.find("_l_") != std::string::npos) return true;
  if (low.size() >= 2 && low.compare(low.size() - 2, 2, "_l") == 0) return true;
  // CMU style: "LFoot", "LHipJoint" (a capital L followed by another capital).
  return name.size() >= 2 && name[0] == 'L' && std::isupper(static_cast<unsigned char>(name[1]));
}

// Rest-pose joint positions (offsets accumulated down the hierarchy).
std::vector<glm::vec3> restPositions(const Skeleton& skeleton) {
  std::vector<glm::vec3> rest(static_cast<size_t>(skeleton.jointCount()));
  for (int j = 0; j < skeleton.jointCount(); ++j) {
    const Joint& joint = skeleton.joints[size_t(j)];
    rest[size_t(j)] =
        (joint.parent < 0 ? glm::vec3(0.0f) : rest[size_t(joint.parent)]) + joint.offset;
  }
  return rest;
}

// The left ankle by name (a toe when no ankle is named); else the lowest end-effector of the
// rest pose on the character's left (+x when facing +z).
int leftFootJoint(const Skeleton& skeleton) {
  int toe = -1;
  for (int j = 0; j < skeleton.jointCount(); ++j) {
    const std::string& name = skeleton.joints[size_t(j)].name;
    if (!isLeftName(name)) continue;
    std::string low = toLower(name);
    if (low.find("foot") != std::string::npos || low.find("ankle") != std::string::npos) return j;
    if (toe < 0 && low.find("toe") != std::string::npos) toe = j;
  }
  if (toe >= 0) return toe;
  std::vector<glm::vec3> rest = restPositions(skeleton);
  std::vector<bool> hasChild(size_t(skeleton.jointCount()), false);
  for (const Joint& joint : skeleton.joints) {
    if (joint.parent >= 0) hasChild[size_t(joint.parent)] = true;
  }
  int best = 0;
  for (int pass = 0; pass < 2 && best == 0; ++pass) {  // pass 1 drops the +x condition
    for (int j = 1; j < skeleton.jointCount(); ++j) {
      if (hasChild[size_t(j)] || (pass == 0 && rest[size_t(j)].x <= rest[0].x)) continue;
      if (best == 0 || rest[size_t(j)].y < rest[size_t(best)].y) best = j;
    }
  }
  return best;
}

// Phase in [0, 1) of the middle of the foot's lowest stretch.
float contactPhase(const Clip& clip, int foot) {
  const int frames = clip.frameCount;
  std::vector<float> height(static_cast<size_t>(frames));
  for (int f = 0; f < frames; ++f)
    height[size_t(f)] = prep::globalPositions(clip, f)[size_t(foot)].y;
  auto lowest = std::min_element(height.begin(), height.end());
  float top = *std::max_element(height.begin(), height.end());
  float band = *lowest + kContactBand * (top - *lowest);
  int bottom = int(lowest - height.begin());
  auto at = [&](int f) { return height[size_t(((f % frames) + frames) % frames)]; };
  int left = bottom, right = bottom;
  while (right - left + 1 < frames && at(left - 1) <= band) --left;
  while (right - left + 1 < frames && at(right + 1) <= band) ++right;
  float middle = 0.5f * float(left + right) / float(frames);
  return middle - std::floor(middle);
}

}  // namespace

int alignPhases(const Clip& slow, Clip& fast) {
  if (slow.jointCount() != fast.jointCount()) {
    fail("slow clip ", slow.name, " has ", slow.jointCount(), " joints, fast clip ", fast.name,
         " has ", fast.jointCount(), ": a pair must share one skeleton");
  }
  if (!slow.skeleton.sameTopology(fast.skeleton)) {
    fail("slow clip ", slow.name, " and fast clip ", fast.name, " both have ", slow.jointCount(),
         " joints but different parents: a pair must share one skeleton");
  }
  prep::checkClip(slow);
  prep::checkClip(fast);
  int foot = leftFootJoint(slow.skeleton);
  const int frames = fast.frameCount;
  float delta = contactPhase(fast, foot) - contactPhase(slow, foot);
  int shift = int(std::lround(delta * float(frames))) % frames;
  if (shift < 0) shift += frames;
  if (shift == 0) return 0;

  // fast'[i] = fast[i + shift]; frames taken from the next cycle carry its travel, and the
  // whole path moves so that frame 0 keeps its place on the ground.
  Clip old = fast;
  const size_t joints = size_t(fast.jointCount());
  for (int i = 0; i < frames; ++i) {
    int source = i + shift;
    glm::vec3 travel(0.0f);
    if (source >= frames) {
      source -= frames;
      travel = old.cycleTravel;
    }
    std::copy_n(old.rotations.begin() + ptrdiff_t(size_t(source) * joints), joints,
                fast.rotations.begin() + ptrdiff_t(size_t(i) * joints));
    if (!old.animatedOffsets.empty()) {  // local: no travel to add
      std::copy_n(old.animatedOffsets.begin() + ptrdiff_t(size_t(source) * joints), joints,
                  fast.animatedOffsets.begin() + ptrdiff_t(size_t(i) * joints));
    }
    fast.rootPositions[size_t(i)] = old.rootPositions[size_t(source)] + travel;
  }
  glm::vec3 move = old.rootPositions[0] - fast.rootPositions[0];
  move.y = 0.0f;
  for (glm::vec3& p : fast.rootPositions) p += move;
  return shift;
}

}  // namespace throng::anim
