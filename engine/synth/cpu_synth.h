#pragma once
// The CPU path for a whole crowd: the reference synthesizer run over every character on one or
// many threads. It is the twin the GPU passes are tested against and the bench's baseline.
#include <functional>
#include <span>

#include "anim/motion_texture.h"
#include "crowd/crowd.h"
#include "synth/gpu_types.h"

namespace throng::synth {

// A range of characters: the group [first, first + count) of a crowd, as the GPU passes take it.
struct CharacterRange {
  size_t first = 0;
  size_t count = 0;
};

void stepCrowdCpu(const anim::MotionPair& pair, crowd::Crowd& crowd, float dt, unsigned threads = 1,
                  const anim::SpeedRetarget& retarget = {});
void stepCrowdCpu(const anim::MotionPair& pair, crowd::Crowd& crowd, CharacterRange range, float dt,
                  unsigned threads = 1, const anim::SpeedRetarget& retarget = {});
// `out` holds crowd.size() × jointCount joint points (character i's from i × jointCount).
void poseCrowdCpu(const anim::MotionPair& pair, const crowd::Crowd& crowd,
                  std::span<JointPoint> out, unsigned threads = 1);
void poseCrowdCpu(const anim::MotionPair& pair, const crowd::Crowd& crowd, CharacterRange range,
                  std::span<JointPoint> out, unsigned threads = 1);

// Runs body(begin, end) over [0, count) split across `threads` threads.
void parallelFor(size_t count, unsigned threads, const std::function<void(size_t, size_t)>& body);

}  // namespace throng::synth
