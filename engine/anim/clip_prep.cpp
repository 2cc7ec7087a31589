// Units, frame rate, loop cutting and facing of real captures (see clip_prep.h); the loop
// search lives in clip_prep_loop.cpp and the foot-contact alignment in clip_prep_phase.cpp.
#include "anim/clip_prep.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "anim/clip_prep_util.h"
#include "core/error.h"
#include "core/math.h"
#include "core/text.h"

namespace throng::anim {
namespace {

constexpr float kPersonHeight = 1.75f;          // metres, when nothing says otherwise
constexpr float kCmuMetresPerUnit = 0.056444f;  // (1/0.45) inch: the CMU ASF length unit
// A rest pose is upright when its height spans most of the head-to-foot bone chain; Bandai
// Namco lays every bone along +x, so its height is only the hips' offset.
constexpr float kUprightRatio = 0.7f;
constexpr float kMinCycleSeconds = 0.4f;  // a fast run
constexpr float kMaxCycleSeconds = 1.6f;  // a slow walk
// Longest capture prepared: the loop search compares every start with every cycle length, so
// its time grows with the clip's length (a 3-frame file with `Frame Time: 3333` is 2.8 hours).
constexpr float kMaxClipSeconds = 600.0f;
constexpr int kMaxFrames = 1 << 20;  // 9.7 hours at 30 fps

bool nameHas(const Joint& joint, const char* word) {
  return toLower(joint.name).find(word) != std::string::npos;
}

// Length of the bone path between joints a and b (through their common ancestor).
float pathLength(const Skeleton& skeleton, int a, int b) {
  float length = 0.0f;
  while (a != b) {
    // Parents come first, so the deeper index is never the other's ancestor.
    int& deeper = a > b ? a : b;
    length += glm::length(skeleton.joints[size_t(deeper)].offset);
    deeper = skeleton.joints[size_t(deeper)].parent;
    if (deeper < 0) return -1.0f;  // disconnected (cannot happen with one root)
  }
  return length;
}

// Top of the head (its End Site when there is one) down to the lower ankle, along the
// bones: the standing height when the rest pose is not upright. 0 when no joint is named
// like a head and a foot.
float headToFootChain(const Skeleton& skeleton) {
  float best = 0.0f;
  for (int h = 0; h < skeleton.jointCount(); ++h) {
    const Joint& head = skeleton.joints[size_t(h)];
    if (!nameHas(head, "head")) continue;
    float top = head.endSite ? glm::length(*head.endSite) : 0.0f;
    for (int f = 0; f < skeleton.jointCount(); ++f) {
      const Joint& foot = skeleton.joints[size_t(f)];
      if (!nameHas(foot, "foot") && !nameHas(foot, "ankle")) continue;
      best = std::max(best, top + pathLength(skeleton, h, f));
    }
  }
  return best;
}

UnitsGuess classify(float height) {
  struct Range {
    float lo, hi, metresPerUnit;
    const char* label;
  };
  // Each range is a plausible person (≈1.1–2.5 m) in that unit; CMU subjects measure 24–27
  // units from toe to the head's End Site (1.4–1.5 m: the End Site is below the crown).
  static const Range kRanges[] = {{1.0f, 2.5f, 1.0f, "metres"},
                                  {100.0f, 250.0f, 0.01f, "centimetres"},
                                  {1000.0f, 2500.0f, 0.001f, "millimetres"},
                                  {20.0f, 42.0f, kCmuMetresPerUnit, "cmu-units"},
                                  {45.0f, 98.0f, 0.0254f, "inches"}};
  UnitsGuess guess;
  guess.heightInUnits = height;
  for (const Range& range : kRanges) {
    if (height >= range.lo && height <= range.hi) {
      guess.metresPerUnit = range.metresPerUnit;
      guess.label = range.label;
      return guess;
    }
  }
  guess.label = "unknown";
  guess.metresPerUnit = height > 0.0f ? kPersonHeight / height : 1.0f;
  return guess;
}

Clip copyHeader(const Clip& clip, int frameCount) {
  Clip out;
  out.name = clip.name;
  out.skeleton = clip.skeleton;
  out.frameCount = frameCount;
  out.frameTime = clip.frameTime;
  out.cycleTravel = clip.cycleTravel;
  out.rotations.reserve(size_t(frameCount) * size_t(clip.jointCount()));
  out.rootPositions.reserve(size_t(frameCount));
  if (!clip.animatedOffsets.empty())
    out.animatedOffsets.reserve(size_t(frameCount) * size_t(clip.jointCount()));
  return out;
}

// Frames [first, frameCount) as a cycle whose travel is the mean root velocity × duration:
// for clips that are about one cycle already, too short to search for a loop.
Clip wholeCycle(const Clip& clip, int first, LoopCut& cut) {
  Clip out = copyHeader(clip, clip.frameCount - first);
  out.rotations.assign(clip.rotations.begin() + ptrdiff_t(first) * clip.jointCount(),
                       clip.rotations.end());
  out.rootPositions.assign(clip.rootPositions.begin() + first, clip.rootPositions.end());
  if (!clip.animatedOffsets.empty()) {
    out.animatedOffsets.assign(clip.animatedOffsets.begin() + ptrdiff_t(first) * clip.jointCount(),
                               clip.animatedOffsets.end());
  }
  int n = out.frameCount;
  out.cycleTravel =
      n > 1 ? (out.rootPositions.back() - out.rootPositions.front()) * (float(n) / float(n - 1))
            : glm::vec3(0.0f);
  cut = LoopCut{first, clip.frameCount, 0.0f};  // no closing frame to compare with
  return out;
}

Clip prepareClip(const RawClip& raw, const PairOptions& options, LoopCut& cut) {
  Clip clip = toClip(raw);
  if (!(clip.duration() <= kMaxClipSeconds))
    fail("clip ", clip.name, ": ", clip.frameCount, " frames of ", clip.frameTime, " s is ",
         clip.duration(), " s; clips of up to ", kMaxClipSeconds, " s are prepared");
  float metresPerUnit = options.metresPerUnit > 0.0f ? options.metresPerUnit
                                                     : detectUnits(clip.skeleton).metresPerUnit;
  clip = resample(scaleToMetres(clip, metresPerUnit), options.frameTime);
  int first = prep::firstUsableFrame(clip);
  int usable = clip.frameCount - 1 - first;
  int minFrames = std::max(2, int(std::lround(kMinCycleSeconds / clip.frameTime)));
  int maxFrames = std::min(usable, int(std::lround(kMaxCycleSeconds / clip.frameTime)));
  if (!options.cutLoops || usable < minFrames) {
    clip = wholeCycle(clip, first, cut);
  } else {
    cut = findBestLoop(clip, minFrames, maxFrames);
    clip = closeSeam(clip, cut);
  }
  return faceForwardZ(clip);
}

// prepareClip with every error naming the file the clip came from (Clip keeps only its stem).
Clip prepareOne(const RawClip& raw, const PairOptions& options, LoopCut& cut) {
  try {
    return prepareClip(raw, options, cut);
  } catch (const Error& e) {
    const std::string message = e.what();
    if (message.rfind(raw.sourceName, 0) == 0) throw;
    fail(raw.sourceName, ": ", message);
  }
}

void checkPoseJoints(const RawClip& raw) {
  const int joints = raw.skeleton.jointCount();
  if (joints < 1 || joints > kMaxPoseJoints)
    fail(raw.sourceName, ": ", joints, " joints; the pose pass supports 1..", kMaxPoseJoints,
         " joints (a skeleton with fewer joints is needed)");
}

void checkPairTopology(const Skeleton& slow, const std::string& slowName, const Skeleton& fast,
                       const std::string& fastName) {
  if (slow.jointCount() != fast.jointCount()) {
    fail("slow clip ", slowName, " has ", slow.jointCount(), " joints, fast clip ", fastName,
         " has ", fast.jointCount(), ": a pair must share one skeleton");
  }
  if (!slow.sameTopology(fast)) {
    fail("slow clip ", slowName, " and fast clip ", fastName, " both have ", slow.jointCount(),
         " joints but different parents: a pair must share one skeleton");
  }
}

}  // namespace

UnitsGuess detectUnits(const Skeleton& skeleton) {
  if (skeleton.jointCount() == 0) fail("detectUnits: the skeleton has no joints");
  // Rest pose: offsets accumulated down the hierarchy, End Sites included.
  std::vector<glm::vec3> rest(static_cast<size_t>(skeleton.jointCount()));
  float lo = std::numeric_limits<float>::infinity();
  float hi = -lo;
  for (int j = 0; j < skeleton.jointCount(); ++j) {
    const Joint& joint = skeleton.joints[size_t(j)];
    if (joint.parent >= j) fail("detectUnits: joint ", joint.name, " comes before its parent");
    rest[size_t(j)] =
        (joint.parent < 0 ? glm::vec3(0.0f) : rest[size_t(joint.parent)]) + joint.offset;
    lo = std::min(lo, rest[size_t(j)].y);
    hi = std::max(hi, rest[size_t(j)].y);
    if (joint.endSite) {
      lo = std::min(lo, rest[size_t(j)].y + joint.endSite->y);
      hi = std::max(hi, rest[size_t(j)].y + joint.endSite->y);
    }
  }
  float height = hi - lo;
  float chain = headToFootChain(skeleton);
  if (chain > 0.0f && height < kUprightRatio * chain) height = chain;
  return classify(height);
}

Clip scaleToMetres(const Clip& clip, float metresPerUnit) {
  if (!(metresPerUnit > 0.0f) || !std::isfinite(metresPerUnit)) {
    fail("clip ", clip.name, ": metres per unit must be a positive number, got ", metresPerUnit);
  }
  Clip out = clip;
  for (Joint& joint : out.skeleton.joints) {
    joint.offset *= metresPerUnit;
    if (joint.endSite) *joint.endSite *= metresPerUnit;
  }
  for (glm::vec3& p : out.rootPositions) p *= metresPerUnit;
  for (glm::vec3& o : out.animatedOffsets) o *= metresPerUnit;
  out.cycleTravel *= metresPerUnit;
  return out;
}

Clip resampleFrames(const Clip& clip, int frameCount, bool cyclic) {
  prep::checkClip(clip);
  // The cap keeps a typo in a frame time (1e-9 s) an Error rather than an allocation failure.
  if (frameCount < 1 || frameCount > kMaxFrames) {
    fail("clip ", clip.name, ": cannot resample to ", frameCount, " frames (expected 1 to ",
         kMaxFrames, ")");
  }
  const int frames = clip.frameCount;
  Clip out = copyHeader(clip, frameCount);
  out.frameTime = clip.duration() / float(frameCount);
  for (int k = 0; k < frameCount; ++k) {
    // In source frames, in double so that shared instants land exactly on a source frame.
    double u = double(k) * double(frames) / double(frameCount);
    int i0 = std::min(frames - 1, int(std::floor(u)));
    float t = float(u - double(i0));
    int i1 = i0 + 1;
    glm::vec3 offset1(0.0f);
    if (i1 >= frames) {
      if (cyclic) {
        i1 = 0;
        offset1 = clip.cycleTravel;
      } else {
        i1 = frames - 1;  // past the last frame of a non-cycle: hold it
      }
    }
    for (int j = 0; j < clip.jointCount(); ++j) {
      glm::vec4 a = clip.rotation(i0, j);
      out.rotations.push_back(t == 0.0f ? a : slerpShortest(a, clip.rotation(i1, j), t));
    }
    glm::vec3 p0 = clip.rootPositions[size_t(i0)];
    glm::vec3 p1 = clip.rootPositions[size_t(i1)] + offset1;
    out.rootPositions.push_back(t == 0.0f ? p0 : p0 + t * (p1 - p0));
    if (clip.animatedOffsets.empty()) continue;
    // Local offsets do not travel: past the end of a cycle they are frame 0's.
    const size_t joints = size_t(clip.jointCount());
    for (size_t j = 0; j < joints; ++j) {
      glm::vec3 a = clip.animatedOffsets[size_t(i0) * joints + j];
      glm::vec3 b = clip.animatedOffsets[size_t(i1) * joints + j];
      out.animatedOffsets.push_back(t == 0.0f ? a : a + t * (b - a));
    }
  }
  return out;
}

Clip resample(const Clip& clip, float frameTime) {
  if (!(frameTime > 0.0f) || !std::isfinite(frameTime)) {
    fail("clip ", clip.name, ": the frame time must be a positive number of seconds, got ",
         frameTime);
  }
  prep::checkClip(clip);
  double frames = std::max(1.0, std::round(double(clip.duration()) / double(frameTime)));
  int frameCount = int(std::min(frames, double(kMaxFrames) + 1.0));
  return resampleFrames(clip, frameCount, clip.cycleTravel != glm::vec3(0.0f));
}

Clip cutLoop(const Clip& clip, const LoopCut& cut) {
  prep::checkClip(clip);
  if (cut.start < 0 || cut.end <= cut.start || cut.end >= clip.frameCount) {
    fail("clip ", clip.name, ": loop [", cut.start, ", ", cut.end, ") needs 0 <= start < end < ",
         clip.frameCount, " (the end frame closes the cycle)");
  }
  Clip out = copyHeader(clip, cut.length());
  const ptrdiff_t joints = clip.jointCount();
  out.rotations.assign(clip.rotations.begin() + cut.start * joints,
                       clip.rotations.begin() + cut.end * joints);
  out.rootPositions.assign(clip.rootPositions.begin() + cut.start,
                           clip.rootPositions.begin() + cut.end);
  if (!clip.animatedOffsets.empty()) {
    out.animatedOffsets.assign(clip.animatedOffsets.begin() + cut.start * joints,
                               clip.animatedOffsets.begin() + cut.end * joints);
  }
  out.cycleTravel = clip.rootPositions[size_t(cut.end)] - clip.rootPositions[size_t(cut.start)];
  return out;
}

Clip closeSeam(const Clip& clip, const LoopCut& cut) {
  Clip out = cutLoop(clip, cut);
  const int length = cut.length();
  const int joints = clip.jointCount();
  const float rise = out.cycleTravel.y;
  for (int k = 1; k < length; ++k) {
    float t = float(k) / float(length);
    for (int j = 0; j < joints; ++j) {
      // r takes frame `end` onto frame `start`; frame k gets the fraction k / length of it.
      glm::vec4 r =
          quatMul(clip.rotation(cut.start, j), prep::conjugate(clip.rotation(cut.end, j)));
      glm::vec4& q = out.rotations[size_t(k) * size_t(joints) + size_t(j)];
      q = glm::normalize(quatMul(slerpShortest(glm::vec4(0, 0, 0, 1), r, t), q));
    }
    out.rootPositions[size_t(k)].y -= t * rise;
    // Animated offsets close the same way: with a root that only slides (Bandai Namco), the
    // hips' height mismatch is here, and spreading it keeps the cycle from climbing.
    if (out.animatedOffsets.empty()) continue;
    for (int j = 1; j < joints; ++j) {
      glm::vec3 gap = clip.animatedOffsets[size_t(cut.start) * size_t(joints) + size_t(j)] -
                      clip.animatedOffsets[size_t(cut.end) * size_t(joints) + size_t(j)];
      out.animatedOffsets[size_t(k) * size_t(joints) + size_t(j)] += t * gap;
    }
  }
  out.cycleTravel.y = 0.0f;
  return out;
}

Clip faceForwardZ(const Clip& clip) {
  prep::checkClip(clip);
  glm::vec3 travel = clip.cycleTravel;
  if (glm::length(glm::vec2(travel.x, travel.z)) < 1e-6f)
    travel = clip.rootPositions.back() - clip.rootPositions.front();
  glm::vec4 turn(0.0f, 0.0f, 0.0f, 1.0f);
  // Travelling in place has no direction to face: only the translation applies.
  if (glm::length(glm::vec2(travel.x, travel.z)) >= 1e-6f)
    turn = yawQuat(-std::atan2(travel.x, travel.z));
  Clip out = clip;
  for (int f = 0; f < out.frameCount; ++f) {
    glm::vec4& root = out.rotations[size_t(f) * size_t(out.jointCount())];
    root = quatMul(turn, root);
    out.rootPositions[size_t(f)] = quatRotate(turn, out.rootPositions[size_t(f)]);
  }
  glm::vec3 origin = out.rootPositions.front();
  for (glm::vec3& p : out.rootPositions) p -= glm::vec3(origin.x, 0.0f, origin.z);
  out.cycleTravel = quatRotate(turn, clip.cycleTravel);
  return out;
}

PreparedPair preparePair(const RawClip& slow, const RawClip& fast, const PairOptions& options) {
  checkPoseJoints(slow);
  checkPoseJoints(fast);
  checkPairTopology(slow.skeleton, slow.sourceName, fast.skeleton, fast.sourceName);
  if (!(options.frameTime > 0.0f))
    fail("preparePair: the frame time must be positive, got ", options.frameTime);
  PreparedPair pair;
  pair.slow = prepareOne(slow, options, pair.slowLoop);
  pair.fast = prepareOne(fast, options, pair.fastLoop);
  // One frame count for both so that frame f of one is frame f of the other (phase f/F).
  int frames = std::max(1, int(std::lround(0.5 * (pair.slow.frameCount + pair.fast.frameCount))));
  pair.slow = resampleFrames(pair.slow, frames, true);
  pair.fast = resampleFrames(pair.fast, frames, true);
  alignPhases(pair.slow, pair.fast);
  return pair;
}

}  // namespace throng::anim
