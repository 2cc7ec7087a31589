// `throng render --storyboard FILE --trajectories FILE`: the storyboard scene end to end, and
// its option errors.
#include <doctest/doctest.h>

#include <filesystem>

#include "cli_support.h"
#include "core/image.h"
#include "test_support.h"

namespace fs = std::filesystem;
using throng::test::runThrong;

namespace {
const std::string kTrajectories = "trajectories/sgan_format/students003.txt";

std::string board() {
  return (throng::test::sourceDir() / "assets/storyboards/plaza_small.png").string();
}
std::string tracks() {
  return (throng::test::sharedDataDir() / kTrajectories).string();
}
}  // namespace

TEST_CASE("render: the storyboard scene renders every glyph's agent with its clip set and group") {
  if (!throng::test::haveSharedData(kTrajectories)) return;
  const fs::path out = throng::test::freshDirectory("storyboard_render");
  throng::test::CommandResult r =
      runThrong("render --storyboard " + board() + " --trajectories " + tracks() +
                " --frames 3 --size 160x90 --validation --out " + out.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  // 81 glyphs in four actions: the four built-in clip pairs, one range each.
  CHECK(r.output.find("81 agents (walk 34, run 14, talk 4, jump 29") != std::string::npos);
  CHECK(r.output.find("rendered 3 frames of 81 characters") != std::string::npos);
  CHECK(r.output.find("avoidance anticipatory") != std::string::npos);
  for (const char* name : {"frame_0000.png", "frame_0002.png"}) {
    throng::ImageRgba8 image = throng::readPng(out / name);
    CHECK(image.width == 160);
  }
  // The published rule, one user pair for every action, the motion cache and the LOD on.
  r = runThrong("render --storyboard " + board() + " --trajectories " + tracks() +
                " --policy published --slow " +
                (throng::test::sourceDir() / "assets/walk_slow.bvh").string() + " --fast " +
                (throng::test::sourceDir() / "assets/walk_fast.bvh").string() +
                " --cache --lod --frames 2 --size 160x90 --validation --overwrite --out " + out.string());
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(r.output.find("avoidance published") != std::string::npos);
}

TEST_CASE("render: storyboard options that cannot work are refused before anything is written") {
  const fs::path out = throng::test::freshDirectory("storyboard_render_bad");
  struct Case {
    std::string args, expected;
  };
  const Case cases[] = {
      {"--storyboard " + board(), "needs --storyboard FILE.png and --trajectories FILE"},
      {"--scene storyboard --trajectories x.txt",
       "needs --storyboard FILE.png and --trajectories FILE"},
      {"--scene circle --storyboard " + board() + " --trajectories x.txt",
       "make the storyboard scene, not 'circle'"},
      {"--storyboard missing.png --trajectories " + board(),
       "--storyboard missing.png: no such file"},
      {"--storyboard " + board() + " --trajectories missing.txt",
       "--trajectories missing.txt: no such file"},
      {"--storyboard " + board() + " --trajectories " + board() + " --policy boids",
       "unknown policy 'boids'"},
      {"--storyboard " + board() + " --trajectories " + board() + " --cell 0",
       "--cell: expected metres > 0"},
      {"--storyboard " + board() + " --trajectories " + board() + " --speed-period 5",
       "--speed-period"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.args);
    throng::test::CommandResult r =
        runThrong("render " + c.args + " --frames 1 --out " + out.string());
    CHECK(r.exitCode != 0);
    CHECK(r.output.find(c.expected) != std::string::npos);
  }
  CHECK(fs::is_empty(out));
}
