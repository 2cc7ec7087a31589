// The coverage LOD live in `throng view` under a private Xvfb: the masks read back at the end of
// each frame follow the camera (statistics and --print-stats), the thresholds reach the running
// crowd, a respawn keeps the readback right, and the tinted window equals `throng render
// --lod --lod-tint`. Every run has the validation layer on.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "core/image.h"
#include "test_support.h"
#include "view_run.h"

using namespace throng;
namespace fs = std::filesystem;

namespace {

// The built-in skeleton's synthesized joints: off screen the base (Hips, Spine, Spine1, Spine2),
// on screen far all but the fingers and toes, mid all but the fingers.
constexpr int kBaseJoints = 4;
constexpr int kFarJoints = 21;
constexpr int kMidJoints = 23;

struct Levels {
  long far = 0, mid = 0, near = 0;
};

// Checks what every LOD report must satisfy and returns its levels.
Levels checkLodReport(const nlohmann::json& stats, long characters) {
  REQUIRE(stats.is_object());
  CHECK(stats["validation_messages"] == 0);
  const nlohmann::json& lod = stats["lod"];
  REQUIRE(lod.is_object());
  CHECK(lod["enabled"] == true);
  CHECK(stats["active_joints"] == lod["active_joints"]);
  const long joints = stats["joints_per_character"].get<long>();
  const long active = lod["active_joints"].get<long>();
  Levels l{lod["levels"][0].get<long>(), lod["levels"][1].get<long>(),
           lod["levels"][2].get<long>()};
  CHECK(l.far + l.mid + l.near == characters);
  // Between every character off screen (base joints) and every one on screen at its level.
  CHECK(active >= kBaseJoints * characters);
  CHECK(active <= kFarJoints * l.far + kMidJoints * l.mid + joints * l.near);
  return l;
}

}  // namespace

TEST_CASE("view --lod: moving the camera close changes the active joints and the levels") {
  const std::string scene = "--lod -n 2000 --frames 20 --validation";
  fs::path out = test::freshDirectory("view_lod_zoom");
  test::writeText(out / "close.txt",
                  "# the closeup preset, then a little closer\nkey 4\nscroll 1\n");
  test::ViewRun wide = test::runView(scene);
  INFO(wide.result.output);
  REQUIRE(wide.result.exitCode == 0);
  test::ViewRun close = test::runView(scene + " --input-script " + (out / "close.txt").string());
  INFO(close.result.output);
  REQUIRE(close.result.exitCode == 0);

  Levels w = checkLodReport(wide.stats, 2000), c = checkLodReport(close.stats, 2000);
  const long activeWide = wide.stats["active_joints"].get<long>();
  const long activeClose = close.stats["active_joints"].get<long>();
  MESSAGE("wide: ", activeWide, " active joints, far/mid/near ", w.far, "/", w.mid, "/", w.near);
  MESSAGE("close: ", activeClose, " active joints, far/mid/near ", c.far, "/", c.mid, "/", c.near);
  // Close up, the characters near the camera get every joint; most of the crowd leaves the
  // view and synthesizes only the base joints.
  CHECK(c.near > w.near);
  CHECK(activeClose < activeWide);
  CHECK(wide.stats["lod"]["mid_pixels"] == 56.0);
  CHECK(wide.stats["lod"]["near_pixels"] == 140.0);
  CHECK(wide.stats["lod"]["tint"] == false);
}

TEST_CASE("view --lod: the thresholds reach the crowd, also after a respawn") {
  const std::string scene = "-n 200 --size 640x360 --seed 7 --frames 8 --validation --lod";
  test::ViewRun none = test::runView(scene + " --lod-mid-pixels 1e9 --lod-near-pixels 1e9");
  INFO(none.result.output);
  REQUIRE(none.result.exitCode == 0);
  checkLodReport(none.stats, 200);
  CHECK(none.stats["lod"]["levels"] == nlohmann::json::array({200, 0, 0}));
  CHECK(none.stats["active_joints"] <= 200 * kFarJoints);
  CHECK(none.stats["active_joints"] > 200 * kBaseJoints);

  fs::path out = test::freshDirectory("view_lod_respawn");
  test::writeText(out / "respawn.txt", "wait 3\nrespawn 300 circle\nwait 2\n");
  test::ViewRun all =
      test::runView(scene + " --lod-mid-pixels 0 --lod-near-pixels 0 --input-script " +
                    (out / "respawn.txt").string());
  INFO(all.result.output);
  REQUIRE(all.result.exitCode == 0);
  checkLodReport(all.stats, 300);
  CHECK(all.stats["respawns"] == 1);
  CHECK(all.stats["lod"]["levels"] == nlohmann::json::array({0, 0, 300}));
  CHECK(all.stats["active_joints"] == 300 * all.stats["joints_per_character"].get<int>());
  CHECK(all.stats["lod"]["mid_pixels"] == 0.0);
}

TEST_CASE("view --lod --lod-tint: the window shows the frame `throng render` tints") {
  const std::string scene =
      "--lod --lod-tint -n 500 --size 800x450 --seed 7 --camera street --frames 20";
  fs::path out = test::freshDirectory("view_lod_tint");
  test::ViewRun run =
      test::runView(scene + " --no-panel --validation --screenshot " + (out / "view.png").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  Levels l = checkLodReport(run.stats, 500);
  CHECK(run.stats["lod"]["tint"] == true);
  CHECK(l.far > 0);  // all three tints are in the picture
  CHECK(l.mid > 0);
  CHECK(l.near > 0);

  test::CommandResult render =
      test::runThrong("render " + scene + " --out " + (out / "render").string());
  INFO(render.output);
  REQUIRE(render.exitCode == 0);
  ImageRgba8 actual = readPng(out / "view.png");
  ImageRgba8 expected = readPng(out / "render" / "frame_0019.png");
  REQUIRE(actual.width == expected.width);
  REQUIRE(actual.height == expected.height);
  ImageDiff diff = compareImages(actual, expected, 24);
  MESSAGE("tinted view vs render: mean ", diff.meanAbsError, ", pixels over threshold ",
          diff.fractionDifferent * 100.0, "%");
  if (diff.meanAbsError >= 1.0) writePngAtomic(out / "diff.png", diff.diffImage);
  CHECK(diff.meanAbsError < 1.0);
  CHECK(diff.fractionDifferent < 0.005);
}
