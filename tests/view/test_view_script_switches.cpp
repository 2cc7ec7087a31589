// The input script's `lod on|off` and `cache on|off` in `throng view` under a private Xvfb: they
// act as the panel's checkboxes. Switching the coverage LOD respawns the crowd at once; the
// motion cache follows at the next respawn. Every run has the validation layer on.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "test_support.h"
#include "view_run.h"

using namespace throng;
namespace fs = std::filesystem;

namespace {

constexpr const char* kScene = "-n 200 --size 640x360 --seed 7 --frames 12 --validation";

test::ViewRun runScript(const std::string& options, const std::string& name,
                        const std::string& script) {
  fs::path out = test::freshDirectory("view_script_switches");
  test::writeText(out / name, script);
  test::ViewRun run = test::runView(std::string(kScene) + " " + options + " --input-script " +
                                    (out / name).string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["validation_messages"] == 0);
  CHECK(run.stats["frames"] == 12);
  return run;
}

}  // namespace

TEST_CASE("view script: lod on respawns with the LOD, cache on waits for a respawn") {
  // `cache on` alone changes nothing; `lod on` rebuilds the crowd with the LOD but keeps the
  // cache as the crowd had it, as the panel does.
  test::ViewRun pending =
      runScript("--no-lod --no-cache", "pending.txt", "cache on\nwait 1\nlod on\nwait 2\n");
  CHECK(pending.stats["lod"]["enabled"] == true);
  CHECK(pending.stats["cache"] == "off");
  CHECK(pending.stats["respawns"] == 1);
  CHECK(pending.stats["characters"] == 200);

  test::ViewRun both =
      runScript("--no-lod --no-cache", "on.txt", "cache on\nlod on\nwait 2\nrespawn 300\nwait 2\n");
  CHECK(both.stats["lod"]["enabled"] == true);
  CHECK(both.stats["lod"]["levels"].size() == 3);
  CHECK(both.stats["cache"].is_object());
  CHECK(both.stats["respawns"] == 2);
  CHECK(both.stats["characters"] == 300);
}

TEST_CASE("view script: lod off and cache off, and a switch to the current state does nothing") {
  test::ViewRun same = runScript("--lod --cache", "same.txt", "lod on\ncache on\nwait 2\n");
  CHECK(same.stats["lod"]["enabled"] == true);
  CHECK(same.stats["cache"].is_object());
  CHECK(same.stats["respawns"] == 0);

  test::ViewRun off =
      runScript("--lod --cache", "off.txt", "lod off\nwait 1\ncache off\nrespawn 150\nwait 2\n");
  CHECK(off.stats["lod"]["enabled"] == false);
  CHECK(off.stats["cache"] == "off");
  CHECK(off.stats["respawns"] == 2);
  CHECK(off.stats["characters"] == 150);
}
