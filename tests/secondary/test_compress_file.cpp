// The .tsc file: exact round trip, and clear errors on corrupted, truncated or inconsistent files.
#include <doctest/doctest.h>

#include <filesystem>

#include "chunk_patch.h"
#include "cloth_fixtures.h"
#include "core/binary_io.h"
#include "core/error.h"
#include "core/file_io.h"
#include "test_support.h"

using namespace throng;
using namespace throng::secondary;

namespace {
ClothDatabase smallDatabase() {
  PlaybackPrimary primary = test::syntheticPrimary(0.5f, {5, 4, 3});
  PlaybackGraph graph = test::syntheticGraph(primary, 3);
  ClothDatabase db = test::randomDatabase(primary, graph, test::gridMesh(6, 5), 7, 11);
  db.report.quantum = 300e-6f;
  db.report.maxError = 0.0012f;
  db.report.singularValues = {3.0f, 2.0f, 1.0f};
  return db;
}

std::filesystem::path scratch(const char* name) {
  std::filesystem::path dir = test::binaryDir() / "test_secondary_compress";
  std::filesystem::create_directories(dir);
  return dir / name;
}
}  // namespace

TEST_CASE(".tsc round trip is exact") {
  ClothDatabase db = smallDatabase();
  std::vector<uint8_t> bytes = encodeClothDatabase(db);
  CHECK(isClothDatabase(bytes));
  ClothDatabase back = decodeClothDatabase(bytes, "memory");
  CHECK(back.vertexCount == db.vertexCount);
  CHECK(back.triangles == db.triangles);
  CHECK(back.primary.firstSuccessor == db.primary.firstSuccessor);
  CHECK(back.primary.successors == db.primary.successors);
  CHECK(back.primary.run.bucketWidth == db.primary.run.bucketWidth);
  CHECK(back.primary.run.framesPerBucket == db.primary.run.framesPerBucket);
  REQUIRE(back.primary.nodes.size() == db.primary.nodes.size());
  for (size_t n = 0; n < db.primary.nodes.size(); ++n) {
    CHECK(back.primary.nodes[n].bucket == db.primary.nodes[n].bucket);
    CHECK(back.primary.nodes[n].frame == db.primary.nodes[n].frame);
  }
  CHECK(back.graph.stateNode == db.graph.stateNode);
  CHECK(back.graph.firstEdge == db.graph.firstEdge);
  CHECK(back.graph.edgeTarget == db.graph.edgeTarget);
  CHECK(back.graph.edgeIsMerge == db.graph.edgeIsMerge);
  CHECK(back.mean == db.mean);
  REQUIRE(back.bases.size() == db.bases.size());
  for (size_t i = 0; i < db.bases.size(); ++i) {
    CHECK(back.bases[i].bits == db.bases[i].bits);
    CHECK(back.bases[i].offset == db.bases[i].offset);
    CHECK(back.bases[i].step == db.bases[i].step);
    CHECK(back.bases[i].values == db.bases[i].values);
  }
  CHECK(back.coefficients == db.coefficients);
  CHECK(back.coefficientSteps == std::vector<uint16_t>(db.basisCount(), 1));  // none given: 1
  CHECK(back.report.maxError == db.report.maxError);
  CHECK(back.report.coefficientQuantum == db.report.coefficientQuantum);
  CHECK(back.report.singularValues == db.report.singularValues);
  CHECK(back.report.storedBytes == bytes.size());
  CHECK(back.report.rawBytes == uint64_t(db.stateCount()) * db.vertexCount * 12);
  // Entropy-coded: coarser coefficient steps and smoother bases take fewer bytes.
  ClothDatabase smooth = db;
  for (QuantizedBasis& b : smooth.bases)
    for (size_t r = 0; r < b.values.size(); ++r) b.values[r] = uint16_t(100 + r / 3 % 2);
  CHECK(encodeClothDatabase(smooth).size() + db.basisCount() * db.vertexCount / 2 < bytes.size());
}

TEST_CASE(".tsc: coefficient steps round trip, and coefficients off their step are refused") {
  ClothDatabase db = smallDatabase();
  db.coefficientSteps.assign(db.basisCount(), 1);
  db.coefficientSteps[2] = 300;
  for (uint32_t s = 0; s < db.stateCount(); ++s) {
    int16_t& c = db.coefficients[size_t(s) * db.basisCount() + 2];
    c = int16_t(c / 300 * 300);
  }
  std::vector<uint8_t> bytes = encodeClothDatabase(db);
  ClothDatabase back = decodeClothDatabase(bytes, "memory");
  CHECK(back.coefficientSteps == db.coefficientSteps);
  CHECK(back.coefficients == db.coefficients);
  // Fewer bytes than the same database with full-precision coefficients.
  CHECK(bytes.size() < encodeClothDatabase(smallDatabase()).size());
  ClothDatabase off = db;
  off.coefficients[2] += 1;
  CHECK_THROWS_WITH_AS(encodeClothDatabase(off), doctest::Contains("not a multiple of its step"),
                       Error);
  ClothDatabase wrongCount = db;
  wrongCount.coefficientSteps.pop_back();
  CHECK_THROWS_WITH_AS(encodeClothDatabase(wrongCount), doctest::Contains("coefficient steps"),
                       Error);
}

TEST_CASE(".tsc: corrupted, truncated and foreign files give clear errors") {
  std::vector<uint8_t> bytes = encodeClothDatabase(smallDatabase());
  std::vector<uint8_t> corrupted = bytes;
  corrupted[corrupted.size() / 2] ^= 0x40;
  CHECK_THROWS_WITH_AS(decodeClothDatabase(corrupted, "g.tsc"),
                       doctest::Contains("g.tsc: checksum mismatch"), Error);
  for (size_t keep : {size_t(2), size_t(10), size_t(40), bytes.size() / 3, bytes.size() - 1}) {
    std::vector<uint8_t> truncated(bytes.begin(), bytes.begin() + long(keep));
    CHECK_THROWS_WITH_AS(decodeClothDatabase(truncated, "g.tsc"), doctest::Contains("g.tsc"),
                         Error);
  }
  std::vector<uint8_t> tail(bytes.begin(), bytes.end() - 5);
  CHECK_THROWS_WITH_AS(decodeClothDatabase(tail, "g.tsc"), doctest::Contains("truncated"), Error);
  std::vector<uint8_t> longer = bytes;
  longer.push_back(0);
  CHECK_THROWS_WITH_AS(decodeClothDatabase(longer, "g.tsc"), doctest::Contains("unexpected bytes"),
                       Error);
  std::vector<uint8_t> foreign = bytes;
  foreign[0] = 'X';
  CHECK_THROWS_WITH_AS(decodeClothDatabase(foreign, "g.tsc"),
                       doctest::Contains("not a compressed cloth (.tsc) file"), Error);
  std::vector<uint8_t> future = bytes;
  future[8] = 9;
  CHECK_THROWS_WITH_AS(decodeClothDatabase(future, "g.tsc"),
                       doctest::Contains("version 9 unsupported"), Error);
  // Version 1 (plain bases and coefficients) is refused by name: it must be recompressed.
  ChunkWriter version1(kClothDatabaseMagic, 1);
  version1.addScalar("VERT", 4u);
  CHECK_THROWS_WITH_AS(decodeClothDatabase(version1.bytes(), "old.tsc"),
                       doctest::Contains("old.tsc: compressed cloth (.tsc) version 1 unsupported"),
                       Error);
}

TEST_CASE(".tsc: inconsistent content is refused on write and read") {
  ClothDatabase db = smallDatabase();
  ClothDatabase badEdge = db;
  badEdge.graph.edgeTarget[0] = badEdge.stateCount();
  CHECK_THROWS_WITH_AS(encodeClothDatabase(badEdge), doctest::Contains("out of range"), Error);
  ClothDatabase wrongNode = db;
  // State 0 sits at node 0; its only successor is node 1, so a target at node 2 is wrong.
  wrongNode.graph.edgeTarget[0] = 2 * 3;
  CHECK_THROWS_WITH_AS(encodeClothDatabase(wrongNode), doctest::Contains("not at successor node"),
                       Error);
  ClothDatabase bits = db;
  bits.bases[1].bits = 12;
  CHECK_THROWS_WITH_AS(encodeClothDatabase(bits), doctest::Contains("12 bits"), Error);
  ClothDatabase coefficients = db;
  coefficients.coefficients.pop_back();
  CHECK_THROWS_WITH_AS(encodeClothDatabase(coefficients), doctest::Contains("coefficients"), Error);
}

TEST_CASE(".tsc file: atomic write, read back, info as JSON") {
  ClothDatabase db = smallDatabase();
  std::filesystem::path path = scratch("small.tsc");
  writeClothDatabase(path, db);
  ClothDatabase back = readClothDatabase(path);
  CHECK(back.coefficients == db.coefficients);
  nlohmann::json info = clothCompressedInfo(path);
  CHECK(info["states"] == db.stateCount());
  CHECK(info["bases"] == 7);
  CHECK(info["compressed_bytes"] == std::filesystem::file_size(path));
  CHECK(info["raw_bytes"] == uint64_t(db.stateCount()) * db.vertexCount * 12);
  CHECK(info["max_reconstruction_error_m"].get<float>() == doctest::Approx(0.0012f));
  CHECK_THROWS_WITH_AS(readClothDatabase(scratch("missing.tsc")), doctest::Contains("cannot open"),
                       Error);
  std::filesystem::path text = scratch("text.tsc");
  writeTextFileAtomic(text, "this is not a cloth database");
  CHECK_THROWS_WITH_AS(clothCompressedInfo(text), doctest::Contains("not a compressed cloth"),
                       Error);
}

TEST_CASE(".tsc: a garbage entropy stream is an error, not a read past the model") {
  // The file: BENC replaced by eight 0xff bytes, checksum recomputed.
  const std::vector<uint8_t> bytes = encodeClothDatabase(smallDatabase());
  const std::vector<uint8_t> garbage =
      test::replacePayload(bytes, "BENC", std::vector<uint8_t>(8, 0xff));
  CHECK_THROWS_WITH_AS(decodeClothDatabase(garbage, "g.tsc"), doctest::Contains("g.tsc: "), Error);
}

TEST_CASE(".tsc: counts no other chunk backs are refused before anything is allocated") {
  const std::vector<uint8_t> bytes = encodeClothDatabase(smallDatabase());
  // 300 million vertices (and the largest count) in a file of a few kB: the mean's 3 floats a
  // vertex are not there, so the reader says so instead of allocating gigabytes.
  for (uint32_t vertices : {300000000u, 0xFFFFFFFFu}) {
    const std::vector<uint8_t> huge =
        test::replacePayload(bytes, "VERT", test::bytesOfValue(vertices));
    CHECK_THROWS_WITH_AS(decodeClothDatabase(huge, "g.tsc"),
                         doctest::Contains("g.tsc: chunk 'MEAN' holds"), Error);
  }
  // 100,000 basis headers (and steps) over the same short entropy streams: more values than the
  // streams' bytes can hold.
  std::vector<uint8_t> many = test::patchChunk(bytes, "BASH", [](test::RawChunk& c) {
    const std::vector<uint8_t> one(c.payload.begin(), c.payload.begin() + 16);
    c.payload.clear();
    for (int i = 0; i < 100000; ++i) c.payload.insert(c.payload.end(), one.begin(), one.end());
    c.count = 100000;
  });
  many = test::replacePayload(many, "CSTP", std::vector<uint8_t>(200000, 0));
  CHECK_THROWS_WITH_AS(decodeClothDatabase(many, "g.tsc"),
                       doctest::Contains("values claimed from an entropy-coded stream"), Error);
  // A bucket claiming 4 billion run frames (playback would allocate a table that long).
  const std::vector<uint8_t> frames = test::patchChunk(bytes, "FPBK", [](test::RawChunk& c) {
    std::vector<uint32_t> f(c.payload.begin(), c.payload.end());  // stored as u8
    f[1] = 4000000000u;
    c.type = uint32_t(ElementType::U32);
    c.elementBytes = 4;
    c.payload.assign(reinterpret_cast<const uint8_t*>(f.data()),
                     reinterpret_cast<const uint8_t*>(f.data() + f.size()));
  });
  CHECK_THROWS_WITH_AS(decodeClothDatabase(frames, "g.tsc"),
                       doctest::Contains("bucket 1 claims 4000000000 run frames"), Error);
}
