// binary_io: typed chunks round trip; truncated, corrupted, foreign and future files give
// errors that say so.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/binary_io.h"
#include "core/error.h"
#include "test_support.h"

using namespace throng;

namespace {
constexpr std::string_view kMagic = "THRNGTST";

struct Record {
  uint32_t a;
  float b;
};

ChunkWriter sampleWriter(const std::vector<glm::vec3>& big) {
  ChunkWriter w(kMagic, 2);
  w.addScalar("ONE_", uint32_t(42));
  w.add("FLTS", std::vector<float>{1.5f, -2.0f, 3.25f});
  w.addString("TEXT", "hello, chunks");
  w.add("RECS", std::vector<Record>{{1, 0.5f}, {2, 0.25f}});
  w.addView("VEC3", std::span<const glm::vec3>(big));
  w.add("EMPT", std::vector<uint8_t>{});
  return w;
}

std::string errorOf(std::vector<uint8_t> bytes, uint32_t maxVersion = 2) {
  try {
    ChunkReader::fromBytes(std::move(bytes), "sample.bin", kMagic, maxVersion, "test");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}
}  // namespace

TEST_CASE("crc32Ieee matches the standard check value and continues across calls") {
  const std::string text = "123456789";
  const std::span<const uint8_t> bytes(reinterpret_cast<const uint8_t*>(text.data()), text.size());
  CHECK(crc32Ieee(bytes) == 0xCBF43926u);
  CHECK(crc32Ieee(bytes.subspan(4), crc32Ieee(bytes.first(4))) == 0xCBF43926u);
}

TEST_CASE("chunks round trip with their types, in memory and through a file") {
  std::vector<glm::vec3> big(1000);
  for (size_t i = 0; i < big.size(); ++i) big[i] = glm::vec3(float(i), -float(i), 0.5f * float(i));
  const ChunkWriter w = sampleWriter(big);
  const std::vector<uint8_t> bytes = w.bytes();
  CHECK(bytes.size() == w.totalBytes());
  CHECK(bytes.size() % 8 == 0);

  auto check = [&](const ChunkReader& r) {
    CHECK(r.version() == 2);
    CHECK(r.scalar<uint32_t>("ONE_") == 42);
    CHECK(r.vector<float>("FLTS") == std::vector<float>{1.5f, -2.0f, 3.25f});
    CHECK(r.string("TEXT") == "hello, chunks");
    const std::vector<Record> recs = r.vector<Record>("RECS");
    REQUIRE(recs.size() == 2);
    CHECK(recs[1].a == 2);
    CHECK(recs[1].b == 0.25f);
    CHECK(r.vector<glm::vec3>("VEC3") == big);
    CHECK(r.vector<uint8_t>("EMPT").empty());
    CHECK_FALSE(r.has("NONE"));
  };
  check(ChunkReader::fromBytes(bytes, "memory", kMagic, 2, "test"));

  const auto path = test::binaryDir() / "test_output" / "binary_io_roundtrip.bin";
  std::filesystem::create_directories(path.parent_path());
  w.writeFileAtomic(path);
  CHECK(std::filesystem::file_size(path) == bytes.size());
  CHECK(readMagic(path) == kMagic);
  check(ChunkReader::openFile(path, kMagic, 2, "test"));
}

TEST_CASE("type, count and tag mistakes are reported by chunk") {
  std::vector<glm::vec3> big(4);
  const ChunkReader r =
      ChunkReader::fromBytes(sampleWriter(big).bytes(), "sample.bin", kMagic, 2, "test");
  CHECK_THROWS_WITH_AS(
      r.vector<uint32_t>("FLTS"),
      doctest::Contains("chunk 'FLTS': expected u32 elements of 4 bytes, found f32"), Error);
  CHECK_THROWS_WITH_AS(r.vector<float>("MISS"), doctest::Contains("missing chunk 'MISS'"), Error);
  CHECK_THROWS_WITH_AS(r.scalar<float>("FLTS"), doctest::Contains("holds 3 elements, expected 1"),
                       Error);
  ChunkWriter w(kMagic, 1);
  w.addScalar("SAME", 1.0f);
  CHECK_THROWS_AS(w.addScalar("SAME", 2.0f), Error);
  CHECK_THROWS_AS(w.addScalar("TOOLONG", 2.0f), Error);
  CHECK_THROWS_AS(ChunkWriter("SHORT", 1), Error);
}

TEST_CASE("truncated, corrupted, foreign and newer files give clear errors") {
  std::vector<glm::vec3> big(100, glm::vec3(1.0f));
  const std::vector<uint8_t> good = sampleWriter(big).bytes();
  CHECK(errorOf(good).empty());

  for (size_t keep : {size_t(0), size_t(5), size_t(20), good.size() / 2, good.size() - 1}) {
    CAPTURE(keep);
    const std::string e =
        errorOf(std::vector<uint8_t>(good.begin(), good.begin() + ptrdiff_t(keep)));
    CHECK(contains(e, concat("sample.bin: truncated at byte ", keep, ", expected")));
  }
  std::vector<uint8_t> longer = good;
  longer.push_back(0);
  CHECK(contains(errorOf(longer), "unexpected bytes after the end"));

  for (size_t at : {size_t(40), good.size() / 2, good.size() - 12}) {
    std::vector<uint8_t> bad = good;
    bad[at] ^= 0x10;
    CAPTURE(at);
    CHECK(contains(errorOf(bad), "checksum mismatch"));
  }

  std::vector<uint8_t> foreign = good;
  std::memcpy(foreign.data(), "PNGXXXXX", 8);
  CHECK(contains(errorOf(foreign), "not a test file (magic 'PNGXXXXX', expected 'THRNGTST')"));
  CHECK(
      contains(errorOf(good, 1), "test version 2 unsupported (this build reads versions 1 to 1)"));
}

TEST_CASE("stale temporaries of an output: dead writers' removed, live writers' and others' kept") {
  const std::filesystem::path dir = test::binaryDir() / "test_secondary_stale_temporaries";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path out = dir / "g.tsg";
  auto touch = [&](const std::string& name) {
    std::ofstream(dir / name) << "partial";
    return dir / name;
  };
  const auto dead = touch("g.tsg.tmp-999999999");  // above any pid_max: no such process
  const auto own = touch("g.tsg.tmp-" + std::to_string(::getpid()));
  const auto live = touch("g.tsg.tmp-1");  // init runs
  const auto other = touch("other.tsg.tmp-999999999");
  const auto notPid = touch("g.tsg.tmp-12ab");
  const std::vector<std::filesystem::path> removed = removeStaleTemporaries(out);
  CHECK(removed.size() == 2);
  CHECK_FALSE(std::filesystem::exists(dead));
  CHECK_FALSE(std::filesystem::exists(own));
  CHECK(std::filesystem::exists(live));
  CHECK(std::filesystem::exists(other));
  CHECK(std::filesystem::exists(notPid));
  CHECK(removeStaleTemporaries(dir / "missing-dir" / "g.tsg").empty());
}

TEST_CASE("an output path is checked before the work: a directory is refused by name") {
  const std::filesystem::path dir = test::binaryDir() / "test_secondary_output_path";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "existing");
  const std::string expected =
      "--out " + (dir / "existing").string() + ": is a directory, expected a file to write";
  CHECK_THROWS_WITH_AS(prepareOutputFile(dir / "existing", "--out"),
                       doctest::Contains(expected.c_str()), Error);
  CHECK_THROWS_WITH_AS(prepareOutputFile("", "--out"), doctest::Contains("--out"), Error);
  std::ofstream(dir / "g.tsc.tmp-999999999") << "partial";
  CHECK(prepareOutputFile(dir / "g.tsc", "--out").size() == 1);
  CHECK(prepareOutputFile(dir / "new" / "g.tsc", "--out").empty());  // the folder is made
  CHECK(std::filesystem::is_directory(dir / "new"));
}
