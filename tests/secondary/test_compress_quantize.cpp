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

  // Rescaling: every coefficient row reaches ±1; bits follow range × m_i / 255 ≤ quantum.
  for (uint32_t i = 0; i < db.basisCount(); ++i) {
    int largest = 0;
    for (uint32_t s = 0; s < db.stateCount(); ++s)
      largest = std::max(largest, std::abs(int(db.coefficients[size_t(s) * db.basisCount() + i])));
    CHECK(largest == 32767);
    const QuantizedBasis& b = db.bases[i];
    float range = b.step * (b.bits == 8 ? 255.0f : 65535.0f);
    CHECK((b.bits == 8) == (range / 255.0f <= options.quantum));
  }
  CHECK(r.bases8 + r.bases16 == db.basisCount());
  CHECK(r.bases8 > 0);   // the small modes' bases fit 8 bits at 300 µm
  CHECK(r.bases16 > 0);  // the 30 cm mode does not

  // After quantization: within the truncation error plus the quantization bound of each basis.
  float bound = 0.0f;
  for (const QuantizedBasis& b : db.bases) {
    float largestValue = std::max(std::abs(b.offset),
                                  std::abs(b.offset + b.step * (b.bits == 8 ? 255.0f : 65535.0f)));
    bound += 0.5f * b.step + largestValue * 0.5f / kCoefficientScale;
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
  ClothFrames wrong = source.frames(graph.stateCount() + 1);
  CHECK_THROWS_WITH_AS(compressCloth(wrong, source.mesh.triangles, primary, graph, {}),
                       doctest::Contains("states"), Error);
  std::vector<uint32_t> badTriangles{0, 1, 99};
  CHECK_THROWS_WITH_AS(compressCloth(frames, badTriangles, primary, graph, {}),
                       doctest::Contains("triangle index 99"), Error);
}
