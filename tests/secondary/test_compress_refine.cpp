// Compression aimed at the largest error: the SVD reweighted towards the worst states, and the
// coefficient refinement after quantization.
#include <doctest/doctest.h>

#include "cloth_fixtures.h"
#include "core/error.h"
#include "secondary/cloth_decoder.h"
#include "secondary/offline/cloth_refine.h"

using namespace throng;
using namespace throng::secondary;

namespace {

// Largest vertex error of every state of `db` against the frames.
std::vector<float> stateErrors(const ClothFrames& frames, const ClothDatabase& db) {
  const DecodedBases d = dequantize(db);
  std::vector<glm::vec3> truth(frames.vertexCount), decoded(frames.vertexCount);
  std::vector<float> errors;
  for (uint32_t s = 0; s < frames.stateCount; ++s) {
    frames.positions(s, truth);
    decodeState(d, s, decoded);
    float e = 0.0f;
    for (uint32_t v = 0; v < frames.vertexCount; ++v)
      e = std::max(e, glm::length(truth[v] - decoded[v]));
    errors.push_back(e);
  }
  return errors;
}

}  // namespace

TEST_CASE("reweighting: a rare state the plain SVD leaves out gets a basis") {
  // Every state moves along mode 0 (large) and mode 1 (small); state 0 alone along mode 2. With
  // two bases the plain SVD keeps modes 0 and 1 (most energy) and misses state 0 entirely; one
  // reweighted pass weights state 0 by its error and takes mode 2 instead of mode 1.
  const test::LowRankFrames shapes{test::gridMesh(8, 6), {1.0f, 1.0f, 1.0f}};
  const std::vector<glm::vec3> mode0 = shapes.mode(0), mode1 = shapes.mode(1),
                               mode2 = shapes.mode(2);
  PlaybackPrimary primary = test::syntheticPrimary(0.5f, {8, 6, 5});
  PlaybackGraph graph = test::syntheticGraph(primary, 20);
  ClothFrames frames;
  frames.stateCount = graph.stateCount();
  frames.vertexCount = uint32_t(shapes.mesh.rest.size());
  frames.positions = [&](uint32_t s, std::span<glm::vec3> out) {
    const float a = 0.3f * std::sin(0.37f * float(s)), b = 0.02f * std::cos(0.91f * float(s));
    for (size_t v = 0; v < out.size(); ++v)
      out[v] = shapes.mesh.rest[v] + a * mode0[v] + (s == 0 ? 0.05f * mode2[v] : b * mode1[v]);
  };
  CompressOptions options;
  options.bases = 2;
  options.threads = 2;
  const ClothDatabase plain = compressCloth(frames, shapes.mesh.triangles, primary, graph, options);
  options.reweightPasses = 1;
  const ClothDatabase reweighted =
      compressCloth(frames, shapes.mesh.triangles, primary, graph, options);
  const std::vector<float> plainErrors = stateErrors(frames, plain);
  const std::vector<float> reweightedErrors = stateErrors(frames, reweighted);
  MESSAGE("largest error before quantization: plain ", plain.report.maxErrorBeforeQuantization,
          " m, reweighted ", reweighted.report.maxErrorBeforeQuantization,
          " m; state 0: ", plainErrors[0], " → ", reweightedErrors[0], " m");
  CHECK(reweighted.report.maxErrorBeforeQuantization <
        0.7f * plain.report.maxErrorBeforeQuantization);
  CHECK(reweightedErrors[0] < 0.2f * plainErrors[0]);
  CHECK(reweighted.basisCount() == 2);

  options.reweightPasses = 9;
  CHECK_THROWS_WITH_AS(compressCloth(frames, shapes.mesh.triangles, primary, graph, options),
                       doctest::Contains("reweight passes"), Error);
}

TEST_CASE("refinement: coefficient steps lower the largest error, never raise a state's") {
  // Coarse coefficient steps (3 mm) leave errors above a 2.5 mm target after quantization.
  const test::LowRankFrames source{test::gridMesh(12, 10), {0.30f, 0.12f, 0.05f, 0.02f, 0.008f}};
  PlaybackPrimary primary = test::syntheticPrimary(0.5f, {8, 6, 5});
  PlaybackGraph graph = test::syntheticGraph(primary, 20);
  ClothFrames frames = source.frames(graph.stateCount());
  CompressOptions options;
  options.bases = 5;
  options.coefficientQuantum = 0.003f;
  options.targetError = 0.0025f;
  options.threads = 2;
  const ClothDatabase rounded =
      compressCloth(frames, source.mesh.triangles, primary, graph, options);
  ClothDatabase refined = rounded;
  const RefineReport report = refineCoefficients(frames, refined, options.targetError, 4096, 2);
  const std::vector<float> before = stateErrors(frames, rounded),
                           after = stateErrors(frames, refined);
  const float largestBefore = *std::max_element(before.begin(), before.end());
  const float largestAfter = *std::max_element(after.begin(), after.end());
  MESSAGE("largest error ", largestBefore, " → ", largestAfter, " m; ", report.statesAboveTarget,
          " states above target, ", report.statesRefined, " refined, ", report.steps, " steps");
  REQUIRE(largestBefore > options.targetError);
  CHECK(largestAfter < largestBefore);
  CHECK(report.statesAboveTarget ==
        uint32_t(std::count_if(before.begin(), before.end(),
                               [&](float e) { return e > options.targetError; })));
  CHECK(report.statesRefined > 0);
  CHECK(report.steps >= report.statesRefined);
  // The measure after refining is reconstructionError's.
  const ReconstructionError measured = reconstructionError(frames, refined, 2);
  CHECK(report.after.max == doctest::Approx(measured.max));
  CHECK(report.after.mean == doctest::Approx(measured.mean));
  const uint32_t b = refined.basisCount();
  for (uint32_t s = 0; s < frames.stateCount; ++s) {
    CHECK(after[s] <= before[s]);
    for (uint32_t i = 0; i < b; ++i) {
      const int q = refined.coefficients[size_t(s) * b + i];
      CHECK(q % refined.coefficientSteps[i] == 0);
      CHECK(std::abs(q) <= 32767);
      // States already within the target keep their rounding.
      if (before[s] <= options.targetError) CHECK(q == rounded.coefficients[size_t(s) * b + i]);
    }
  }
  // compressCloth refines when asked, and reports it.
  options.refineSteps = 4096;
  const ClothDatabase direct =
      compressCloth(frames, source.mesh.triangles, primary, graph, options);
  CHECK(direct.report.statesRefined == report.statesRefined);
  CHECK(direct.report.maxError == doctest::Approx(largestAfter));
  options.targetError = 0.0f;
  CHECK_THROWS_WITH_AS(compressCloth(frames, source.mesh.triangles, primary, graph, options),
                       doctest::Contains("target error"), Error);
}
