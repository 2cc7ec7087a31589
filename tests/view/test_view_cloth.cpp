// `throng view --cloth` under a private Xvfb: the panel's cape statistics (what --print-stats
// reports from the same PanelInfo) are the cloth layer's counts of the newest completed frame:
// the capes drawn add up to the visible characters, the states decoded follow the camera, and the
// cloth passes' GPU times are real. Validation on.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "test_support.h"
#include "view_run.h"

using namespace throng;
namespace fs = std::filesystem;

namespace {

// A small cape database: an 8 × 12 cape explored for two expansions, then compressed.
fs::path smallCape() {
  static fs::path tsc;
  if (!tsc.empty()) return tsc;
  fs::path dir = test::freshDirectory("view_cloth_db");
  test::CommandResult r = test::runThrong(
      "cloth explore --garment-config '{\"cape\": {\"columns\": 8, \"rows\": 12}}' "
      "--budget-expansions 2 --quiet --out " + (dir / "cape.tsg").string());
  REQUIRE_MESSAGE(r.exitCode == 0, r.output);
  r = test::runThrong("cloth compress " + (dir / "cape.tsg").string() + " --out " +
                      (dir / "cape.tsc").string() + " --quiet");
  REQUIRE_MESSAGE(r.exitCode == 0, r.output);
  return tsc = dir / "cape.tsc";
}

// Checks what every cloth report must satisfy and returns it.
const nlohmann::json& checkClothReport(const nlohmann::json& stats, long characters) {
  REQUIRE(stats.is_object());
  CHECK(stats["validation_messages"] == 0);
  CHECK(test::firstNonSnakeKey(stats) == "");
  const nlohmann::json& cloth = stats["cloth"];
  REQUIRE(cloth.is_object());
  CHECK(cloth["frame"].get<long>() > 0);
  long levels = 0;
  for (const auto& l : cloth["levels"]) levels += l.get<long>();
  const nlohmann::json& capes = cloth["capes"];
  CHECK(capes["triangles"].get<long>() + capes["coarse"].get<long>() + capes["splatted"].get<long>() ==
        levels);
  CHECK(levels <= characters);
  CHECK(capes["triangles"] == cloth["levels"][0].get<long>() + cloth["levels"][1].get<long>());
  if (cloth["splat"] == true) CHECK(capes["splatted"] == cloth["levels"][3]);
  // Every visible cape shows a decoded state; characters share them.
  CHECK(cloth["used_states"].get<long>() >= (levels > 0 ? 1 : 0));
  CHECK(cloth["used_states"].get<long>() <= 2 * levels);
  const nlohmann::json& ms = cloth["last_frame_ms"];
  CHECK(ms["total"].get<double>() > 0.0);
  CHECK(ms["decode"].get<double>() > 0.0);
  CHECK(ms["total"].get<double>() >= ms["decode"].get<double>() + ms["draw"].get<double>() +
                                         ms["splat"].get<double>() - 1e-9);
  CHECK(cloth["gpu_ms"].get<double>() > 0.0);
  return cloth;
}

}  // namespace

TEST_CASE("view --cloth: the panel's cape statistics follow the camera") {
  const std::string scene = "-n 400 --size 640x360 --seed 7 --frames 12 --validation --cloth " +
                            smallCape().string();
  test::ViewRun wide = test::runView(scene);
  INFO(wide.result.output);
  REQUIRE(wide.result.exitCode == 0);
  const nlohmann::json& w = checkClothReport(wide.stats, 400);
  // The wide view holds the whole crowd, far: every cape visible, most of them coarse.
  long wideCapes = 0;
  for (const auto& l : w["levels"]) wideCapes += l.get<long>();
  CHECK(wideCapes > 300);
  CHECK(w["levels"][0].get<long>() < wideCapes / 2);

  fs::path out = test::freshDirectory("view_cloth_close");
  test::writeText(out / "close.txt", "# the closeup preset\nkey 4\nwait 3\n");
  test::ViewRun close = test::runView(scene + " --input-script " + (out / "close.txt").string());
  INFO(close.result.output);
  REQUIRE(close.result.exitCode == 0);
  const nlohmann::json& c = checkClothReport(close.stats, 400);
  MESSAGE("wide: levels ", w["levels"].dump(), ", ", w["used_states"], " states; close: levels ",
          c["levels"].dump(), ", ", c["used_states"], " states");
  // Close up, fewer capes are in view and the nearest are drawn at full detail.
  long closeCapes = 0;
  for (const auto& l : c["levels"]) closeCapes += l.get<long>();
  CHECK(closeCapes < wideCapes);
  CHECK(c["levels"][0].get<long>() > w["levels"][0].get<long>());
}
