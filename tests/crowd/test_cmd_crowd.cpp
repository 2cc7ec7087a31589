#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "crowd/trajectories.h"

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

namespace {
// Per second, how far each agent on the scene moved from the second's first frame to its last:
// the samples behind the simulation's mean speed, recomputed from a trajectories file.
std::vector<double> perSecondMoves(const crowd::Trajectories& t, int framesPerSecond, int seconds) {
  std::vector<double> moves;
  for (const crowd::Track& track : t.tracks) {
    std::map<long, glm::vec2> at;  // frame → position
    for (const crowd::TrackPoint& p : track.points)
      at[std::lround(p.time / t.secondsPerFrame)] = p.position;
    for (int s = 0; s < seconds; ++s) {
      auto from = at.find(long(s * framesPerSecond)), to = at.find(long((s + 1) * framesPerSecond));
      if (from != at.end() && to != at.end())
        moves.push_back(double(glm::length(to->second - from->second)));
    }
  }
  return moves;
}
}  // namespace

TEST_CASE("throng crowd simulate --trajectories-out: every step, read back as the simulation ran") {
  auto dir = test::freshDirectory("crowd_simulate_trajectories");
  auto tracks = writeTracks(dir);
  auto board = dir / "board.png";
  REQUIRE(test::runThrong("storyboard example --seed 5 --out " + board.string()).exitCode == 0);
  const std::string simulate = "crowd simulate --cpu --storyboard " + board.string() +
                               " --trajectories " + tracks.string() + " --policy none --seconds 3";
  const auto out = dir / "agents.txt";
  test::CommandResult r = test::runThrong(simulate + " --json --trajectories-out " + out.string());
  REQUIRE_MESSAGE(r.exitCode == 0, r.output);
  const nlohmann::json doc = nlohmann::json::parse(r.output.substr(r.output.find('{')));
  const nlohmann::json& run = doc["runs"][0];
  const size_t agents = doc["agents"].get<size_t>();
  CHECK(doc["trajectories_out"] == out.string());

  const crowd::Trajectories t = crowd::loadTrajectories(out);
  CHECK(t.format == crowd::TrajectoryFormat::PedPy);
  CHECK(t.secondsPerFrame == doctest::Approx(0.05));
  CHECK(t.tracks.size() == agents);
  // Frame 0 is the start, then one frame per step: 3 s at 0.05 s.
  CHECK(run["steps"] == 60);
  for (const crowd::Track& track : t.tracks) CHECK(track.points.size() == 61);
  // The positions are the simulated ones: the per-second moves give the reported mean speed.
  const std::vector<double> moves = perSecondMoves(t, 20, 3);
  CHECK(moves.size() == run["speed_samples"].get<size_t>());
  double sum = 0.0;
  for (double m : moves) sum += m;
  CHECK(sum / double(moves.size()) ==
        doctest::Approx(run["mean_speed"].get<double>()).epsilon(1e-4));

  // `crowd metrics` reads the file back as tracked people.
  test::CommandResult metrics = test::runThrong(
      "crowd metrics --cpu --policy none --seconds 2 "
      "--json --trajectories " +
      out.string());
  REQUIRE_MESSAGE(metrics.exitCode == 0, metrics.output);
  const nlohmann::json m = nlohmann::json::parse(metrics.output.substr(metrics.output.find('{')));
  CHECK(m["files"][0]["people"] == agents);

  // CSV: every agent in every frame, with the header the render command writes.
  const auto csv = dir / "agents.csv";
  r = test::runThrong(simulate + " --trajectories-out " + csv.string());
  REQUIRE_MESSAGE(r.exitCode == 0, r.output);
  CHECK(r.output.find("trajectories: " + csv.string()) != std::string::npos);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  CHECK(line == "id,frame,time,x,y,z,heading,speed,group,state");
  size_t rows = 0;
  while (std::getline(in, line)) ++rows;
  CHECK(rows == agents * 61);

  // One file holds one run; a bad name is refused before the run.
  r = test::runThrong(simulate + " --policy all --trajectories-out " + (dir / "all.txt").string());
  CHECK(r.exitCode == 1);
  CHECK(r.output.find("records one run; give one --policy") != std::string::npos);
  r = test::runThrong(simulate + " --trajectories-out " + (dir / "agents.dat").string());
  CHECK(r.exitCode == 1);
  CHECK(r.output.find("expected a .txt (PedPy 'id frame x y z') or .csv") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "all.txt"));
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
  CHECK(boids.output.find("error: --policy: unknown policy 'boids': expected anticipatory, "
                          "published, none, ttc, rule or all") != std::string::npos);
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
  // Counts and choices checked while parsing: usage errors, before any device is opened.
  auto expectUsage = [](const std::string& args, const std::string& text) {
    test::CommandResult r = test::runThrong(args);
    CAPTURE(args);
    CAPTURE(r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("error: " + text) != std::string::npos);
  };
  expectUsage("crowd bench --agents 10 0", "--agents: expected 1..1000000 agents, got 0");
  expectUsage("crowd metrics --cpu --body-radius 0 --trajectories " + tracks.string(),
              "--body-radius: expected metres in (0, 10], got 0");
  expectUsage("crowd bench --numbering sideways",
              "--numbering: unknown numbering 'sideways': expected grid or random");
  expectUsage("crowd simulate --storyboard " + board.string() + " --trajectories " +
                  tracks.string() + " --seconds 0.5",
              "--seconds: expected 1..100000 seconds, got 0.5");
}
