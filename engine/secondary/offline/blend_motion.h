#pragma once
// How smoothly playback shows the cape where its traversal crosses a merge edge: characters run
// along the database's run graph (one primary frame per step, a new speed now and then at a cycle
// end, as the synthesizer changes speed), their capes advance with advanceCharacter, and each step
// records the largest vertex move of the shown cape (character space, the blend included), split
// into the steps that crossed a merge edge or jumped and the others.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "secondary/cloth_playback.h"

namespace throng::secondary {

// Positions (character space, vertexCount of them) of a cloth state.
using StatePositions = std::function<std::span<const glm::vec3>(uint32_t state)>;

// The cape a character shows at the finest levels (cloth.vert's twin): its state blended with its
// blend source by blendSourceWeight.
void shownClothPositions(const ClothCharacter& c, const StatePositions& positions,
                         std::span<glm::vec3> out);

struct BlendMotionOptions {
  uint32_t characters = 32;
  uint32_t steps = 600;  // per character
  uint64_t seed = 1;
  float speedChangeChance = 0.5f;  // at a cycle end: the chance of a new speed bucket
};

struct BlendMotionReport {
  std::vector<float> mergeSteps;     // largest vertex move (m) of each step that crossed a merge
  std::vector<float> ordinarySteps;  // and of the other steps that moved the character's node
  float p95Merge = 0.0f, p95Ordinary = 0.0f;
  // p95 at merge steps over p95 at ordinary steps (1: a merge moves the cape like any frame).
  float ratio() const { return p95Ordinary > 0.0f ? p95Merge / p95Ordinary : 0.0f; }
};

// Throws Error when the database's run graph has no node to run on.
BlendMotionReport measureBlendMotion(const ClothDatabase& db, const StatePositions& positions,
                                     const BlendMotionOptions& options = {});

// The same on an explored graph (.tsg: the simulator's own frames, playback's tables from its
// run graph) and on a compressed database (.tsc: the decoded states).
struct ExploreFile;
BlendMotionReport measureBlendMotion(const ExploreFile& file,
                                     const BlendMotionOptions& options = {});
BlendMotionReport measureBlendMotion(const ClothDatabase& db,
                                     const BlendMotionOptions& options = {});

// The q-quantile (0 … 1) of values, nearest rank; 0 for none.
float quantile(std::vector<float> values, float q);

}  // namespace throng::secondary
