// Trajectory files with huge frame numbers and long absences (the hardening issue, defects 3
// and 4): bounded work, time kept in double, errors naming the file.
#include <doctest/doctest.h>

#include <sstream>

#include "core/error.h"
#include "crowd/crowd_metrics.h"
#include "crowd/crowd_sim.h"
#include "crowd/path_vectors.h"
#include "crowd/trajectories.h"

using namespace throng;

namespace {

// Three people over 20 s, annotated every 10 frames (0.4 s), frames offset by `shift`: 1 and 2
// walk side by side 0.5 m apart, 3 walks the other way 40 m away.
std::string walkers(long long shift) {
  std::ostringstream out;
  out.precision(9);
  for (int k = 0; k <= 50; ++k) {
    const long long frame = shift + 10 * k;
    const float t = 0.4f * float(k);
    out << frame << "\t1\t" << 1.2f * t << "\t0\n";
    out << frame << "\t2\t" << 1.2f * t << "\t0.5\n";
    out << frame << "\t3\t" << 40.0f << "\t" << 10.0f - 1.0f * t << "\n";
  }
  return out.str();
}

}  // namespace

TEST_CASE("trajectories: shifting every frame number by 999,999,000 keeps the metrics") {
  const crowd::Trajectories near = crowd::parseTrajectories(walkers(0), "near.txt");
  const crowd::Trajectories far = crowd::parseTrajectories(walkers(999'999'000), "far.txt");
  REQUIRE(far.tracks.size() == 3);
  // Consecutive annotations stay 0.4 s apart at 4e7 s.
  CHECK(far.tracks[0].points[1].time - far.tracks[0].points[0].time ==
        doctest::Approx(0.4).epsilon(1e-6));
  const crowd::CrowdMetrics a = crowd::trajectoryMetrics(near, 0.3f);
  const crowd::CrowdMetrics b = crowd::trajectoryMetrics(far, 0.3f);
  CHECK(a.collisions == b.collisions);
  CHECK(a.safeIntrusions == b.safeIntrusions);
  CHECK(a.agentSeconds == doctest::Approx(b.agentSeconds));
  CHECK(a.seconds == doctest::Approx(b.seconds));
  CHECK(a.speedSamples == b.speedSamples);
  CHECK(a.meanSpeed == doctest::Approx(b.meanSpeed).epsilon(1e-5));
  CHECK(b.collisionsPerAgentSecond == 0.0);  // the real people never touch

  const std::vector<crowd::PathSource> sa = crowd::resamplePathVectors(near);
  const std::vector<crowd::PathSource> sb = crowd::resamplePathVectors(far);
  REQUIRE(sa.size() == sb.size());
  for (size_t i = 0; i < sa.size(); ++i) {
    REQUIRE(sa[i].vectors.size() == sb[i].vectors.size());
    for (size_t j = 0; j < sa[i].vectors.size(); ++j) {
      CHECK(sa[i].vectors[j].x == doctest::Approx(sb[i].vectors[j].x).epsilon(1e-4));
      CHECK(sa[i].vectors[j].y == doctest::Approx(sb[i].vectors[j].y).epsilon(1e-4));
    }
  }
}

TEST_CASE("trajectories: a person absent for longer than the bound becomes two tracks") {
  // Person 1 at frames 0..100 and again at 1e9; person 2 only at 0 and 1e9.
  std::string text;
  for (int k = 0; k <= 10; ++k)
    text += std::to_string(10 * k) + " 1 " + std::to_string(0.5 * k) + " 0\n";
  text += "1000000000 1 3 3\n1000000010 1 3.5 3\n1000000020 1 4 3\n";
  text += "0 2 0 5\n1000000000 2 9 9\n";
  const crowd::Trajectories t = crowd::parseTrajectories(text, "gap.txt");
  CHECK(t.gapSplits == 2);
  REQUIRE(t.tracks.size() == 4);
  CHECK(t.tracks[0].id == 1);
  CHECK(t.tracks[1].id == 1);
  CHECK(t.tracks[0].points.size() == 11);
  CHECK(t.tracks[1].points.size() == 3);
  for (const crowd::Track& track : t.tracks) CHECK(track.duration() < 4.001);
  // Work proportional to the annotations, not to the 4e7 s the file spans.
  const std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(t);
  size_t vectors = 0;
  for (const crowd::PathSource& s : sources) vectors += s.vectors.size();
  CHECK(sources.size() == 1);
  CHECK(vectors == 4);
}

TEST_CASE("trajectories: a file where nobody spans two seconds names the file") {
  const crowd::Trajectories t =
      crowd::parseTrajectories("0 1 0 0\n1000000000 1 5 5\n", "lonely.txt");
  const std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(t);
  CHECK(sources.empty());
  CHECK_THROWS_WITH_AS(crowd::replaySetup(sources, "lonely.txt"),
                       doctest::Contains("lonely.txt: no tracked person spans two whole seconds"),
                       Error);
  const std::vector<crowd::SpeedRange> ranges = {{0.5f, 1.5f}};
  CHECK_THROWS_WITH_AS(crowd::assignSources(sources, ranges, 1, "lonely.txt"),
                       doctest::Contains("lonely.txt: no tracked person"), Error);
}

TEST_CASE("trajectories: a replay skips the empty seconds between people far apart in time") {
  // Two people 2.4 s each, 40 s apart: the replay steps only through their own seconds.
  std::string text;
  for (int k = 0; k <= 6; ++k) {
    text += std::to_string(10 * k) + " 1 " + std::to_string(0.4 * k) + " 0\n";
    text += std::to_string(1000 + 10 * k) + " 2 " + std::to_string(0.4 * k) + " 3\n";
  }
  const crowd::Trajectories t = crowd::parseTrajectories(text, "apart.txt");
  const crowd::SimulationSetup setup =
      crowd::replaySetup(crowd::resamplePathVectors(t), "apart.txt");
  crowd::SimulationOptions options;
  options.avoidance.policy = crowd::SteerPolicy::None;
  options.seconds = 100.0f;
  options.dt = 0.1f;
  const crowd::SimulationResult r = crowd::simulateCrowd(nullptr, setup, options);
  CHECK(r.metrics.agentSeconds == doctest::Approx(4.0));  // 2 s of path vectors each
  CHECK(r.steps < 100);                                   // not 1000 steps of an empty scene
  CHECK(r.metrics.maxPathError < 1e-3);
}
