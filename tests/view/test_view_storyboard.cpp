// `throng view --storyboard FILE --trajectories FILE` under the suite's private Xvfb: the
// storyboard scene with its four clip pairs, live, with the coverage LOD counting every agent.
#include <doctest/doctest.h>

#include "test_support.h"
#include "view_run.h"

using namespace throng;

TEST_CASE(
    "view: the storyboard scene runs with steering, four clip pairs and the LOD over every agent") {
  const std::string tracks = "trajectories/sgan_format/students003.txt";
  if (!test::haveSharedData(tracks)) return;
  test::ViewRun run = test::runView(
      "--storyboard " + (test::sourceDir() / "assets/storyboards/plaza_small.png").string() +
      " --trajectories " + (test::sharedDataDir() / tracks).string() +
      " --lod --frames 8 --size 320x180 --no-panel --validation");
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["characters"] == 81);
  CHECK(run.stats["validationMessages"] == 0);
  const nlohmann::json& levels = run.stats["lod"]["levels"];
  CHECK(levels[0].get<long>() + levels[1].get<long>() + levels[2].get<long>() == 81);
  CHECK(run.stats["simulatedSeconds"].get<double>() > 0.2);
}
