#include "secondary/offline/blend_motion.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/rng.h"
#include "secondary/cloth_decoder.h"
#include "secondary/offline/explore_file.h"
#include "synth/motion_cache.h"

namespace throng::secondary {

void shownClothPositions(const ClothCharacter& c, const StatePositions& positions,
                         std::span<glm::vec3> out) {
  const std::span<const glm::vec3> state = positions(c.state);
  std::copy(state.begin(), state.end(), out.begin());
  const float w = blendSourceWeight(c);
  if (w <= 0.0f || c.blendSource == kNoClothState) return;
  const std::span<const glm::vec3> source = positions(c.blendSource);
  for (size_t v = 0; v < out.size(); ++v) out[v] = glm::mix(out[v], source[v], w);
}

float quantile(std::vector<float> values, float q) {
  if (values.empty()) return 0.0f;
  const size_t rank = size_t(std::ceil(std::clamp(q, 0.0f, 1.0f) * float(values.size())));
  const size_t k = std::min(values.size() - 1, rank > 0 ? rank - 1 : 0);
  std::nth_element(values.begin(), values.begin() + long(k), values.end());
  return values[k];
}

namespace {
// A runner of the run graph: its speed weight (a bucket centre) and phase.
struct Runner {
  float w = 0.0f, phase = 0.0f;
  ClothCharacter cloth = noClothCharacter();
  std::vector<glm::vec3> shown;
};

float largestMove(std::span<const glm::vec3> a, std::span<const glm::vec3> b) {
  float largest = 0.0f;
  for (size_t v = 0; v < a.size(); ++v) largest = std::max(largest, glm::length(a[v] - b[v]));
  return largest;
}
}  // namespace

BlendMotionReport measureBlendMotion(const ClothDatabase& db, const StatePositions& positions,
                                     const BlendMotionOptions& o) {
  const PlaybackTables tables = makePlaybackTables(db);
  const RunGraphParams& run = db.primary.run;
  std::vector<uint32_t> buckets;
  for (uint32_t b = 0; b < run.framesPerBucket.size(); ++b)
    if (run.framesPerBucket[b] > 0) buckets.push_back(b);
  if (buckets.empty()) fail("blend motion: the database's run graph has no node");
  Rng rng(o.seed, 11);
  auto anySpeed = [&] {
    return synth::bucketSpeed(buckets[rng.next() % buckets.size()], run.bucketWidth);
  };
  BlendMotionReport report;
  std::vector<glm::vec3> shown(db.vertexCount);
  for (uint32_t i = 0; i < o.characters; ++i) {
    Runner r{anySpeed(), 0.0f, noClothCharacter(), {}};
    {
      // Start mid-frame, so one step of 1 / F moves exactly one node.
      const float frames =
          float(run.framesPerBucket[synth::speedBucket(r.w, run.bucketWidth, tables.bucketCount)]);
      r.phase = (std::floor(rng.uniform() * frames) + 0.5f) / frames;
    }
    for (uint32_t step = 0; step <= o.steps; ++step) {
      const uint32_t node = r.cloth.node;
      const bool merged = advanceCharacter(db, tables, r.cloth, {r.phase, r.w, r.w, 1.0f});
      if (r.cloth.state != kNoClothState) {
        shownClothPositions(r.cloth, positions, shown);
        if (!r.shown.empty() && node != kNoNode && r.cloth.node != node)
          (merged ? report.mergeSteps : report.ordinarySteps)
              .push_back(largestMove(shown, r.shown));
        r.shown = shown;
      }
      const uint32_t frames =
          run.framesPerBucket[synth::speedBucket(r.w, run.bucketWidth, tables.bucketCount)];
      r.phase += 1.0f / float(frames);
      if (r.phase >= 1.0f) {
        r.phase -= std::floor(r.phase);
        if (rng.uniform() < o.speedChangeChance) r.w = anySpeed();
      }
    }
  }
  report.p95Merge = quantile(report.mergeSteps, 0.95f);
  report.p95Ordinary = quantile(report.ordinarySteps, 0.95f);
  return report;
}

BlendMotionReport measureBlendMotion(const ExploreFile& file, const BlendMotionOptions& o) {
  const nlohmann::json& garment = file.config.value("garment", nlohmann::json::object());
  const float bucketWidth =
      garment.contains("cape") ? garment["cape"].value("bucket_width", 0.05f) : 0.05f;
  ClothDatabase db;
  db.vertexCount = file.graph.vertexCount;
  db.primary = playbackPrimary(file.primary, bucketWidth);
  db.graph = playbackGraph(file.graph);
  return measureBlendMotion(
      db, [&](uint32_t s) { return file.graph.frame(s).positions; }, o);
}

BlendMotionReport measureBlendMotion(const ClothDatabase& db, const BlendMotionOptions& o) {
  // States are decoded as they are shown, into a few slots (a step reads a state, then its blend
  // source): memory stays at a few frames however large the database.
  const DecodedBases bases = dequantize(db);
  std::vector<std::vector<glm::vec3>> slots(4, std::vector<glm::vec3>(db.vertexCount));
  std::vector<uint32_t> slotState(slots.size(), kNoClothState);
  size_t next = 0;
  return measureBlendMotion(
      db,
      [&](uint32_t s) -> std::span<const glm::vec3> {
        for (size_t i = 0; i < slots.size(); ++i)
          if (slotState[i] == s) return slots[i];
        next = (next + 1) % slots.size();
        slotState[next] = s;
        decodeState(bases, s, slots[next]);
        return slots[next];
      },
      o);
}

}  // namespace throng::secondary
