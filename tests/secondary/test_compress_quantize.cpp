// Compression end to end on synthetic low-rank cloth: basis count chosen by error, rescaling,
// the 8/16-bit rule, quantization error bounds.
#include <doctest/doctest.h>

#include "cloth_fixtures.h"
#include "core/error.h"
#include "secondary/cloth_decoder.h"

using namespace throng;
using namespace throng::secondary;

TEST_CASE("quantizeBasis: 8 bits exactly when range × m / 255 fits the quantum") {
  const float quantum = 300e-6f;
  // Unit basis spanning [-0.5, 0.5]: range × m = m.
  std::vector<float> unit{-0.5f, -0.1f, 0.0f, 0.25f, 0.5f};
  const float limit = 255.0f * quantum;  // largest m that still fits 8 bits
  QuantizedBasis small = quantizeBasis(unit, limit * 0.999f, quantum);
  QuantizedBasis large = quantizeBasis(unit, limit * 1.001f, quantum);
  CHECK(small.bits == 8);
  CHECK(large.bits == 16);
  CHECK(small.step <= quantum);
  for (const QuantizedBasis* q : {&small, &large}) {
    for (size_t r = 0; r < unit.size(); ++r) {
      CHECK(std::abs(q->value(r) - unit[r] * q->scale) <= 0.5f * q->step + 1e-7f);
      CHECK(q->values[r] <= (q->bits == 8 ? 255 : 65535));
    }
  }
  // A constant basis (zero range) decodes to its value.
  QuantizedBasis flat = quantizeBasis(std::vector<float>{0.3f, 0.3f}, 2.0f, quantum);
  CHECK(flat.bits == 8);
  CHECK(flat.value(1) == doctest::Approx(0.6f));
}

TEST_CASE("coefficients: 16 bits over [-1, 1], clamped") {
  for (float c : {-1.0f, -0.731f, 0.0f, 1e-5f, 0.5f, 0.99999f, 1.0f})
    CHECK(std::abs(dequantizeCoefficient(quantizeCoefficient(c)) - c) <=
          0.5f / kCoefficientScale + 1e-7f);
  CHECK(quantizeCoefficient(3.0f) == 32767);
  CHECK(quantizeCoefficient(-3.0f) == -32767);
}

TEST_CASE("coefficient steps: one step moves no vertex more than the coefficient quantum") {
  // A basis whose largest vertex displacement is |(0.3, 0.4, 0)| = 0.5 m (8-bit grid of 0.1 m).
  std::vector<float> unit{0.3f, 0.4f, 0.0f, 0.1f, -0.2f, 0.0f};
  QuantizedBasis b = quantizeBasis(unit, 1.0f, 0.1f / 255.0f * 10.0f);
  float largest = glm::length(glm::vec3(b.value(0), b.value(1), b.value(2)));
  const float cq = 0.001f;
  const uint16_t k = coefficientStepFor(b, cq);
  CHECK(k > 1);
  CHECK(float(k) * largest / kCoefficientScale <= cq);
  CHECK(float(k + 1) * largest / kCoefficientScale > cq);
  CHECK(coefficientStepFor(b, 0.0f) == 1);
  CHECK(coefficientStepFor(b, 100.0f) == 32767);
  // Multiples of the step, the nearest one, never beyond ±32767.
  for (float c : {-1.0f, -0.4f, 0.0f, 0.0003f, 0.7f, 1.0f}) {
    int16_t q = quantizeCoefficientInSteps(c, k);
    CHECK(q % k == 0);
    CHECK(std::abs(float(q) - c * kCoefficientScale) <= 0.5f * k + 1e-3f);
  }
  CHECK(quantizeCoefficientInSteps(1.0f, 1000) == 32000);
  CHECK(quantizeCoefficientInSteps(-5.0f, 1000) == -32000);
  CHECK(quantizeCoefficientInSteps(0.7f, 1) == quantizeCoefficient(0.7f));
}

TEST_CASE(
    "compressCloth: fewest bases meeting the target, 8/16 bits follow m_i, error within the "
    "quantum") {
  test::LowRankFrames source{test::gridMesh(12, 10), {0.30f, 0.12f, 0.05f, 0.02f, 0.008f, 0.0005f}};
  PlaybackPrimary primary = test::syntheticPrimary(0.5f, {8, 6, 5});
  PlaybackGraph graph = test::syntheticGraph(primary, 20);
  ClothFrames frames = source.frames(graph.stateCount());
  CompressOptions options;
  options.targetError = 0.002f;
  options.maxBases = 10;
  options.threads = 2;
  ClothDatabase db = compressCloth(frames, source.mesh.triangles, primary, graph, options);
  const CompressionReport& r = db.report;
  // Modes of 0.5 mm fall under the 2 mm target; the 8 mm one does not.
  CHECK(db.basisCount() == 5);
  CHECK(r.maxErrorBeforeQuantization <= options.targetError);
  CompressOptions fewer = options;
  fewer.bases = db.basisCount() - 1;
  CHECK(compressCloth(frames, source.mesh.triangles, primary, graph, fewer)
            .report.maxErrorBeforeQuantization > options.targetError);

  // Rescaling: every coefficient row reaches ±1 (the largest multiple of its step there);
  // bits follow range × m_i / 255 ≤ quantum.
  REQUIRE(db.coefficientSteps.size() == db.basisCount());
  for (uint32_t i = 0; i < db.basisCount(); ++i) {
    const int step = db.coefficientSteps[i];
    CHECK(step == coefficientStepFor(db.bases[i], options.coefficientQuantum));
    int largest = 0;
    for (uint32_t s = 0; s < db.stateCount(); ++s) {
      const int q = db.coefficients[size_t(s) * db.basisCount() + i];
      CHECK(q % step == 0);
      largest = std::max(largest, std::abs(q));
    }
    CHECK(largest == 32767 / step * step);
    const QuantizedBasis& b = db.bases[i];
    float range = b.step * (b.bits == 8 ? 255.0f : 65535.0f);
    CHECK((b.bits == 8) == (range / 255.0f <= options.quantum));
  }
  CHECK(r.bases8 + r.bases16 == db.basisCount());
  CHECK(r.bases8 > 0);   // the small modes' bases fit 8 bits at 300 µm
  CHECK(r.bases16 > 0);  // the 30 cm mode does not

  // After quantization: within the truncation error plus the quantization bound of each basis.
  float bound = 0.0f;
  for (uint32_t i = 0; i < db.basisCount(); ++i) {
    const QuantizedBasis& b = db.bases[i];
    float largestValue = std::max(std::abs(b.offset),
                                  std::abs(b.offset + b.step * (b.bits == 8 ? 255.0f : 65535.0f)));
    bound += 0.5f * b.step + largestValue * 0.5f * db.coefficientSteps[i] / kCoefficientScale;
  }
  CHECK(r.maxError <= r.maxErrorBeforeQuantization + std::sqrt(3.0f) * bound);
  CHECK(r.meanError <= options.quantum);
  ReconstructionError again = reconstructionError(frames, db, 1);
  CHECK(again.max == doctest::Approx(r.maxError));
  CHECK(r.rawBytes == uint64_t(graph.stateCount()) * source.mesh.rest.size() * 12);
  CHECK(r.storedBytes == encodeClothDatabase(db).size());
  CHECK(r.ratio() > 1.0);
}

TEST_CASE(
    "compressCloth: a given basis count and an exact low-rank round trip within the quantum") {
  test::LowRankFrames source{test::gridMesh(8, 8), {0.04f, 0.02f, 0.01f}};
  PlaybackPrimary primary = test::syntheticPrimary(0.5f, {4, 4, 4});
  PlaybackGraph graph = test::syntheticGraph(primary, 10);
  ClothFrames frames = source.frames(graph.stateCount());
  CompressOptions options;
  options.bases = 3;
  ClothDatabase db = compressCloth(frames, source.mesh.triangles, primary, graph, options);
  CHECK(db.basisCount() == 3);
  CHECK(db.report.targetError == 0.0f);
  CHECK(db.report.maxErrorBeforeQuantization < 1e-5f);
  CHECK(db.report.maxError <= options.quantum);
  // Coarser coefficients: each basis may add half a coefficient quantum, no more.
  options.coefficientQuantum = 0.002f;
  ClothDatabase coarse = compressCloth(frames, source.mesh.triangles, primary, graph, options);
  CHECK(coarse.report.maxError > db.report.maxError);
  CHECK(coarse.report.maxError <= options.quantum + 3 * 0.5f * options.coefficientQuantum);
  CHECK(coarse.report.storedBytes < db.report.storedBytes);
}

TEST_CASE("compressCloth: a minimum ratio caps the basis count by the file's bytes") {
  test::LowRankFrames source{test::gridMesh(10, 10),
                             {0.2f, 0.1f, 0.05f, 0.03f, 0.02f, 0.01f, 0.005f, 0.003f}};
  PlaybackPrimary primary = test::syntheticPrimary(0.5f, {8, 6, 5});
  PlaybackGraph graph = test::syntheticGraph(primary, 30);
  ClothFrames frames = source.frames(graph.stateCount());
  CompressOptions options;
  options.targetError = 1e-6f;  // unreachable: every basis would be kept
  options.maxBases = 8;
  options.threads = 2;
  ClothDatabase all = compressCloth(frames, source.mesh.triangles, primary, graph, options);
  CHECK(all.basisCount() == 8);
  options.minRatio = 1.5 * all.report.ratio();
  ClothDatabase capped = compressCloth(frames, source.mesh.triangles, primary, graph, options);
  CHECK(capped.basisCount() < all.basisCount());
  CHECK(capped.report.ratio() >= options.minRatio);
  CHECK(capped.report.storedBytes == encodeClothDatabase(capped).size());
  // One more basis would break the ratio (the count is the largest that keeps it).
  CompressOptions more = options;
  more.minRatio = 0.0;
  more.bases = capped.basisCount() + 1;
  CHECK(compressCloth(frames, source.mesh.triangles, primary, graph, more).report.ratio() <
        options.minRatio);
  CHECK(capped.report.maxErrorBeforeQuantization > all.report.maxErrorBeforeQuantization);
}

TEST_CASE("compressCloth: bad options and inputs are reported") {
  test::LowRankFrames source{test::gridMesh(4, 4), {0.1f}};
  PlaybackPrimary primary = test::syntheticPrimary(0.5f, {2, 2, 2});
  PlaybackGraph graph = test::syntheticGraph(primary, 1);
  ClothFrames frames = source.frames(graph.stateCount());
  CompressOptions bad;
  bad.quantum = 0.0f;
  CHECK_THROWS_WITH_AS(compressCloth(frames, source.mesh.triangles, primary, graph, bad),
                       doctest::Contains("quantum"), Error);
  CompressOptions badCoefficients;
  badCoefficients.coefficientQuantum = -1.0f;
  CHECK_THROWS_WITH_AS(
      compressCloth(frames, source.mesh.triangles, primary, graph, badCoefficients),
      doctest::Contains("coefficient quantum"), Error);
  ClothFrames wrong = source.frames(graph.stateCount() + 1);
  CHECK_THROWS_WITH_AS(compressCloth(wrong, source.mesh.triangles, primary, graph, {}),
                       doctest::Contains("states"), Error);
  std::vector<uint32_t> badTriangles{0, 1, 99};
  CHECK_THROWS_WITH_AS(compressCloth(frames, badTriangles, primary, graph, {}),
                       doctest::Contains("triangle index 99"), Error);
}
