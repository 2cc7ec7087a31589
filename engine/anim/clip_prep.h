#pragma once
// Preparing real capture before baking: units to metres, common frame rate, the best loop
// cut out of a raw capture, travel along +z, and the slow/fast pair aligned by foot contact.
#include <string>

#include "anim/clip.h"

namespace throng::anim {

struct UnitsGuess {
  float metresPerUnit = 1.0f;
  float heightInUnits = 0.0f;  // standing height of the skeleton (rest pose), file units
  std::string label;           // "metres", "centimetres", "cmu-units", "inches", ...
};
// Guess the unit from the skeleton's rest height (a person is ~1.5–2.0 m tall).
UnitsGuess detectUnits(const Skeleton& skeleton);
// Offsets, End Sites, root positions, animated offsets and travel, times metresPerUnit.
Clip scaleToMetres(const Clip& clip, float metresPerUnit);

// Resample to a new frame time (slerp rotations, lerp root positions and animated offsets).
// The duration is kept exactly: the clip gets round(duration / frameTime) frames, so the
// frame time actually used is the nearest one that divides the duration. A clip with a
// non-zero cycleTravel is a cycle (the frame after the last is frame 0 moved by cycleTravel,
// with frame 0's animated offsets); any other holds its last frame.
Clip resample(const Clip& clip, float frameTime);
// The same with the frame count given (frame time = duration / frameCount).
Clip resampleFrames(const Clip& clip, int frameCount, bool cyclic);

struct LoopCut {
  int start = 0;    // first frame of the cycle
  int end = 0;      // one past the last frame: frame `end` ≈ frame `start`
  float error = 0;  // pose + velocity distance between start and end (radians-ish, per joint)
  int length() const { return end - start; }
};
// Best cycle in [minFrames, maxFrames] frames by pose and velocity similarity (root
// positions and animated offsets in metres). A leading calibration T-pose is skipped; when
// two or three cycles match about as well as one, the single cycle is returned. Error when
// no cut fits.
LoopCut findBestLoop(const Clip& clip, int minFrames, int maxFrames);
// The distance findBestLoop scores a cut (start, end) with, to compare with other pairs.
float loopError(const Clip& clip, int start, int end);
// Frames [start, end) as a cyclic clip; cycleTravel = root(end) - root(start).
Clip cutLoop(const Clip& clip, const LoopCut& cut);
// cutLoop, then the pose, root-height and animated-offset mismatch left between frames end
// and start is spread over the cycle (frame k gets k/length of it), so the cycle repeats
// without a pop and without climbing or sinking: cycleTravel.y becomes 0. preparePair uses
// this.
Clip closeSeam(const Clip& clip, const LoopCut& cut);

// Rotates the whole clip about +y so its net travel points along +z and puts the first
// frame's root above the origin. Animated offsets are local to their parents, which turn
// with the root, so they stay as they are.
Clip faceForwardZ(const Clip& clip);

// Rotates `fast` cyclically so its left-foot contact falls at the same phase as in `slow`.
// Returns the frame shift applied. Both clips must share a topology (else Error).
int alignPhases(const Clip& slow, Clip& fast);

struct PairOptions {
  float metresPerUnit = 0.0f;  // 0: detect from the skeleton height
  float frameTime = 1.0f / 30.0f;
  bool cutLoops = true;  // false for clips that are already cycles
};
struct PreparedPair {
  Clip slow;
  Clip fast;
  LoopCut slowLoop;
  LoopCut fastLoop;
};
// The most joints a skeleton may have for the synthesis passes (synth's pose pass keeps a
// joint's parent chain in 64-bit masks); preparePair refuses more, naming the file.
inline constexpr int kMaxPoseJoints = 64;

// The whole preparation for a slow/fast pair; a topology mismatch is a clear Error, and every
// Error names the BVH file (RawClip::sourceName) it concerns. Each clip:
// toClip, metres, resample to options.frameTime, best loop of 0.4–1.6 s (closeSeam; a clip
// too short for that, or cutLoops false, is one whole cycle whose travel is the mean root
// velocity × duration), faceForwardZ; then both get the mean of the two cycle lengths in
// frames (so frame f of one matches frame f of the other) and alignPhases.
PreparedPair preparePair(const RawClip& slow, const RawClip& fast, const PairOptions& options);

}  // namespace throng::anim
