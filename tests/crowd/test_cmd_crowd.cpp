#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_support.h"

using namespace throng;

namespace {
// Two people walking 12 s across each other, annotated every 0.4 s.
std::filesystem::path writeTracks(const std::filesystem::path& dir) {
  std::ofstream out(dir / "tracks.txt");
  for (int k = 0; k <= 30; ++k) {
    float t = 0.4f * float(k);
    out << 10 * k << "\t1.0\t" << -6.0f + 1.0f * t << "\t0.0\n";
    out << 10 * k << "\t2.0\t0.0\t" << -7.0f + 1.3f * t << "\n";
  }
  return dir / "tracks.txt";
}
}  // namespace

TEST_CASE("throng crowd simulate: a storyboard on tracked paths, every policy, as JSON") {
  auto dir = test::freshDirectory("crowd_simulate");
  auto tracks = writeTracks(dir);
  auto board = dir / "board.png";
  REQUIRE(test::runThrong("storyboard example --seed 5 --out " + board.string()).exitCode == 0);
  test::CommandResult r =
      test::runThrong("crowd simulate --storyboard " + board.string() + " --trajectories " +
                      tracks.string() + " --policy all --seconds 4 --json");
  REQUIRE_MESSAGE(r.exitCode == 0, r.output);
  nlohmann::json doc = nlohmann::json::parse(r.output.substr(r.output.find('{')));
  CHECK(doc["agents"].get<int>() > 20);
  CHECK(doc["sources"] == 2);
  REQUIRE(doc["runs"].size() == 3);
  CHECK(doc["runs"][0]["policy"] == "none");
  CHECK(doc["runs"][1]["policy"] == "published");
  CHECK(doc["runs"][2]["policy"] == "anticipatory");
  CHECK(doc["schema"] == "throng.crowd_simulate");
  CHECK(doc["version"] == 1);
  for (const auto& run : doc["runs"]) {
    CHECK(run["steps"] == 80);
    CHECK(run["speed_samples"].get<int>() == 4 * doc["agents"].get<int>());
    CHECK(run["mean_speed"].get<double>() > 0.5);
  }
}

TEST_CASE("throng crowd metrics: replays the people with the CPU twin") {
  auto dir = test::freshDirectory("crowd_metrics");
  auto tracks = writeTracks(dir);
  test::CommandResult r = test::runThrong("crowd metrics --trajectories " + tracks.string() +
                                          " --cpu --policy ttc");  // the alias
  REQUIRE_MESSAGE(r.exitCode == 0, r.output);
  CHECK(r.output.find(
            "2 people (2 span 2+ s), frame step 10 = 0.400 s, replay of 12 s on cpu twin") !=
        std::string::npos);
  CHECK(r.output.find("real people: 2 agents") != std::string::npos);
  CHECK(r.output.find("policy anticipatory: 2 agents, 12 s") != std::string::npos);
  CHECK(r.output.find("at body radius 0.2 m") != std::string::npos);
  CHECK(r.output.find("safe-radius (0.3 m) intrusions per agent-second") != std::string::npos);
}

TEST_CASE("throng crowd: bad input is reported, not crashed on") {
  auto dir = test::freshDirectory("crowd_errors");
  auto tracks = writeTracks(dir);
  auto board = dir / "board.png";
  REQUIRE(test::runThrong("storyboard example --out " + board.string()).exitCode == 0);
  auto expectError = [](const std::string& args, const std::string& text) {
    test::CommandResult r = test::runThrong(args);
    CAPTURE(args);
    CAPTURE(r.output);
    CHECK(r.exitCode == 1);
    CHECK(r.output.find("error: " + text) != std::string::npos);
  };
  // An unknown policy is a usage error (exit 2) that lists the names.
  test::CommandResult boids =
      test::runThrong("crowd simulate --storyboard " + board.string() + " --trajectories " +
                      tracks.string() + " --policy boids");
  CAPTURE(boids.output);
  CHECK(boids.exitCode == 2);
  CHECK(boids.output.find(
            "error: --policy: boids not in {anticipatory,published,none,ttc,rule,all}") !=
        std::string::npos);
  expectError("crowd simulate --storyboard " + board.string() + " --trajectories " +
                  (dir / "none.txt").string(),
              (dir / "none.txt").string() + ": cannot open");
  expectError("crowd simulate --storyboard " + board.string() + " --trajectories " +
                  tracks.string() + " --dt 0.3",
              "step 0.3 s: expected 1/n of a second");
  std::ofstream(dir / "bad.txt") << "0\t1\t0\t0\n10\t1\tx\t0\n";
  expectError("crowd metrics --trajectories " + (dir / "bad.txt").string(),
              (dir / "bad.txt").string() + ":2: field 3 'x' is not a finite number");
  std::ofstream(dir / "lonely.txt") << "0\t1\t0\t0\n1000000000\t1\t5\t5\n";
  expectError("crowd metrics --cpu --trajectories " + (dir / "lonely.txt").string(),
              (dir / "lonely.txt").string() + ": no tracked person spans two whole seconds");
  expectError("crowd metrics --cpu --body-radius 0 --trajectories " + tracks.string(),
              "--body-radius 0: expected 0 < metres <= 10");
  expectError("crowd bench --agents 0", "--agents: each count must be 1..1000000, got 0");
  expectError("crowd bench --numbering sideways",
              "--numbering: expected grid or random, got 'sideways'");
}
