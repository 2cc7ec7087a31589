// Exploration runs: the graph does not depend on threads or lookahead, a checkpoint resumed
// gives the uninterrupted graph, and the .tsg file round trips and rejects damage clearly.
#include <doctest/doctest.h>

#include <fstream>

#include "core/error.h"
#include "explore_fixtures.h"
#include "secondary/offline/explore_file.h"
#include "test_support.h"

using namespace throng;
using namespace throng::secondary;
using namespace throng::secondary::fixtures;

namespace {
SecondaryGraph explore(const Garment& garment, unsigned threads, uint64_t expansions,
                       uint32_t lookahead = 0, const ExploreHooks& hooks = {}) {
  SecondaryGraph g = initializeToy(garment, threads);
  ThreadedRunner runner(*garment.primary, garment.step, threads);
  ExpandOptions options;
  options.lookahead = lookahead;
  exploreGraph(g, *garment.primary, runner, toyMetric(garment), options, {expansions, 0.0, 0.0f},
               hooks);
  return g;
}

nlohmann::json runConfig(const Garment& garment) {
  return {{"garment", garment.config},
          {"explore", {{"depth", 3}, {"max_states", 64}, {"velocity_scale", 0.1}}}};
}

std::filesystem::path outputPath(const std::string& name) {
  const auto dir = test::binaryDir() / "test_output" / "explore_run";
  std::filesystem::create_directories(dir);
  return dir / name;
}

std::vector<char> fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::filesystem::path& path, const std::vector<char>& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}
}  // namespace

TEST_CASE("the explored graph does not depend on threads or lookahead") {
  const Garment garment = toyGarment(3);
  const SecondaryGraph one = explore(garment, 1, 60, 1);
  const SecondaryGraph two = explore(garment, 2, 60);
  const SecondaryGraph wide = explore(garment, 2, 60, 16);
  requireSameGraph(one, two);
  requireSameGraph(one, wide);
  CHECK(one.expansions == 60);
  // A different seed explores a different graph (the seed jitters the initial cloth).
  const SecondaryGraph other = explore(toyGarment(4), 1, 60);
  CHECK_FALSE(sameBits(one.positions, other.positions));
}

TEST_CASE("a checkpoint resumed gives the uninterrupted graph") {
  const Garment garment = toyGarment();
  const SecondaryGraph full = explore(garment, 2, 50);

  const auto path = outputPath("checkpoint.tsg");
  std::filesystem::remove(path);
  ExploreHooks hooks;
  hooks.checkpointEvery = 7;
  uint64_t saved = 0;
  hooks.checkpoint = [&](const SecondaryGraph& g) {
    saveExploreFile(path, runConfig(garment), *garment.primary, *garment.mesh, g, garment.clips);
    saved = g.expansions;
  };
  explore(garment, 2, 30, 0, hooks);  // "interrupted" after 30; the last checkpoint is at 28
  CHECK(saved == 28);

  ExploreFile file = loadExploreFile(path);
  CHECK(file.graph.expansions == 28);
  CHECK(file.config == runConfig(garment));
  const Garment restored = restoreGarment(file.config["garment"], file.primary, file.mesh);
  ThreadedRunner runner(*restored.primary, restored.step, 1);
  exploreGraph(file.graph, *restored.primary, runner, toyMetric(restored), {}, {50, 0.0, 0.0f});
  requireSameGraph(file.graph, full);
}

TEST_CASE(".tsg round trips bit for bit and reports its contents") {
  const Garment garment = toyGarment();
  const SecondaryGraph g = explore(garment, 1, 12);
  const auto path = outputPath("roundtrip.tsg");
  saveExploreFile(path, runConfig(garment), *garment.primary, *garment.mesh, g, garment.clips);
  const ExploreFile f = loadExploreFile(path);
  requireSameGraph(f.graph, g);
  CHECK(f.mesh.restPositions == garment.mesh->restPositions);
  CHECK(f.primary.successors == garment.primary->successors);
  const auto again = outputPath("roundtrip2.tsg");
  saveExploreFile(again, f.config, f.primary, f.mesh, f.graph, f.clips);
  CHECK(fileBytes(path) == fileBytes(again));

  const nlohmann::json info = exploreFileInfo(path, true);
  CHECK(info["states"] == g.stateCount());
  CHECK(info["primary_nodes"] == garment.primary->nodes.size());
  CHECK(info["dead_ends"] == 0);
  CHECK(info["expansions"] == 12);
  CHECK(info["max_merge_error_m"].get<float>() == maxMergeError(g));
  CHECK(info["bytes"] == std::filesystem::file_size(path));
  CHECK(info["error_history"].size() == 13);
  CHECK(info["garment"] == "toy");
}

TEST_CASE("truncated or corrupted .tsg files give clear errors") {
  const Garment garment = toyGarment();
  const auto path = outputPath("good.tsg");
  saveExploreFile(path, runConfig(garment), *garment.primary, *garment.mesh, explore(garment, 1, 5),
                  garment.clips);
  const std::vector<char> good = fileBytes(path);
  const auto bad = outputPath("bad.tsg");

  writeBytes(bad, std::vector<char>(good.begin(), good.begin() + ptrdiff_t(good.size() * 2 / 3)));
  const std::string truncated = concat("bad.tsg: truncated at byte ", good.size() * 2 / 3);
  CHECK_THROWS_WITH_AS(loadExploreFile(bad), doctest::Contains(truncated.c_str()), Error);
  CHECK_THROWS_WITH_AS(exploreFileInfo(bad), doctest::Contains("truncated at byte"), Error);

  std::vector<char> flipped = good;
  flipped[good.size() / 2] ^= 0x40;
  writeBytes(bad, flipped);
  CHECK_THROWS_WITH_AS(loadExploreFile(bad), doctest::Contains("checksum mismatch"), Error);

  std::vector<char> future = good;
  future[8] = 9;  // version field
  writeBytes(bad, future);
  CHECK_THROWS_WITH_AS(loadExploreFile(bad), doctest::Contains("version 9 unsupported"), Error);

  writeBytes(bad, std::vector<char>{'n', 'o', 't', ' ', 'a', ' ', 'g', 'r', 'a', 'p', 'h'});
  CHECK_THROWS_WITH_AS(loadExploreFile(bad),
                       doctest::Contains("not a secondary motion graph (.tsg) file"), Error);
  CHECK_THROWS_WITH_AS(loadExploreFile(outputPath("missing.tsg")), doctest::Contains("cannot open"),
                       Error);
}
