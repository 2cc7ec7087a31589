// `throng bench` end to end: the quick run writes well-formed JSON with every variant, and the
// experiments write their CSV files; with --cloth the caped-crowd row and its cloth passes, without
// it a line saying why the row is missing; bad options fail clearly.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "core/file_io.h"
#include "json_keys.h"

using namespace throng;

namespace {
using throng::test::firstNonSnakeKey;

// The render-loop row's frames go to folders named so in the temporary directory.
size_t renderLoopFolders() {
  size_t count = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
    if (entry.path().filename().string().rfind("throng-bench-render-", 0) == 0) ++count;
  return count;
}
}  // namespace

TEST_CASE("bench --quick: JSON rows for every variant, medians present") {
  auto dir = test::freshDirectory("bench_quick");
  const size_t foldersBefore = renderLoopFolders();
  test::CommandResult run =
      test::runThrong("bench --quick --json " + (dir / "bench.json").string() + " --experiments " +
                      (dir / "experiments").string());
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  auto doc = nlohmann::json::parse(readTextFile(dir / "bench.json"));
  CHECK(doc["schema"] == "throng.bench");
  CHECK(doc["version"] == 1);
  CHECK(firstNonSnakeKey(doc) == "");
  CHECK(doc["cpu_threads"].get<int>() >= 1);
  CHECK(doc["frames_measured"] == 5);
  std::set<std::string> variants;
  for (const auto& row : doc["results"]) {
    variants.insert(row["variant"].get<std::string>());
    CHECK(row["synthesis_ms_median"].get<double>() > 0.0);
    CHECK(row["characters"].get<int>() == 1000);
  }
  for (const char* v : {"gpu-synthesis", "gpu-synthesis-lod", "gpu-synthesis-lod+cache",
                        "cpu-1-thread", "throng-render-default-pngs"})
    CHECK(variants.count(v) == 1);
  // The default `throng render` as a row: its GPU frame, wall time and encoding per frame, and
  // its frames removed afterwards.
  for (const auto& row : doc["results"]) {
    if (row["variant"] != "throng-render-default-pngs") continue;
    CHECK(row["frames"] == 5);
    CHECK(row["render_ms_median"].get<double>() > 0.0);
    CHECK(row["wall_ms_per_frame"].get<double>() > 0.0);
    CHECK(row["wall_median_ms_per_frame"].get<double>() > 0.0);
    CHECK(row["encode_ms_per_frame"].get<double>() > 0.0);
    CHECK(row["prepare_ms"].get<double>() > 0.0);  // the one-time costs, before the first frame
  }
  CHECK(run.output.find("wall per frame") != std::string::npos);
  // The full path against the twin, a frame of each in turn: one entry per crowd size.
  REQUIRE(doc["twin_pairs"].size() == 1);
  const auto& pair = doc["twin_pairs"][0];
  CHECK(pair["characters"] == 1000);
  CHECK(pair["pairs"] == 5);
  CHECK(pair["cpu_threads"] == doc["cpu_threads"]);
  CHECK(pair["gpu_ms_median"].get<double>() > 0.0);
  CHECK(pair["twin_ms_median"].get<double>() > 0.0);
  CHECK(pair["ratio_min"].get<double>() <= pair["ratio_median"].get<double>());
  CHECK(pair["ratio_median"].get<double>() <= pair["ratio_max"].get<double>());
  CHECK(pair["ratio_min"].get<double>() > 0.0);
  CHECK(run.output.find("a frame of each in turn") != std::string::npos);
  CHECK(renderLoopFolders() == foldersBefore);
  CHECK(doc["joints_per_character"].get<int>() == 25);
  CHECK(run.output.find("cloth row skipped: no --cloth") != std::string::npos);
  CHECK(doc["cloth"]["skipped"].get<std::string>().find("--cloth") != std::string::npos);
  CHECK(std::filesystem::exists(dir / "experiments" / "cache_vs_n.csv"));
  CHECK(readTextFile(dir / "experiments" / "time_vs_n.csv")
            .rfind("characters,cpu_ms,gpu_full_ms,gpu_lod_ms", 0) == 0);
  std::string csv = readTextFile(dir / "experiments" / "hit_rate_vs_bucket.csv");
  CHECK(csv.rfind("bucket_width,hit_rate", 0) == 0);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 7);  // header + 6 widths
}

TEST_CASE("bench --quick --cloth: a caped frame with its cloth passes and target") {
  auto dir = test::freshDirectory("bench_cloth");
  test::CommandResult r = test::runThrong(
      "cloth explore --garment-config '{\"cape\": {\"columns\": 8, \"rows\": 12}}' "
      "--budget-expansions 2 --quiet --out " +
      (dir / "cape.tsg").string());
  REQUIRE(r.exitCode == 0);
  r = test::runThrong("cloth compress " + (dir / "cape.tsg").string() + " --out " +
                      (dir / "cape.tsc").string() + " --quiet");
  REQUIRE(r.exitCode == 0);
  test::CommandResult run = test::runThrong("bench --quick --cloth " + (dir / "cape.tsc").string() +
                                            " --json " + (dir / "bench.json").string());
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  CHECK(run.output.find("gpu-lod+cache+cloth-320x180") != std::string::npos);
  CHECK(run.output.find("far-cape splat") != std::string::npos);
  auto doc = nlohmann::json::parse(readTextFile(dir / "bench.json"));
  const auto& cloth = doc["cloth"];
  REQUIRE(cloth.is_object());
  CHECK(firstNonSnakeKey(doc) == "");
  CHECK(cloth["variant"] == "gpu-lod+cache+cloth-320x180");
  CHECK(cloth["characters"] == 1000);
  CHECK(cloth["target_ms"] == 50.0);
  CHECK(cloth["target_met"] == (cloth["frame_ms_median"].get<double>() < 50.0));
  // The frame holds the synthesis and the render, and the render holds the cloth passes.
  CHECK(cloth["frame_ms_median"].get<double>() > 0.0);
  CHECK(cloth["frame_ms_min"].get<double>() <= cloth["frame_ms_median"].get<double>());
  CHECK(cloth["frame_ms_median"].get<double>() <= cloth["frame_ms_max"].get<double>());
  const auto& ms = cloth["cloth_ms_median"];
  CHECK(ms["total"].get<double>() > 0.0);
  CHECK(ms["decode"].get<double>() > 0.0);
  CHECK(ms["total"].get<double>() < cloth["render_ms_median"].get<double>());
  long capes = 0;
  for (const auto& n : cloth["capes_per_level"]) capes += n.get<long>();
  CHECK(capes > 0);
  CHECK(capes <= 1000);
  CHECK(cloth["states_decoded"].get<long>() > 0);
  bool row = false;
  for (const auto& r2 : doc["results"]) row = row || r2["variant"] == "gpu-lod+cache+cloth-320x180";
  CHECK(row);

  test::CommandResult bad =
      test::runThrong("bench --quick --cloth " + (dir / "missing.tsc").string());
  CHECK(bad.exitCode != 0);
  CHECK(bad.output.find("missing.tsc") != std::string::npos);
}

TEST_CASE("bench: bad options fail clearly") {
  test::CommandResult run = test::runThrong("bench --characters 0");
  CHECK(run.exitCode != 0);
  CHECK(run.output.find("--characters: each count must be 1..4000000") != std::string::npos);
}
