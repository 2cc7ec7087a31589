// `throng bench` end to end: the quick run writes well-formed JSON with every variant, and the
// experiments write their CSV files; bad options fail clearly.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "core/file_io.h"

using namespace throng;

TEST_CASE("bench --quick: JSON rows for every variant, medians present") {
  auto dir = test::freshDirectory("bench_quick");
  test::CommandResult run = test::runThrong("bench --quick --json " + (dir / "bench.json").string() +
                                            " --experiments " + (dir / "experiments").string());
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  auto doc = nlohmann::json::parse(readTextFile(dir / "bench.json"));
  std::set<std::string> variants;
  for (const auto& row : doc["results"]) {
    variants.insert(row["variant"].get<std::string>());
    CHECK(row["synthesisMsMedian"].get<double>() > 0.0);
    CHECK(row["characters"].get<int>() == 1000);
  }
  for (const char* v : {"gpu-synthesis", "gpu-synthesis-lod", "gpu-synthesis-lod+cache", "cpu-1-thread"})
    CHECK(variants.count(v) == 1);
  CHECK(doc["jointsPerCharacter"].get<int>() == 25);
  CHECK(std::filesystem::exists(dir / "experiments" / "cache_vs_n.csv"));
  CHECK(readTextFile(dir / "experiments" / "time_vs_n.csv").rfind("characters,cpu_ms,gpu_full_ms,gpu_lod_ms", 0) == 0);
  std::string csv = readTextFile(dir / "experiments" / "hit_rate_vs_bucket.csv");
  CHECK(csv.rfind("bucket_width,hit_rate", 0) == 0);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 7);  // header + 6 widths
}

TEST_CASE("bench: bad options fail clearly") {
  test::CommandResult run = test::runThrong("bench --characters 0");
  CHECK(run.exitCode != 0);
  CHECK(run.output.find("--characters: each count must be 1..4000000") != std::string::npos);
}
