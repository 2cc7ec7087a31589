// `throng cloth compress` end to end on a small explored cape, and its error paths.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "core/file_io.h"
#include "secondary/offline/cloth_compress.h"
#include "json_keys.h"

using namespace throng;

namespace {
// A small cape (8 × 12 vertices) explored for a few expansions: about 0.5 s.
std::filesystem::path exploredCape(const std::filesystem::path& dir) {
  std::filesystem::path tsg = dir / "cape.tsg";
  test::CommandResult r = test::runThrong(
      "cloth explore --garment-config '{\"cape\": {\"columns\": 8, \"rows\": 12}}' "
      "--budget-expansions 3 --quiet --out " +
      tsg.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  return tsg;
}
// The --json report; a missed --target-error puts a warning line before it (stderr).
nlohmann::json reportOf(const std::string& output) {
  return nlohmann::json::parse(output.substr(output.find('{')));
}
using throng::test::firstNonSnakeKey;
// The number printed after `"key": ` in pretty-printed JSON text.
std::string numberTextOf(const std::string& text, const std::string& key) {
  const std::string field = "\"" + key + "\": ";
  const size_t at = text.find(field);
  if (at == std::string::npos) return {};
  const size_t begin = at + field.size();
  return text.substr(begin, text.find_first_of(",\n}", begin) - begin);
}
}  // namespace

TEST_CASE("cloth compress: .tsg → .tsc, the report, and cloth info on the result") {
  std::filesystem::path dir = test::freshDirectory("cloth_compress");
  std::filesystem::path tsg = exploredCape(dir), tsc = dir / "cape.tsc";
  test::CommandResult r = test::runThrong("cloth compress " + tsg.string() + " --out " +
                                          tsc.string() + " --json --quiet");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  nlohmann::json report = reportOf(r.output);
  secondary::ClothDatabase db = secondary::readClothDatabase(tsc);
  CHECK(report["states"] == db.stateCount());
  CHECK(report["vertices"] == 96);
  CHECK(report["compressed_bytes"] == std::filesystem::file_size(tsc));
  CHECK(report["raw_bytes"] == uint64_t(db.stateCount()) * 96 * 12);
  CHECK(report["max_reconstruction_error_m"].get<double>() >= 0.0);
  CHECK(db.primary.run.bucketWidth == doctest::Approx(0.05f));  // the cape's run graph
  CHECK(db.triangles.size() > 0);

  test::CommandResult info = test::runThrong("cloth info " + tsc.string() + " --json");
  INFO(info.output);
  REQUIRE(info.exitCode == 0);
  nlohmann::json j = nlohmann::json::parse(info.output);
  CHECK(j["schema"] == "throng.cloth_info");
  CHECK(j["version"] == 1);
  CHECK(firstNonSnakeKey(j) == "");
  CHECK(j["format"] == "tsc");
  // Metres stored as floats read as typed: 0.0003, not 0.000300000014249235.
  CHECK(numberTextOf(info.output, "coefficient_quantum_m") == "0.0003");
  CHECK(numberTextOf(r.output, "coefficient_quantum_m") == "0.0003");
  CHECK(j["bases"] == report["bases"]);
  // Capes played along the decoded database: how far a merge frame moves them.
  test::CommandResult blend =
      test::runThrong("cloth info " + tsc.string() + " --json --blend-motion");
  INFO(blend.output);
  REQUIRE(blend.exitCode == 0);
  const nlohmann::json b = nlohmann::json::parse(blend.output);
  CHECK(b["blend_ordinary_steps"].get<int>() > 1000);
  CHECK(b["blend_p95_move_ordinary_m"].get<double>() > 0.0);
  CHECK(b["blend_merge_over_ordinary"].get<double>() >= 0.0);
  CHECK(j["max_reconstruction_error_m"] == report["max_reconstruction_error_m"]);

  // A fixed basis count and a coarser quantum.
  r = test::runThrong("cloth compress " + tsg.string() + " --out " + (dir / "b8.tsc").string() +
                      " --bases 8 --quantum 0.001 --json --quiet");
  REQUIRE(r.exitCode == 0);
  CHECK(reportOf(r.output)["bases"] == 8);  // given: the ratio cap does not apply
  // The default size cap (100:1) against none: the cap keeps fewer bases on this small cape.
  r = test::runThrong("cloth compress " + tsg.string() + " --out " + (dir / "free.tsc").string() +
                      " --min-ratio 0 --json --quiet");
  REQUIRE(r.exitCode == 0);
  CHECK(reportOf(r.output)["bases"].get<int>() > report["bases"].get<int>());
  CHECK(report["coefficient_quantum_m"].get<double>() == doctest::Approx(0.0003));
}

TEST_CASE("cloth reports: numbers that are floats are written as the float's shortest decimal") {
  nlohmann::json j = {{"float", 0.05f},
                      {"double", 0.1},
                      {"third", 1.0 / 3.0},
                      {"count", 7},
                      {"nested", {{"list", {0.3f, 2.5f, 1e-7f}}}}};
  secondary::writeFloatsShort(j);
  CHECK(j["float"].dump() == "0.05");
  CHECK(j["nested"]["list"].dump() == "[0.3,2.5,1e-07]");
  // Doubles no float equals keep every digit; integers stay integers.
  CHECK(j["double"].get<double>() == 0.1);
  CHECK(j["third"].get<double>() == 1.0 / 3.0);
  CHECK(j["count"].is_number_integer());
}

TEST_CASE("cloth compress: a missed --target-error warns, and with --strict fails unwritten") {
  std::filesystem::path dir = test::freshDirectory("cloth_compress_target");
  std::filesystem::path tsg = exploredCape(dir);
  // 10 µm is far below the 0.3 mm quantum: missed. Without --quiet, one plain line per stage.
  const std::filesystem::path missed = dir / "missed.tsc";
  test::CommandResult r = test::runThrong("cloth compress " + tsg.string() + " --out " +
                                          missed.string() + " --target-error 0.00001 --json");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(std::filesystem::exists(missed));
  const nlohmann::json report = reportOf(r.output);
  CHECK(report["schema"] == "throng.cloth_compress");
  CHECK(report["version"] == 1);
  CHECK(report["target_met"] == false);
  const double error = report["max_reconstruction_error_m"].get<double>();
  CHECK(error > 0.00001);
  char figures[96];
  std::snprintf(figures, sizeof figures,
                "warning: max reconstruction error %.2f mm misses --target-error 0.01 mm",
                1000.0 * error);
  CHECK(r.output.find(figures) != std::string::npos);
  CHECK(r.output.find("compress: svd (1/7 done)") != std::string::npos);
  CHECK(r.output.find("compress: error (6/7 done)") != std::string::npos);

  // --strict: exit 1 and no file, not even a temporary one.
  const std::filesystem::path strict = dir / "strict.tsc";
  r = test::runThrong("cloth compress " + tsg.string() + " --out " + strict.string() +
                      " --target-error 0.00001 --strict --quiet");
  CHECK(r.exitCode == 1);
  CHECK(r.output.find("error: --strict: max reconstruction error") != std::string::npos);
  CHECK(r.output.find(strict.string() + " not written") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(strict));
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  CHECK(files == 2);  // the graph and missed.tsc

  // A target the result meets: --strict writes the file and nothing warns.
  r = test::runThrong("cloth compress " + tsg.string() + " --out " + strict.string() +
                      " --target-error 0.5 --strict --quiet --json");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(reportOf(r.output)["target_met"] == true);
  CHECK(r.output.find("warning") == std::string::npos);
  CHECK(std::filesystem::exists(strict));
}

TEST_CASE("cloth compress: bad input and options fail clearly and write nothing") {
  std::filesystem::path dir = test::freshDirectory("cloth_compress_errors");
  std::filesystem::path tsg = exploredCape(dir);
  struct Case {
    std::string arguments, expected;
  };
  const Case cases[] = {
      {"cloth compress " + (dir / "missing.tsg").string() + " --out " + (dir / "a.tsc").string(),
       "missing.tsg"},
      {"cloth compress " + tsg.string() + " --out " + (dir / "a.tsc").string() + " --quantum 0",
       "--quantum"},
      {"cloth compress " + tsg.string() + " --out " + (dir / "a.tsc").string() +
           " --bucket-width 2",
       "--bucket-width"},
      {"cloth compress " + tsg.string() + " --out /proc/no/a.tsc", "/proc/no"},
      {"cloth compress " + tsg.string(), "--out"},
      // An existing folder as the output: refused before the compression, not after it.
      {"cloth compress " + tsg.string() + " --out " + dir.string(),
       "--out " + dir.string() + ": is a directory, expected a file to write"},
  };
  for (const Case& c : cases) {
    test::CommandResult r = test::runThrong(c.arguments);
    INFO(c.arguments, "\n", r.output);
    CHECK(r.exitCode != 0);
    CHECK(r.output.find(c.expected) != std::string::npos);
  }
  // Not an explored graph: a text file, and a truncated .tsg.
  writeTextFileAtomic(dir / "text.tsg", "not a graph at all");
  test::CommandResult r = test::runThrong("cloth compress " + (dir / "text.tsg").string() +
                                          " --out " + (dir / "a.tsc").string());
  CHECK(r.exitCode != 0);
  CHECK(r.output.find("text.tsg") != std::string::npos);
  std::filesystem::copy_file(tsg, dir / "cut.tsg");
  std::filesystem::resize_file(dir / "cut.tsg", std::filesystem::file_size(tsg) / 2);
  r = test::runThrong("cloth compress " + (dir / "cut.tsg").string() + " --out " +
                      (dir / "a.tsc").string());
  CHECK(r.exitCode != 0);
  CHECK(r.output.find("truncated") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "a.tsc"));
}
