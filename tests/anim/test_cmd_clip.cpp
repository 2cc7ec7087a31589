// `throng clip info`: the built binary ($THRONG_BIN, set by ctest) run on real captures and
// on a malformed file.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace fs = std::filesystem;

namespace {

const fs::path kBadDir = fs::path(THRONG_ANIM_TEST_DATA) / "bad";

struct Captured {
  int status = -1;
  std::string output;
};

Captured runCommand(const std::string& command) {
  Captured result;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  int raw = pclose(pipe);
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return result;
}

fs::path throngBinary() {
  const char* env = std::getenv("THRONG_BIN");
  return env ? fs::path(env) : throng::test::binaryDir() / "bin" / "throng";
}

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  out += '\'';
  return out;
}

}  // namespace

TEST_CASE("throng clip info --json reports a CMU capture") {
  const char* rel = "bvh/cmu/cmu_09_01_run.bvh";
  if (!throng::test::haveSharedData(rel)) return;
  fs::path bin = throngBinary();
  REQUIRE_MESSAGE(fs::exists(bin), "build the throng target (or set THRONG_BIN): ", bin.string());
  fs::path file = throng::test::sharedDataDir() / rel;
  Captured run = runCommand(shellQuote(bin.string()) + " clip info " + shellQuote(file.string()) +
                            " --json --loop 2>&1");
  CAPTURE(run.output);
  REQUIRE(run.status == 0);
  nlohmann::json info = nlohmann::json::parse(run.output);
  CHECK(info["schema"] == "throng.clip_info");
  CHECK(info["version"] == 1);
  CHECK(info["file"] == file.string());
  CHECK(info["joint_count"] == 31);
  CHECK(info["frames"] == 149);
  CHECK(info["frame_time"].get<double>() == doctest::Approx(0.0083333));
  REQUIRE(info["joints"].size() == 31);
  CHECK(info["joints"][0]["name"] == "Hips");
  CHECK(info["joints"][0]["parent"] == -1);
  CHECK(info["joints"][0]["channels"] ==
        nlohmann::json({"Xposition", "Yposition", "Zposition", "Zrotation", "Yrotation", "Xrotation"}));
  CHECK(info["joints"][2]["name"] == "LeftUpLeg");
  CHECK(info["joints"][2]["parent"] == 1);
  CHECK(info["joints"][2]["channels"] == nlohmann::json({"Zrotation", "Yrotation", "Xrotation"}));
  // The data's README: one unit ≈ 0.0564 m; a person stands 1.5–2.0 m.
  CHECK(!info["units"]["label"].get<std::string>().empty());
  CHECK(info["units"]["metres_per_unit"].get<double>() == doctest::Approx(0.0564).epsilon(0.15));
  CHECK(info["units"]["height_m"].get<double>() > 1.4);
  CHECK(info["units"]["height_m"].get<double>() < 2.1);
  // 149 frames at 120 fps → 37 at 30 fps; a running cycle is ~0.6–0.8 s (18–24 frames).
  const auto& loop = info["loop"];
  CHECK(loop["length"] == loop["end"].get<int>() - loop["start"].get<int>());
  CHECK(loop["start"].get<int>() >= 0);
  CHECK(loop["end"].get<int>() <= 36);
  CHECK(loop["length"].get<int>() >= 15);
  CHECK(loop["error"].get<double>() >= 0.0);
}

TEST_CASE("throng clip info on a malformed file prints the error and exits 1") {
  fs::path bin = throngBinary();
  REQUIRE(fs::exists(bin));
  fs::path file = kBadDir / "wrong_value_count.bvh";
  Captured run = runCommand(shellQuote(bin.string()) + " clip info " + shellQuote(file.string()) + " 2>&1");
  CHECK(run.status == 1);
  CHECK(run.output.rfind("error: " + file.string() + ":20: expected 9 values", 0) == 0);
}

TEST_CASE("throng clip info prints joints, channel orders, frames and units as text") {
  const char* rel = "bvh/bandai_namco/dataset-1_run_normal_001.bvh";
  if (!throng::test::haveSharedData(rel)) return;
  fs::path bin = throngBinary();
  REQUIRE(fs::exists(bin));
  fs::path file = throng::test::sharedDataDir() / rel;
  Captured run = runCommand(shellQuote(bin.string()) + " clip info " + shellQuote(file.string()) + " 2>&1");
  CAPTURE(run.output);
  REQUIRE(run.status == 0);
  CHECK(run.output.find("joints: 22\n") != std::string::npos);
  CHECK(run.output.find("frames: 24\n") != std::string::npos);
  CHECK(run.output.find("joint_Root") != std::string::npos);
  CHECK(run.output.find("Xposition Yposition Zposition Zrotation Xrotation Yrotation") !=
        std::string::npos);
  CHECK(run.output.find("units: ") != std::string::npos);
  CHECK(run.output.find("loop") == std::string::npos);  // only with --loop
}
