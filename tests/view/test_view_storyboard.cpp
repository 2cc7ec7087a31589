// `throng view --storyboard FILE --trajectories FILE` under the suite's private Xvfb: the
// storyboard scene with its four clip pairs, live, with the coverage LOD counting every agent.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

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
  CHECK(run.stats["validation_messages"] == 0);
  const nlohmann::json& levels = run.stats["lod"]["levels"];
  CHECK(levels[0].get<long>() + levels[1].get<long>() + levels[2].get<long>() == 81);
  CHECK(run.stats["simulated_seconds"].get<double>() > 0.2);
}

TEST_CASE("view: a respawn keeps the storyboard scene until another scenario is picked") {
  const std::string tracks = "trajectories/sgan_format/students003.txt";
  if (!test::haveSharedData(tracks)) return;
  std::filesystem::path out = test::freshDirectory("view_storyboard_respawn");
  // Without a scenario the respawn rebuilds the storyboard (81 agents, whatever the count);
  // "circle" leaves it, "storyboard" comes back to it.
  std::ofstream(out / "script.txt") << "wait 2\nrespawn 10\nwait 2\nrespawn 50 circle\nwait 2\n"
                                       "respawn 10 storyboard\nwait 2\n";
  test::ViewRun run = test::runView(
      "--storyboard " + (test::sourceDir() / "assets/storyboards/plaza_small.png").string() +
      " --trajectories " + (test::sharedDataDir() / tracks).string() +
      " --frames 10 --size 320x180 --validation --input-script " + (out / "script.txt").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["respawns"] == 3);
  CHECK(run.stats["characters"] == 81);
  CHECK(run.stats["validation_messages"] == 0);

  // A viewer started without --storyboard has no storyboard to go back to.
  std::ofstream(out / "bad.txt") << "respawn 10 storyboard\n";
  test::ViewRun bad = test::runView("--frames 3 --size 320x180 -n 100 --input-script " + (out / "bad.txt").string());
  CHECK(bad.result.exitCode != 0);
  CHECK(bad.result.output.find("without --storyboard") != std::string::npos);
}
