// Other clips joining the primary graph through pose + velocity transitions.
#include <doctest/doctest.h>

#include "anim/bvh.h"
#include "anim/clip_prep.h"
#include "core/error.h"
#include "primary_fixtures.h"
#include "test_support.h"

using namespace throng;
using namespace throng::secondary;

namespace {

// Every edge added between the graph's old nodes and the clip joins similar poses: from a node
// into the frame after a similar clip frame, or from a clip frame on to where a similar node goes.
void checkTransitionsJoinSimilarPoses(const PrimaryGraph& before, const PrimaryGraph& after,
                                      const ClipPoses& clip, const TransitionReport& report,
                                      const TransitionOptions& options) {
  const uint32_t frames = clip.frameCount();
  uint32_t into = 0, out = 0;
  for (uint32_t a = 0; a < report.firstNode; ++a)
    for (size_t k = before.successors[a].size(); k < after.successors[a].size(); ++k) {
      const uint32_t target = after.successors[a][k];
      REQUIRE(target >= report.firstNode);
      const uint32_t similar = (target - report.firstNode + frames - 1) % frames;
      CHECK(transitionDistance(before, a, clip, similar, options) < options.threshold);
      ++into;
    }
  for (uint32_t c = 0; c < frames; ++c)
    for (uint32_t target : after.successors[report.firstNode + c]) {
      if (target >= report.firstNode) continue;
      bool fromSimilar = false;
      for (uint32_t a = 0; a < report.firstNode && !fromSimilar; ++a)
        for (uint32_t s : before.successors[a])
          if (s == target && transitionDistance(before, a, clip, c, options) < options.threshold)
            fromSimilar = true;
      CHECK_MESSAGE(fromSimilar, "clip frame ", c, " → node ", target);
      ++out;
    }
  CHECK(into == report.intoClip);
  CHECK(out == report.outOfClip);
}

}  // namespace

TEST_CASE("a jog cycle joins the run graph both ways and survives pruning") {
  const PrimaryGraph& run = *test::defaultRunGraph();
  PrimaryGraph graph = run;
  const ClipPoses jog = clipPoses(test::jogClip(), true);
  REQUIRE(jog.frameCount() == 26);
  const TransitionOptions options;
  const TransitionReport report = addClipWithTransitions(graph, jog, options);
  MESSAGE("jog: ", report.intoClip, " edges in, ", report.outOfClip, " out, closest pose distance ",
          report.bestDistance);
  CHECK(report.clip == 1);
  CHECK(report.firstNode == run.nodes.size());
  CHECK(report.intoClip > 0);
  CHECK(report.outOfClip > 0);
  CHECK(graph.nodes.size() == run.nodes.size() + 26);
  CHECK(graph.nodes.back().clip == 1);
  CHECK(graph.nodes.back().frame == 25);
  checkTransitionsJoinSimilarPoses(run, graph, jog, report, options);
  // The jog's own cycle: the last frame goes back to the first with the cycle's travel.
  CHECK(naturalSuccessor(graph, report.firstNode + 25) == report.firstNode);

  const std::vector<int32_t> remap = pruneToStronglyConnected(graph);
  CHECK(graph.nodes.size() == run.nodes.size() + 26);  // nothing was a dead end
  for (int32_t r : remap) CHECK(r >= 0);
  CHECK(isStronglyConnected(graph));
}

TEST_CASE("a one-shot clip keeps only the frames that lead back, and no dead end is left") {
  PrimaryGraph graph = *test::defaultRunGraph();
  ClipPoses shot = clipPoses(test::jogClip(), false);
  REQUIRE(shot.rootSteps.size() == 25);
  const TransitionReport report = addClipWithTransitions(graph, shot, TransitionOptions{});
  CHECK(report.outOfClip > 0);
  const std::vector<int32_t> remap = pruneToStronglyConnected(graph);
  CHECK(isStronglyConnected(graph));
  for (const auto& next : graph.successors) CHECK(!next.empty());
  uint32_t kept = 0;
  for (uint32_t c = 0; c < 26; ++c) kept += remap[report.firstNode + c] >= 0 ? 1u : 0u;
  MESSAGE("one-shot jog: ", kept, " of 26 frames kept");
  CHECK(kept > 0);
  // The run graph itself is never cut.
  for (uint32_t v = 0; v < report.firstNode; ++v) CHECK(remap[v] == int32_t(v));
}

TEST_CASE("a threshold below every distance adds no transition; bad input is refused") {
  PrimaryGraph graph = *test::defaultRunGraph();
  const ClipPoses jog = clipPoses(test::jogClip(), true);
  const TransitionReport report =
      addClipWithTransitions(graph, jog, TransitionOptions{.threshold = 1e-4f});
  CHECK(report.intoClip == 0);
  CHECK(report.outOfClip == 0);
  CHECK(report.bestDistance > 1e-4f);
  pruneToStronglyConnected(graph);
  CHECK(graph.nodes.size() == test::defaultRunGraph()->nodes.size());  // the unjoined jog is cut

  ClipPoses other = jog;
  other.parents[3] = 1;
  CHECK_THROWS_WITH_AS(addClipWithTransitions(graph, other, {}),
                       doctest::Contains("skeleton topology"), Error);
  CHECK_THROWS_AS(addClipWithTransitions(graph, jog, TransitionOptions{.threshold = 0.0f}), Error);
}

TEST_CASE("real capture: the Bandai Namco walk joins the Bandai Namco run + dash graph") {
  const std::string dir = "bvh/bandai_namco/";
  if (!test::haveSharedData(dir + "dataset-1_walk_normal_002.bvh") ||
      !test::haveSharedData(dir + "dataset-1_run_normal_001.bvh") ||
      !test::haveSharedData(dir + "dataset-1_dash_normal_001.bvh"))
    return;
  const std::filesystem::path root = test::sharedDataDir() / dir;
  const anim::ClipPair pair = anim::loadClipPair(root / "dataset-1_run_normal_001.bvh",
                                                 root / "dataset-1_dash_normal_001.bvh");
  PrimaryGraph graph = buildRunGraph(pair, 0.1f);
  // The walk prepared like one clip of a pair: metres, 30 fps, best loop, travel along +z.
  anim::Clip walk = anim::toClip(anim::loadBvh(root / "dataset-1_walk_normal_002.bvh"));
  walk = anim::scaleToMetres(walk, anim::detectUnits(walk.skeleton).metresPerUnit);
  walk = anim::resample(walk, graph.frameTime);
  walk = anim::faceForwardZ(anim::closeSeam(walk, anim::findBestLoop(walk, 12, walk.frameCount)));
  if (!walk.skeleton.sameTopology(pair.slow.skeleton)) {
    MESSAGE("SKIPPED: the Bandai Namco walk does not share the run's skeleton topology");
    return;
  }
  const ClipPoses poses = clipPoses(walk, true);
  const TransitionOptions options{.threshold = 0.3f};
  const PrimaryGraph before = graph;
  const TransitionReport report = addClipWithTransitions(graph, poses, options);
  MESSAGE("Bandai walk (", poses.frameCount(), " frames): ", report.intoClip, " edges in, ",
          report.outOfClip, " out, closest pose distance ", report.bestDistance);
  CHECK(report.intoClip > 0);
  CHECK(report.outOfClip > 0);
  checkTransitionsJoinSimilarPoses(before, graph, poses, report, options);
  pruneToStronglyConnected(graph);
  CHECK(isStronglyConnected(graph));
  CHECK(graph.nodes.size() == before.nodes.size() + poses.frameCount());

  // The built-in gait's skeleton is not Bandai Namco's: joining it is refused, clearly.
  PrimaryGraph gait = *test::defaultRunGraph();
  CHECK_THROWS_WITH_AS(addClipWithTransitions(gait, poses, options),
                       doctest::Contains("skeleton topology"), Error);
}
