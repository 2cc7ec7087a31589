#include "synth/body_parts.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <optional>

#include "anim/reference_synth.h"
#include "core/error.h"

namespace throng::synth {
namespace {

const char* const kPartNames[kBodyPartCount] = {"left arm", "right arm", "torso", "left leg",
                                                "right leg"};

// The skeleton as a tree with bone lengths accumulated from the root.
struct Tree {
  std::vector<int> parent;
  std::vector<std::vector<int>> children;
  std::vector<float> pathLength;  // sum of bone lengths from the root
  std::vector<glm::vec3> rest;

  int size() const { return static_cast<int>(parent.size()); }
  bool isAncestor(int a, int j) const {  // a == j counts
    for (; j >= 0; j = parent[size_t(j)])
      if (j == a) return true;
    return false;
  }
  // Distance along the bones between two joints: a bound on their distance in any pose.
  float boneDistance(int a, int b) const {
    int lca = a;
    while (!isAncestor(lca, b)) lca = parent[size_t(lca)];
    return pathLength[size_t(a)] + pathLength[size_t(b)] - 2.0f * pathLength[size_t(lca)];
  }
  std::vector<int> subtree(int top) const {
    std::vector<int> out;
    for (int j = 0; j < size(); ++j)
      if (isAncestor(top, j)) out.push_back(j);
    return out;
  }
  std::vector<int> pathFromRoot(int j) const {
    std::vector<int> path;
    for (; j >= 0; j = parent[size_t(j)]) path.push_back(j);
    std::reverse(path.begin(), path.end());
    return path;
  }
};

Tree makeTree(const anim::Skeleton& skeleton) {
  const int n = skeleton.jointCount();
  if (n < 1 || n > 64)
    fail("body parts: the coverage LOD supports 1..64 joints, the skeleton has ", n);
  Tree t;
  t.rest = restPositions(skeleton);
  t.children.resize(size_t(n));
  for (int j = 0; j < n; ++j) {
    int p = skeleton.joints[size_t(j)].parent;
    if (j == 0 ? p != -1 : (p < 0 || p >= j))
      fail("body parts: joint ", j, " ('", skeleton.joints[size_t(j)].name, "') has parent ", p,
           ", expected joints stored parents first with the root at index 0");
    t.parent.push_back(p);
    t.pathLength.push_back(
        p < 0 ? 0.0f : t.pathLength[size_t(p)] + glm::length(skeleton.joints[size_t(j)].offset));
    if (p >= 0) t.children[size_t(p)].push_back(j);
  }
  return t;
}

// What the parts are built from, whichever way they were found.
struct Layout {
  int head = -1;
  std::array<int, 4> limbCentre{};  // left arm, right arm, left leg, right leg
};

enum class Side { None, Left, Right };

std::string lowerCase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// "LeftForeArm", "LowerArm_L", "l_elbow", "lShin", "LHipJoint": the side and the name without it.
std::pair<Side, std::string> splitSide(const std::string& name) {
  std::string low = lowerCase(name);
  Side side = Side::None;
  auto erase = [&](size_t at, size_t count) { low.erase(at, count); };
  if (size_t at = low.find("left"); at != std::string::npos) {
    side = Side::Left;
    erase(at, 4);
  } else if (size_t at = low.find("right"); at != std::string::npos) {
    side = Side::Right;
    erase(at, 5);
  } else if (low.size() > 2 && (low[1] == '_' || low[1] == '.' || low[1] == '-') &&
             (low[0] == 'l' || low[0] == 'r')) {
    side = low[0] == 'l' ? Side::Left : Side::Right;
    erase(0, 2);
  } else if (low.size() > 2 &&
             (endsWith(low, "_l") || endsWith(low, ".l") || endsWith(low, "-l"))) {
    side = Side::Left;
    erase(low.size() - 2, 2);
  } else if (low.size() > 2 &&
             (endsWith(low, "_r") || endsWith(low, ".r") || endsWith(low, "-r"))) {
    side = Side::Right;
    erase(low.size() - 2, 2);
  } else if (name.size() > 1 &&
             (name[0] == 'l' || name[0] == 'L' || name[0] == 'r' || name[0] == 'R') &&
             std::isupper(static_cast<unsigned char>(name[1]))) {
    side = std::tolower(static_cast<unsigned char>(name[0])) == 'l' ? Side::Left : Side::Right;
    erase(0, 1);
  }
  std::string stem;
  for (char c : low)
    if (std::isalnum(static_cast<unsigned char>(c))) stem += c;
  return {side, stem};
}

bool contains(const std::string& s, const char* part) {
  return s.find(part) != std::string::npos;
}

// Helper bones (twist, roll) and end markers never stand for the joint itself.
bool isHelper(const std::string& stem) {
  return contains(stem, "twist") || contains(stem, "roll") || contains(stem, "end") ||
         contains(stem, "nub") || contains(stem, "site");
}
bool isElbow(const std::string& stem) {
  return !isHelper(stem) &&
         (contains(stem, "forearm") || contains(stem, "lowerarm") || contains(stem, "elbow"));
}
bool isKnee(const std::string& stem) {
  if (isHelper(stem) || contains(stem, "up") || contains(stem, "thigh")) return false;
  return stem == "leg" || contains(stem, "lowerleg") || contains(stem, "knee") ||
         contains(stem, "shin") || contains(stem, "calf");
}

// The shallowest joint matching; nullopt when none or when two equally shallow ones do.
template <typename Match>
std::optional<int> shallowest(const anim::Skeleton& skeleton, const Tree& tree, Match match) {
  std::optional<int> best;
  size_t bestDepth = 0;
  bool tie = false;
  for (int j = 0; j < tree.size(); ++j) {
    if (!match(skeleton.joints[size_t(j)].name)) continue;
    size_t depth = tree.pathFromRoot(j).size();
    if (!best || depth < bestDepth) {
      best = j;
      bestDepth = depth;
      tie = false;
    } else if (depth == bestDepth) {
      tie = true;
    }
  }
  return tie ? std::nullopt : best;
}

int highestJoint(const Tree& tree) {
  int head = 0;
  for (int j = 1; j < tree.size(); ++j)
    if (tree.rest[size_t(j)].y >= tree.rest[size_t(head)].y) head = j;
  return head;
}

std::optional<Layout> layoutFromNames(const anim::Skeleton& skeleton, const Tree& tree) {
  auto sided = [&](Side side, bool (*kind)(const std::string&)) {
    return shallowest(skeleton, tree, [&](const std::string& name) {
      auto [s, stem] = splitSide(name);
      return s == side && kind(stem);
    });
  };
  std::optional<int> centres[4] = {sided(Side::Left, isElbow), sided(Side::Right, isElbow),
                                   sided(Side::Left, isKnee), sided(Side::Right, isKnee)};
  Layout layout;
  for (int k = 0; k < 4; ++k) {
    if (!centres[k]) return std::nullopt;
    layout.limbCentre[size_t(k)] = *centres[k];
  }
  std::optional<int> head = shallowest(skeleton, tree, [](const std::string& name) {
    std::string stem = splitSide(name).second;
    return contains(stem, "head") && !isHelper(stem) && !contains(stem, "top");
  });
  layout.head = head ? *head : highestJoint(tree);
  return layout;
}

// Joint of `chain` whose bone distance from chain.front() is closest to half the chain's.
int middleOf(const Tree& tree, const std::vector<int>& chain) {
  float start = tree.pathLength[size_t(chain.front())];
  float half = 0.5f * (tree.pathLength[size_t(chain.back())] - start);
  int best = chain.front();
  for (int j : chain)
    if (std::abs(tree.pathLength[size_t(j)] - start - half) <
        std::abs(tree.pathLength[size_t(best)] - start - half))
      best = j;
  return best;
}

// The rest pose's shape: the head is the highest joint; the four longest branches off the
// root→head chain are the limbs, the two reaching lowest being the legs; the side with the
// larger mean x is the left (characters face +z with +y up); each limb's centre is the joint
// halfway along its longest chain.
std::optional<Layout> layoutFromGeometry(const Tree& tree) {
  Layout layout;
  layout.head = highestJoint(tree);
  std::vector<int> trunk = tree.pathFromRoot(layout.head);
  struct Branch {
    int top;
    float extent = 0.0f, minY = 0.0f, meanX = 0.0f;
    int deepest = -1;
  };
  std::vector<Branch> branches;
  for (int t : trunk) {
    for (int c : tree.children[size_t(t)]) {
      if (std::find(trunk.begin(), trunk.end(), c) != trunk.end()) continue;
      Branch b{c};
      std::vector<int> joints = tree.subtree(c);
      b.minY = tree.rest[size_t(c)].y;
      for (int j : joints) {
        float extent = tree.pathLength[size_t(j)] - tree.pathLength[size_t(t)];
        if (extent > b.extent) {
          b.extent = extent;
          b.deepest = j;
        }
        b.minY = std::min(b.minY, tree.rest[size_t(j)].y);
        b.meanX += tree.rest[size_t(j)].x / float(joints.size());
      }
      if (b.deepest >= 0) branches.push_back(b);
    }
  }
  if (branches.size() < 4) return std::nullopt;
  std::sort(branches.begin(), branches.end(),
            [](const Branch& a, const Branch& b) { return a.extent > b.extent; });
  branches.resize(4);
  std::sort(branches.begin(), branches.end(),
            [](const Branch& a, const Branch& b) { return a.minY < b.minY; });
  auto centre = [&](const Branch& b) {
    std::vector<int> path = tree.pathFromRoot(b.deepest);
    return middleOf(tree, std::vector<int>(std::find(path.begin(), path.end(), b.top), path.end()));
  };
  const Branch* legs[2] = {&branches[0], &branches[1]};
  const Branch* arms[2] = {&branches[2], &branches[3]};
  if (legs[0]->meanX < legs[1]->meanX) std::swap(legs[0], legs[1]);
  if (arms[0]->meanX < arms[1]->meanX) std::swap(arms[0], arms[1]);
  layout.limbCentre = {centre(*arms[0]), centre(*arms[1]), centre(*legs[0]), centre(*legs[1])};
  return layout;
}

uint64_t maskOf(const std::vector<int>& joints) {
  uint64_t mask = 0;
  for (int j : joints) mask |= uint64_t(1) << j;
  return mask;
}

// A limb's upper, lower and tip joints: along the path from its centre to its deepest joint.
void setLimbChain(const Tree& tree, BodyPart& part) {
  int deepest = part.centreJoint;
  for (int j : part.joints)
    if (tree.isAncestor(part.centreJoint, j) &&
        tree.pathLength[size_t(j)] > tree.pathLength[size_t(deepest)])
      deepest = j;
  std::vector<int> path = tree.pathFromRoot(deepest);
  auto at = std::find(path.begin(), path.end(), part.centreJoint);
  part.upper = tree.parent[size_t(part.centreJoint)];
  part.lower = at + 1 < path.end() ? *(at + 1) : -1;
  part.tip = at + 2 < path.end() ? *(at + 2) : -1;
}

// Builds the parts from a layout; nullopt when the layout does not describe a body (a limb
// centre on the trunk, two limbs sharing a branch).
std::optional<BodyParts> buildParts(const Tree& tree, const Layout& layout) {
  const std::vector<int> trunk = tree.pathFromRoot(layout.head);
  auto onTrunk = [&](int j) { return std::find(trunk.begin(), trunk.end(), j) != trunk.end(); };
  BodyParts out;
  out.jointCount = tree.size();
  out.allMask = tree.size() == 64 ? ~uint64_t(0) : (uint64_t(1) << tree.size()) - 1;
  std::array<int, 4> limbTop{};
  uint64_t limbJoints = 0;
  const int limbPart[4] = {0, 1, 3, 4};
  for (int k = 0; k < 4; ++k) {
    int top = layout.limbCentre[size_t(k)];
    if (onTrunk(top)) return std::nullopt;
    while (!onTrunk(tree.parent[size_t(top)])) top = tree.parent[size_t(top)];
    limbTop[size_t(k)] = top;
    uint64_t joints = maskOf(tree.subtree(top));
    if (joints & limbJoints) return std::nullopt;
    limbJoints |= joints;
    BodyPart& part = out.parts[size_t(limbPart[k])];
    part.centreJoint = layout.limbCentre[size_t(k)];
    part.joints = tree.subtree(top);
    setLimbChain(tree, part);
  }
  // The pelvis is where the legs leave the trunk; mid-spine is halfway from it to the head.
  int pelvis = std::max(tree.parent[size_t(limbTop[2])], tree.parent[size_t(limbTop[3])]);
  std::vector<int> spine(std::find(trunk.begin(), trunk.end(), pelvis), trunk.end());
  int midSpine = middleOf(tree, spine);
  for (int j : trunk) {
    out.baseMask |= uint64_t(1) << j;
    if (j == midSpine) break;
  }
  out.parents = tree.parent;
  out.pelvis = pelvis;
  out.chest = std::max(tree.parent[size_t(limbTop[0])], tree.parent[size_t(limbTop[1])]);
  out.head = layout.head;
  BodyPart& torso = out.parts[size_t(BodyPartId::Torso)];
  torso.centreJoint = midSpine;
  for (int j = 0; j < tree.size(); ++j)
    if (!((limbJoints >> j) & 1u)) torso.joints.push_back(j);
  for (BodyPart& part : out.parts) {
    uint64_t closed = 0;
    for (int j : part.joints)
      for (int a = j; a >= 0; a = tree.parent[size_t(a)]) closed |= uint64_t(1) << a;
    part.activates = closed & ~out.baseMask;
    // Bone paths bound the distance in every pose, whatever the BVH's rest pose looks like
    // (Bandai Namco lays every bone along +x). The torso's sphere starts at the pelvis: a
    // root below it (Bandai's ground-level joint_Root) would make the sphere body-sized.
    for (int j : part.joints)
      if (j == pelvis || !tree.isAncestor(j, pelvis))
        part.radius = std::max(part.radius, tree.boneDistance(part.centreJoint, j));
  }
  // Until setMeanCentres sees the motion: the rest pose standing on the ground.
  float floor = 0.0f, top = 0.0f;
  for (const glm::vec3& p : tree.rest) floor = std::min(floor, p.y);
  for (const glm::vec3& p : tree.rest) top = std::max(top, p.y);
  out.height = top - floor;
  for (BodyPart& part : out.parts) {
    glm::vec3 p = tree.rest[size_t(part.centreJoint)] - tree.rest[0];
    part.meanCentre = glm::vec3(p.x, p.y - floor, p.z);
  }
  return out;
}

}  // namespace

const char* bodyPartName(int part) {
  THRONG_CHECK(part >= 0 && part < kBodyPartCount, "body part ", part, " out of range");
  return kPartNames[part];
}

std::vector<glm::vec3> restPositions(const anim::Skeleton& skeleton) {
  std::vector<glm::vec3> rest;
  for (const anim::Joint& joint : skeleton.joints) {
    glm::vec3 base = joint.parent >= 0 && joint.parent < int(rest.size())
                         ? rest[size_t(joint.parent)]
                         : glm::vec3(0.0f);
    rest.push_back(base + joint.offset);
  }
  return rest;
}

int countJoints(uint64_t mask) {
  return std::popcount(mask);
}

BodyParts describeBodyParts(const anim::Skeleton& skeleton) {
  Tree tree = makeTree(skeleton);
  if (std::optional<Layout> named = layoutFromNames(skeleton, tree)) {
    if (std::optional<BodyParts> parts = buildParts(tree, *named)) {
      parts->method = "names";
      return *parts;
    }
  }
  if (std::optional<Layout> shaped = layoutFromGeometry(tree)) {
    if (std::optional<BodyParts> parts = buildParts(tree, *shaped)) {
      parts->method = "geometry";
      return *parts;
    }
  }
  fail("body parts: cannot find two arms and two legs in a ", skeleton.jointCount(),
       "-joint skeleton: expected joints named like LeftForeArm/LeftLeg (or a rest pose with four "
       "limbs "
       "hanging off the root-to-head chain)");
}

void setMeanCentres(BodyParts& parts, const anim::MotionPair& pair) {
  if (pair.jointCount() != parts.jointCount)
    fail("body parts: the motion pair has ", pair.jointCount(), " joints, the body parts describe ",
         parts.jointCount);
  std::vector<anim::PoseJoint> pose(size_t(parts.jointCount));
  std::array<glm::dvec3, kBodyPartCount> sum{};
  double heights = 0.0;
  int samples = 0;
  for (float w : {0.0f, 1.0f}) {
    int frames = w == 0.0f ? pair.slow.frameCount : pair.fast.frameCount;
    for (int f = 0; f < frames; ++f, ++samples) {
      anim::poseCharacterSpace(pair, (float(f) + 0.5f) / float(frames), w, pose);
      for (int k = 0; k < kBodyPartCount; ++k)
        sum[size_t(k)] += glm::dvec3(pose[size_t(parts.parts[size_t(k)].centreJoint)].position);
      auto [low, high] = std::minmax_element(
          pose.begin(), pose.end(), [](const anim::PoseJoint& a, const anim::PoseJoint& b) {
            return a.position.y < b.position.y;
          });
      heights += double(high->position.y - low->position.y);
    }
  }
  if (samples == 0) fail("body parts: the motion pair has no frames");
  for (int k = 0; k < kBodyPartCount; ++k)
    parts.parts[size_t(k)].meanCentre = glm::vec3(sum[size_t(k)] / double(samples));
  parts.height = float(heights / double(samples));
  parts.slowCycleSeconds = pair.slow.duration();
  parts.fastCycleSeconds = pair.fast.duration();
  parts.jointRadius = pair.jointRadius;
}

namespace {

uint64_t ancestorsClosed(uint64_t mask, const std::vector<int32_t>& parents) {
  uint64_t closed = 0;
  for (int j = 0; j < int(parents.size()) && j < 64; ++j)
    if ((mask >> j) & 1u)
      for (int a = j; a >= 0; a = parents[size_t(a)]) closed |= uint64_t(1) << a;
  return closed;
}

uint64_t bitsOf(std::initializer_list<int> joints) {
  uint64_t mask = 0;
  for (int j : joints)
    if (j >= 0 && j < 64) mask |= uint64_t(1) << j;
  return mask;
}

// Each drawn joint's bone starts at its nearest ancestor that is drawn or is the pelvis.
void setBones(const BodyParts& parts, LevelJoints& level) {
  level.boneFrom.fill(255);
  level.boneRadius.fill(1.0f);
  const uint64_t anchors = level.draw | bitsOf({parts.pelvis});
  for (int j = 0; j < parts.jointCount; ++j) {
    if (!((level.draw >> j) & 1u)) continue;
    const int parent = parts.parents[size_t(j)];
    int from = parent;
    while (from >= 0 && !((anchors >> from) & 1u)) from = parts.parents[size_t(from)];
    if (from < 0 || from == parent) continue;
    level.boneFrom[size_t(j)] = uint8_t(from);
    if (parts.jointRadius.size() != size_t(parts.jointCount) ||
        !(parts.jointRadius[size_t(j)] > 0.0f))
      continue;
    float thickest = 0.0f;
    for (int k = j; k != from; k = parts.parents[size_t(k)])
      thickest = std::max(thickest, parts.jointRadius[size_t(k)]);
    level.boneRadius[size_t(j)] = thickest / parts.jointRadius[size_t(j)];
  }
}

}  // namespace

std::array<LevelJoints, 3> levelJoints(const BodyParts& parts) {
  std::array<LevelJoints, 3> levels;
  const BodyPart* arms[2] = {&parts.parts[size_t(BodyPartId::LeftArm)],
                             &parts.parts[size_t(BodyPartId::RightArm)]};
  const BodyPart* legs[2] = {&parts.parts[size_t(BodyPartId::LeftLeg)],
                             &parts.parts[size_t(BodyPartId::RightLeg)]};
  const uint64_t trunk = bitsOf({0, parts.pelvis, parts.chest, parts.head});
  uint64_t mid = trunk, far = trunk;
  for (const BodyPart* arm : arms) {
    mid |= bitsOf({arm->lower});
    far |= bitsOf({arm->upper, arm->centreJoint, arm->lower});
  }
  for (const BodyPart* leg : legs) {
    mid |= bitsOf({leg->lower, leg->tip});
    far |= bitsOf({leg->upper, leg->centreJoint, leg->lower});
  }
  mid = ancestorsClosed(mid, parts.parents);
  levels[0].draw = far;
  levels[1].draw = mid;
  levels[2].draw = parts.allMask;
  for (LevelJoints& level : levels) {
    level.synth = ancestorsClosed(level.draw, parts.parents);
    setBones(parts, level);
  }
  return levels;
}

}  // namespace throng::synth
