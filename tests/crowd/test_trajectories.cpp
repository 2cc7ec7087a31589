#include <doctest/doctest.h>

#include <cmath>

#include "core/error.h"
#include "crowd/trajectories.h"
#include "test_support.h"

using namespace throng;

namespace {
const crowd::Track* findTrack(const crowd::Trajectories& t, int id) {
  for (const crowd::Track& track : t.tracks)
    if (track.id == id) return &track;
  return nullptr;
}

struct RealFile {
  const char* path;
  size_t people;
  size_t samples;
  int frameStep;
  float secondsPerStep;
};
}  // namespace

TEST_CASE("trajectories: every real ETH/UCY file loads with its people, samples and frame step") {
  if (!test::haveSharedData("trajectories")) return;
  const RealFile files[] = {
      {"sgan_format/biwi_eth.txt", 360, 5492, 10, 0.667f},
      {"sgan_format/biwi_hotel.txt", 389, 6543, 10, 0.4f},
      {"sgan_format/crowds_zara01.txt", 148, 5153, 10, 0.4f},
      {"sgan_format/crowds_zara02.txt", 204, 9722, 10, 0.4f},
      {"sgan_format/crowds_zara03.txt", 137, 5005, 10, 0.4f},
      {"sgan_format/students001.txt", 415, 21813, 10, 0.4f},
      {"sgan_format/students003.txt", 434, 17953, 10, 0.4f},
      // obsmat: 15 fps video annotated every 6th frame (seq_eth), 25 fps every 10th (hotel).
      {"eth_original/seq_eth/obsmat.txt", 360, 8908, 6, 0.4f},
      {"eth_original/seq_hotel/obsmat.txt", 390, 6544, 10, 0.4f},
  };
  for (const RealFile& f : files) {
    CAPTURE(f.path);
    auto path = test::sharedDataDir() / "trajectories" / f.path;
    if (!std::filesystem::exists(path)) {
      MESSAGE("SKIPPED: ", path.string(), " is absent");
      continue;
    }
    crowd::Trajectories t = crowd::loadTrajectories(path);
    CHECK(t.tracks.size() == f.people);
    CHECK(t.sampleCount == f.samples);
    CHECK(t.frameStep == f.frameStep);
    CHECK(t.secondsPerStep == doctest::Approx(f.secondsPerStep));
    size_t samples = 0;
    for (const crowd::Track& track : t.tracks) {
      samples += track.points.size();
      for (size_t k = 1; k < track.points.size(); ++k) REQUIRE(track.points[k].time > track.points[k - 1].time);
    }
    CHECK(samples == f.samples);
  }
}

TEST_CASE("trajectories: first samples of biwi_eth and ETH obsmat agree on person 1") {
  if (!test::haveSharedData("trajectories/sgan_format/biwi_eth.txt") ||
      !test::haveSharedData("trajectories/eth_original/seq_eth/obsmat.txt"))
    return;
  auto dir = test::sharedDataDir() / "trajectories";
  crowd::Trajectories sgan = crowd::loadTrajectories(dir / "sgan_format/biwi_eth.txt");
  crowd::Trajectories obsmat = crowd::loadTrajectories(dir / "eth_original/seq_eth/obsmat.txt");
  CHECK(obsmat.format == crowd::TrajectoryFormat::EthObsmat);
  const crowd::Track* a = findTrack(sgan, 1);
  const crowd::Track* b = findTrack(obsmat, 1);
  REQUIRE(a);
  REQUIRE(b);
  // "780 1.0 8.46 3.59" and "7.8e+02 1.0e+00 8.4568443e+00 0 3.5880664e+00 …": both frame 780.
  CHECK(a->points[0].position.x == doctest::Approx(8.46f));
  CHECK(a->points[0].position.y == doctest::Approx(3.59f));
  CHECK(b->points[0].position.x == doctest::Approx(8.4568443f));
  CHECK(b->points[0].position.y == doctest::Approx(3.5880664f));
  CHECK(a->points[0].time == doctest::Approx(780 * 0.0667f));
  CHECK(b->points[0].time == doctest::Approx(780 * 0.4f / 6.0f));
  // The same person walks at the same speed in both (≈ 1.7 m/s at the start).
  float va = glm::length(a->points[1].position - a->points[0].position) / (a->points[1].time - a->points[0].time);
  float vb = glm::length(b->points[1].position - b->points[0].position) / (b->points[1].time - b->points[0].time);
  CHECK(va == doctest::Approx(vb).epsilon(0.1));
}

TEST_CASE("trajectories: gaps, CRLF, spaces and comments in the frame/ped/x/y format") {
  const std::string text =
      "# a comment\r\n"
      "0\t1.0\t0.0\t0.0\r\n"
      "10  1.0   0.4 0.0\r\n"
      "\r\n"
      "80\t2.0\t5.0\t5.0\r\n"   // a jump of 70 frames where nobody was annotated
      "90\t2.0\t5.0\t5.5\n"
      "20\t1.0\t0.8\t0.0";     // out of order, no final newline
  crowd::Trajectories t = crowd::parseTrajectories(text, "mini.txt");
  CHECK(t.format == crowd::TrajectoryFormat::FramePedXY);
  CHECK(t.frameStep == 10);
  CHECK(t.secondsPerFrame == doctest::Approx(0.04f));
  REQUIRE(t.tracks.size() == 2);
  REQUIRE(t.tracks[0].points.size() == 3);
  CHECK(t.tracks[0].points[2].time == doctest::Approx(0.8f));
  CHECK(t.tracks[0].points[2].position.x == doctest::Approx(0.8f));
  CHECK(t.tracks[1].points[0].time == doctest::Approx(3.2f));
  CHECK(t.startTime() == 0.0f);
  crowd::TrajectoryOptions slow;
  slow.secondsPerStep = 0.667f;
  CHECK(crowd::parseTrajectories(text, "mini.txt", slow).tracks[1].points[0].time == doctest::Approx(8 * 0.667f));
  CHECK(crowd::defaultSecondsPerStep("/x/biwi_eth.txt") == doctest::Approx(0.667f));
  CHECK(crowd::defaultSecondsPerStep("/x/crowds_zara01.txt") == doctest::Approx(0.4f));
}

TEST_CASE("trajectories: malformed input names file, line and what was expected") {
  auto error = [](const std::string& text, const std::string& name = "bad.txt") {
    try {
      crowd::parseTrajectories(text, name);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(error("").find("bad.txt: no trajectory samples") != std::string::npos);
  CHECK(error("# only a comment\n\n").find("no trajectory samples") != std::string::npos);
  CHECK(error("1 2 3\n").find("bad.txt:1: expected 4 numbers 'frame ped_id x y' or 8") != std::string::npos);
  CHECK(error("0 1 0 0\n10 1 0\n").find("bad.txt:2: expected 4 numbers 'frame ped_id x y', got 3 fields") !=
        std::string::npos);
  CHECK(error("0 1 0 0\n10 1 abc 0\n").find("bad.txt:2: field 3 'abc' is not a finite number") != std::string::npos);
  CHECK(error("0 1 0 0\n10 1 nan 0\n").find("bad.txt:2: field 3 'nan' is not a finite number") != std::string::npos);
  CHECK(error("0.5 1 0 0\n").find("bad.txt:1: frame number 0.5 is not an integer") != std::string::npos);
  CHECK(error("0 1.5 0 0\n").find("bad.txt:1: person id 1.5 is not an integer") != std::string::npos);
  CHECK(error("-10 1 0 0\n").find("bad.txt:1: frame number -10 is negative") != std::string::npos);
  CHECK(error("0 1 0 0\n10 1 1 0\n0 1 2 0\n").find("bad.txt:3: person 1 appears twice in frame 0 (first on line 1)") !=
        std::string::npos);
  CHECK(error("0 1 1e9 0\n").find("bad.txt:1: position (1e+09, 0) is not within 1e6 metres") != std::string::npos);
  // obsmat by name: 8 columns expected.
  CHECK(error("0 1 0 0\n", "seq/obsmat.txt").find("seq/obsmat.txt:1: expected 8 numbers 'frame ped x z y vx vz vy'") !=
        std::string::npos);
  crowd::TrajectoryOptions bad;
  bad.secondsPerStep = -1.0f;
  CHECK_THROWS_WITH_AS(crowd::parseTrajectories("0 1 0 0\n", "x.txt", bad), doctest::Contains("seconds per step -1"),
                       Error);
  CHECK_THROWS_WITH_AS(crowd::loadTrajectories("/nonexistent/dir/tracks.txt"),
                       doctest::Contains("/nonexistent/dir/tracks.txt: cannot open"), Error);
}

TEST_CASE("trajectories: obsmat scientific notation with the height column ignored") {
  const std::string text =
      "   6.0000000e+00   3.0000000e+00   1.5000000e+00   9.9000000e+01  -2.2500000e+00   0.0e+00 0.0e+00 0.0e+00\r\n"
      "   1.2000000e+01   3.0000000e+00   2.0000000e+00   9.9000000e+01  -2.0000000e+00   0.0e+00 0.0e+00 0.0e+00\r\n";
  crowd::Trajectories t = crowd::parseTrajectories(text, "obsmat.txt");
  REQUIRE(t.tracks.size() == 1);
  CHECK(t.tracks[0].id == 3);
  CHECK(t.frameStep == 6);
  CHECK(t.tracks[0].points[1].time == doctest::Approx(0.8f));
  CHECK(t.tracks[0].points[0].position == glm::vec2(1.5f, -2.25f));
}
