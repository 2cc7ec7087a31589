// Runs the built `throng storyboard ...` commands ($THRONG_BIN, set by ctest).
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "storyboard_fixtures.h"
#include "test_support.h"

using namespace throng;
using namespace throng::storyboard;

namespace {
std::string throngBin() {
  const char* bin = std::getenv("THRONG_BIN");
  return bin && *bin ? bin : THRONG_BIN_DEFAULT;
}

struct Run {
  int exitCode = -1;
  std::string out, err;
};

Run run(const std::string& args, const std::filesystem::path& dir) {
  const auto errFile = dir / "stderr.txt";
  const std::string command = "'" + throngBin() + "' " + args + " 2>'" + errFile.string() + "'";
  Run result;
  std::FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe);
  std::array<char, 4096> buffer;
  size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(errFile);
  result.err.assign(std::istreambuf_iterator<char>(err), {});
  return result;
}

bool haveThrong() {
  if (std::filesystem::exists(throngBin())) return true;
  MESSAGE("SKIPPED: the throng binary ", throngBin(), " is not built");
  return false;
}
}  // namespace

TEST_CASE("cli: storyboard decode --json prints the agents and invalid glyphs") {
  if (!haveThrong()) return;
  test::TempDir dir("throng-cli-decode");
  ImageRgba8 image = test::exampleStoryboard(50, 4);
  test::drawSum(image, 2, 47, 1 + 4 + 64, test::kOrange, test::kBlue);  // may merge; still invalid
  const auto file = dir.path / "board.png";
  writePngAtomic(file, image);
  const Storyboard expected = decodeStoryboard(image, Legend{});
  REQUIRE(!expected.invalid.empty());

  const Run r = run("storyboard decode '" + file.string() + "' --json", dir.path);
  REQUIRE(r.exitCode == 0);
  const nlohmann::json json = nlohmann::json::parse(r.out);
  CHECK(r.out.rfind("{\"schema\":\"throng.storyboard\",\"version\":1,\"width\":50,\"height\":50,"
                    "\"agents\":[",
                    0) == 0);
  CHECK(json["width"] == 50);
  CHECK(json["height"] == 50);
  REQUIRE(json["agents"].size() == expected.glyphs.size());
  for (size_t i = 0; i < expected.glyphs.size(); ++i) {
    const Glyph& g = expected.glyphs[i];
    const auto& a = json["agents"][i];
    CHECK(a["x"] == g.x);
    CHECK(a["y"] == g.y);
    CHECK(a["heading"] == std::string(headingName(g.heading)));
    CHECK(a["state"] == std::string(stateName(g.state)));
    CHECK(a["action"] == std::string(actionName(g.action)));
    CHECK(a["group"] == g.group);
  }
  REQUIRE(json["invalid"].size() == expected.invalid.size());
  CHECK(json["invalid"][0]["x"] == expected.invalid[0].x);
  CHECK(json["invalid"][0]["reason"] == expected.invalid[0].reason);

  const Run strict = run("storyboard decode '" + file.string() + "' --strict --json", dir.path);
  CHECK(strict.exitCode != 0);
  CHECK(strict.err.find("board.png") != std::string::npos);
  CHECK(strict.err.find("invalid glyph") != std::string::npos);

  const Run summary = run("storyboard decode '" + file.string() + "'", dir.path);
  CHECK(summary.exitCode == 0);
  CHECK(summary.out.find("invalid at pixel") != std::string::npos);
}

TEST_CASE("cli: example, quilt and encode write storyboards that decode") {
  if (!haveThrong()) return;
  test::TempDir dir("throng-cli-quilt");
  const std::string small = (dir.path / "small.png").string(), large = (dir.path / "large.png").string();
  Run r = run("storyboard example --out '" + small + "' --seed 3 --size 60x60", dir.path);
  REQUIRE(r.exitCode == 0);
  CHECK(decodeStoryboard(readPng(small), Legend{}).glyphs.size() == 36);

  r = run("storyboard quilt '" + small + "' --size 200x150 --seed 2 --out '" + large + "'", dir.path);
  REQUIRE(r.exitCode == 0);
  CHECK(r.out.find("TV distance") != std::string::npos);
  const Storyboard quilted = decodeStoryboard(readPng(large), Legend{});
  CHECK(quilted.width == 200);
  CHECK(quilted.height == 150);
  CHECK(quilted.invalid.empty());
  CHECK(quilted.glyphs.size() > 150);

  // decode --json feeds encode: the same agents come back.
  r = run("storyboard decode '" + small + "' --json", dir.path);
  REQUIRE(r.exitCode == 0);
  const auto agents = dir.path / "agents.json";
  std::ofstream(agents) << r.out;
  const std::string again = (dir.path / "again.png").string();
  r = run("storyboard encode '" + agents.string() + "' --out '" + again + "'", dir.path);
  REQUIRE(r.exitCode == 0);
  CHECK(readPng(again).pixels == readPng(small).pixels);
}

TEST_CASE("cli: bad input exits non-zero with a message naming the file") {
  if (!haveThrong()) return;
  test::TempDir dir("throng-cli-errors");
  const auto garbage = dir.path / "garbage.png";
  std::ofstream(garbage) << "not a png";
  Run r = run("storyboard decode '" + garbage.string() + "' --json", dir.path);
  CHECK(r.exitCode != 0);
  CHECK(r.err.find("garbage.png") != std::string::npos);

  const auto legend = dir.path / "legend.json";
  std::ofstream(legend) << "{\"states\": {\"stroll\": [1, 2]}}";
  writePngAtomic(dir.path / "ok.png", test::exampleStoryboard(30, 1));
  r = run("storyboard decode '" + (dir.path / "ok.png").string() + "' --legend '" + legend.string() + "'", dir.path);
  CHECK(r.exitCode != 0);
  CHECK(r.err.find("legend.json: states.stroll: expected a colour") != std::string::npos);

  r = run("storyboard quilt '" + (dir.path / "ok.png").string() + "' --size 20by20 --out x.png", dir.path);
  CHECK(r.exitCode != 0);
  CHECK(r.err.find("expected WxH") != std::string::npos);
}
