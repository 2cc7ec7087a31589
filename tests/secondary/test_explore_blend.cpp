// The merge blend on an explored cape: playback along the graph moves the shown cape no more in a
// frame that crosses a merge edge than in any other frame (p95 of the largest vertex move).
#include <doctest/doctest.h>

#include "secondary/offline/blend_motion.h"
#include "secondary/offline/explore.h"
#include "secondary/offline/explore_file.h"
#include "secondary/offline/garment.h"

using namespace throng;
using namespace throng::secondary;

namespace {
// A 16 × 24 cape explored for 300 expansions (about 2 s): merges come every few frames along a
// path, so blends are often still under way when the next merge comes.
ExploreFile exploredCape() {
  nlohmann::json config = defaultGarmentConfig("cape");
  config["cape"]["columns"] = 16;
  config["cape"]["rows"] = 24;
  const Garment garment = buildGarment(config);
  ThreadedRunner runner(*garment.primary, garment.step, 2);
  const MergeMetric metric{garment.primary->frameTime, garment.term};
  SecondaryGraph graph = initializeGraph(*garment.primary, runner, metric, initialNode(garment),
                                         initialClothState(garment));
  exploreGraph(graph, *garment.primary, runner, metric, ExpandOptions{}, {300, 0.0, 0.0f});
  return {{{"garment", garment.config}}, *garment.primary, *garment.mesh, std::move(graph)};
}
}  // namespace

TEST_CASE("merge blend: a frame that crosses a merge edge moves the cape like an ordinary one") {
  const ExploreFile file = exploredCape();
  BlendMotionOptions options;
  options.characters = 64;
  options.steps = 600;
  const BlendMotionReport r = measureBlendMotion(file, options);
  MESSAGE("p95 largest vertex move: ", 1000.0f * r.p95Merge, " mm at ", r.mergeSteps.size(),
          " merge frames, ", 1000.0f * r.p95Ordinary, " mm at ", r.ordinarySteps.size(),
          " other frames (ratio ", r.ratio(), ")");
  REQUIRE(r.mergeSteps.size() > 1000);
  REQUIRE(r.ordinarySteps.size() > 10000);
  CHECK(r.p95Ordinary > 0.01f);  // the cape does move
  CHECK(r.ratio() <= 1.2f);
}

TEST_CASE("merge blend: quantile is the nearest rank") {
  CHECK(quantile({}, 0.95f) == 0.0f);
  CHECK(quantile({3.0f}, 0.95f) == 3.0f);
  std::vector<float> values;
  for (int i = 100; i >= 1; --i) values.push_back(float(i));
  CHECK(quantile(values, 0.95f) == 95.0f);
  CHECK(quantile(values, 1.0f) == 100.0f);
  CHECK(quantile(values, 0.0f) == 1.0f);
}
