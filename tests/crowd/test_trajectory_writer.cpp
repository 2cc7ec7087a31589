// --trajectories-out: the PedPy text and CSV exports of a crowd, and the PedPy file read back
// by the trajectory reader that `crowd metrics` uses.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "anim/default_clips.h"
#include "core/error.h"
#include "core/file_io.h"
#include "crowd/circle_paths.h"
#include "crowd/crowd_metrics.h"
#include "crowd/scenario.h"
#include "crowd/trajectories.h"
#include "crowd/trajectory_writer.h"
#include "test_support.h"

using namespace throng;

namespace {
std::filesystem::path scratch(const std::string& name) {
  std::filesystem::path dir = test::binaryDir() / "test_output" / "trajectory_writer";
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / name);
  return dir / name;
}

// The steered circle scene on the CPU, `frames` steps at 10 fps, recorded into `writer` and
// kept in memory as tracks (ground plane (engine x, engine z), time = frame / fps).
crowd::Trajectories runAndRecord(crowd::TrajectoryWriter& writer, int frames) {
  crowd::ScenarioOptions scenario;
  scenario.name = "circle";
  scenario.characters = 40;
  const crowd::Crowd start = crowd::makeScenario(scenario);
  const anim::ClipPair clips = anim::defaultRunPair();
  const anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  const crowd::AgentPaths paths =
      crowd::circlePaths(start, anim::clipRootSpeed(pair.slow), anim::clipRootSpeed(pair.fast));
  crowd::SteeredCrowdCpu sim(pair, start, &paths, crowd::AvoidanceParams{});
  crowd::Trajectories memory;
  memory.source = "memory";
  memory.format = crowd::TrajectoryFormat::PedPy;
  memory.frameStep = 1;
  memory.secondsPerStep = memory.secondsPerFrame = 0.1;
  memory.tracks.resize(start.size());
  for (int f = 0; f < frames; ++f) {
    if (f > 0) sim.step(0.1f);
    writer.addFrame(sim.crowd().placement);
    for (size_t i = 0; i < start.size(); ++i) {
      const glm::vec4 p = sim.crowd().placement[i];
      memory.tracks[i].id = int(i);
      memory.tracks[i].points.push_back({double(f) * 0.1, glm::vec2(p.x, p.z)});
    }
  }
  writer.finish();
  return memory;
}
}  // namespace

TEST_CASE("trajectory export: the PedPy file reads back within 1e-4 m with the same metrics") {
  const std::filesystem::path path = scratch("circle.txt");
  crowd::TrajectoryWriter writer(path, 10.0, {});
  const crowd::Trajectories memory = runAndRecord(writer, 60);
  const std::string text = readTextFile(path);
  CHECK(text.rfind("# framerate: 10\n", 0) == 0);
  CHECK(text.find("y = engine z") != std::string::npos);
  const crowd::Trajectories read = crowd::loadTrajectories(path);
  CHECK(read.format == crowd::TrajectoryFormat::PedPy);
  CHECK(read.frameStep == 1);
  CHECK(read.secondsPerFrame == doctest::Approx(0.1));
  REQUIRE(read.tracks.size() == memory.tracks.size());
  double worst = 0.0;
  for (size_t t = 0; t < read.tracks.size(); ++t) {
    REQUIRE(read.tracks[t].points.size() == memory.tracks[t].points.size());
    for (size_t k = 0; k < read.tracks[t].points.size(); ++k) {
      worst = std::max(worst, double(glm::length(read.tracks[t].points[k].position -
                                                 memory.tracks[t].points[k].position)));
      CHECK(read.tracks[t].points[k].time == doctest::Approx(memory.tracks[t].points[k].time));
    }
  }
  MESSAGE("largest position difference after the round trip: ", worst, " m");
  CHECK(worst <= 1e-4);
  const crowd::CrowdMetrics a = crowd::trajectoryMetrics(memory, 0.3f);
  const crowd::CrowdMetrics b = crowd::trajectoryMetrics(read, 0.3f);
  CHECK(a.agents == b.agents);
  CHECK(a.collisions == b.collisions);
  CHECK(a.safeIntrusions == b.safeIntrusions);
  CHECK(b.agentSeconds == doctest::Approx(a.agentSeconds));
  CHECK(b.meanSpeed == doctest::Approx(a.meanSpeed).epsilon(1e-5));
  CHECK(b.peakDensity == doctest::Approx(a.peakDensity));
  CHECK(b.meanSpeed > 1.0);  // the runners move
}

TEST_CASE("trajectory export: CSV rows carry time, heading, speed, group and state") {
  const std::filesystem::path path = scratch("two.csv");
  crowd::TrajectoryWriter writer(path, 20.0, {3, 5});
  const std::vector<glm::vec4> first{{0, 0, 0, 0.5f}, {1, 0, 1, 0}};
  const std::vector<glm::vec4> second{{0.1f, 0, 0, 0.5f}, {1, 0, 1, 0}};
  writer.addFrame(first, std::vector<uint8_t>{1, 0});
  writer.addFrame(second, std::vector<uint8_t>{1, 1});
  CHECK(!std::filesystem::exists(path));  // nothing on disk before finish
  writer.finish();
  const std::string text = readTextFile(path);
  CHECK(text.rfind("id,frame,time,x,y,z,heading,speed,group,state\n", 0) == 0);
  CHECK(text.find("1,0,0.000000,1.000000,0.000000,1.000000,0.00000,0.0000,5,inactive\n") !=
        std::string::npos);
  // 0.1 m in 1/20 s: 2 m/s.
  CHECK(text.find("0,1,0.050000,0.100000,0.000000,0.000000,0.50000,2.0000,3,active\n") !=
        std::string::npos);
  CHECK(writer.rows() == 4);
}

TEST_CASE("trajectory export: bad names and sizes are refused before a run") {
  CHECK_THROWS_WITH_AS(crowd::checkTrajectoryOutput("out.json", 10, 10),
                       doctest::Contains("--trajectories-out out.json: expected a .txt"), Error);
  CHECK_THROWS_WITH_AS(crowd::checkTrajectoryOutput("out.txt", 100000, 100000),
                       doctest::Contains("rows"), Error);
  CHECK_NOTHROW(crowd::checkTrajectoryOutput(scratch("ok.txt"), 10, 10));
  crowd::TrajectoryWriter writer(scratch("n.txt"), 10.0, {});
  writer.addFrame(std::vector<glm::vec4>(3));
  CHECK_THROWS_WITH_AS(writer.addFrame(std::vector<glm::vec4>(2)),
                       doctest::Contains("has 2 agents"), Error);
}

TEST_CASE("trajectories: PedPy text with a framerate, centimetres and extra columns") {
  const std::string text =
      "# framerate: 16.0\n# x/cm y/cm z/cm\n1 0 100 200 170 9\n1 1 110 200 170 9\n"
      "2 0 0 0 170 9\n2 1 0 10 170 9\n";
  const crowd::Trajectories t = crowd::parseTrajectories(text, "pedpy.txt");
  CHECK(t.format == crowd::TrajectoryFormat::PedPy);
  CHECK(t.secondsPerFrame == doctest::Approx(1.0 / 16.0));
  REQUIRE(t.tracks.size() == 2);
  CHECK(t.tracks[0].points[1].position.x == doctest::Approx(1.1f));
  CHECK(t.tracks[0].points[1].time == doctest::Approx(1.0 / 16.0));
  CHECK_THROWS_WITH_AS(crowd::parseTrajectories("# framerate: -3\n1 0 0 0 0\n", "bad.txt"),
                       doctest::Contains("bad.txt:1: expected '# framerate: F'"), Error);
  CHECK_THROWS_WITH_AS(crowd::parseTrajectories("# framerate: 10\n1 0 0 0\n", "short.txt"),
                       doctest::Contains("short.txt:2: expected 5 numbers 'id frame x y z'"),
                       Error);
}
