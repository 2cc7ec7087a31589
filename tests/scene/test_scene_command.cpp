// `throng render SCENE.json`: a scene given by flags and saved with --save-scene renders the same
// frames from its file; a file of several groups renders them; flags that describe the scene
// are refused next to a file; a bad file writes nothing.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "cli_support.h"
#include "core/image.h"

using namespace throng;

namespace {

bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(fa), {}) ==
         std::string(std::istreambuf_iterator<char>(fb), {});
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

}  // namespace

TEST_CASE("render SCENE.json: a flag scene saved as a file renders the same frames") {
  const std::filesystem::path dir = test::freshDirectory("scene_round_trip");
  const std::string scene = (dir / "circle.json").string();
  const test::CommandResult flags = test::runThrong(
      "render --scene circle -n 120 --policy published --camera top --size 160x90 --frames 3 "
      "--out " +
      (dir / "a").string() + " --save-scene " + scene);
  REQUIRE_MESSAGE(flags.exitCode == 0, flags.output);
  const test::CommandResult file =
      test::runThrong("render " + scene + " --out " + (dir / "b").string());
  REQUIRE_MESSAGE(file.exitCode == 0, file.output);
  CHECK(file.output.find("rendered 3 frames of 120 characters") != std::string::npos);
  for (const char* frame : {"frame_0000.png", "frame_0002.png"}) {
    CAPTURE(frame);
    CHECK(sameFile(dir / "a" / frame, dir / "b" / frame));
  }
}

TEST_CASE("render SCENE.json: several groups, a camera path, and refusals") {
  const std::filesystem::path dir = test::freshDirectory("scene_groups");
  const std::string scene = (dir / "groups.json").string();
  writeText(scene, R"({
  "schema": "throng.scene", "version": 1,
  "groups": [
    {"count": 60, "clips": "walk", "centre": [-8, 0]},
    {"count": 60, "clips": "run", "centre": [8, 0]},
    {"count": 30, "clips": "hop", "centre": [0, 10]}
  ],
  "camera": {"path": [{"time": 0, "eye": [0, 40, -30], "target": [0, 0, 0]},
                      {"time": 0.1, "eye": [30, 40, 0], "target": [0, 0, 0]}]},
  "output": {"size": "160x90", "fps": 30, "seconds": 0.1}
})");
  const test::CommandResult r =
      test::runThrong("render " + scene + " --validation --out " + (dir / "out").string());
  REQUIRE_MESSAGE(r.exitCode == 0, r.output);
  CHECK(r.output.find("rendered 3 frames of 150 characters") != std::string::npos);
  // The camera moved along its path: first and last frames differ.
  const ImageRgba8 first = readPng(dir / "out" / "frame_0000.png");
  const ImageRgba8 last = readPng(dir / "out" / "frame_0002.png");
  CHECK(compareImages(first, last, 8).fractionDifferent > 0.05);

  const test::CommandResult both =
      test::runThrong("render " + scene + " -n 10 --out " + (dir / "refused").string());
  CHECK(both.exitCode != 0);
  CHECK(both.output.find("--characters: the scene file") != std::string::npos);

  const std::string bad = (dir / "bad.json").string();
  writeText(bad, "{\"schema\": \"throng.scene\", \"version\": 1,\n \"groups\": [{\"count\": -3}]}");
  const test::CommandResult b =
      test::runThrong("render " + bad + " --out " + (dir / "bad").string());
  CHECK(b.exitCode == 1);
  CHECK(b.output.find("bad.json:2: groups[0].count: expected 1..4000000") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "bad" / "frame_0000.png"));
}
