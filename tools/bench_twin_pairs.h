#pragma once
// The bench's full-path ratio: the GPU synthesis of every joint (no LOD, no cache) and the CPU
// twin on all threads, a frame of each in turn, so that both see the machine as it is at that
// moment (a shared VM's speed swings by a third within minutes, more than the rows measured one
// after the other can tell from a change of code).
#include <cstdint>
#include <vector>

#include "anim/motion_texture.h"
#include "crowd/crowd.h"
#include "gpu/context.h"
#include "stats.h"
#include "synth/synth_jobs.h"

namespace throng::tools {

// The bench's crowd of `characters`: the default scenario, seed 42.
crowd::Crowd benchCrowd(uint32_t characters);

// One frame of the CPU twin on `threads` threads (a step and the pose into `joints`); its wall
// milliseconds.
double twinFrameMs(const anim::MotionPair& pair, crowd::Crowd& crowd,
                   std::vector<synth::JointPoint>& joints, unsigned threads);

struct TwinPairResult {
  uint32_t characters = 0;
  unsigned threads = 1;  // the twin's
  int pairs = 0;         // measured pairs of frames
  double gpuMs = 0.0;    // the GPU frame, median
  double twinMs = 0.0;   // the twin's frame (step and pose), median
  Spread ratio;          // per pair: twin / GPU
};

// warmup pairs, for at least warmupSeconds (WarmUp), before `pairs` measured ones.
TwinPairResult benchFullAgainstTwin(const gpu::Context& context,
                                    const synth::SynthPrograms& programs,
                                    const anim::MotionPair& pair, const anim::Skeleton& skeleton,
                                    uint32_t characters, unsigned threads, int pairs, int warmup,
                                    double warmupSeconds);

}  // namespace throng::tools
