// The one atomic write: whole file or nothing, under the final name only once complete.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "core/file_io.h"
#include "test_support.h"

using namespace throng;
namespace fs = std::filesystem;

namespace {
fs::path freshDir(const std::string& name) {
  const fs::path dir = test::binaryDir() / "test_output" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

size_t entryCount(const fs::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}
}  // namespace

TEST_CASE("writeFileAtomic streams every piece into the file and leaves no temporary") {
  const fs::path dir = freshDir("file_io_stream");
  const fs::path path = dir / "out.bin";
  writeFileAtomic(path, [](const ByteSink& sink) {
    const uint8_t a[] = {1, 2, 3};
    const uint8_t b[] = {4, 5};
    sink(a, sizeof a);
    sink(b, sizeof b);
  });
  CHECK(readTextFile(path) == std::string("\x01\x02\x03\x04\x05", 5));
  CHECK(entryCount(dir) == 1);
}

TEST_CASE("a producer that throws leaves the old file as it was and no temporary") {
  const fs::path dir = freshDir("file_io_throw");
  const fs::path path = dir / "out.txt";
  writeTextFileAtomic(path, "old");
  CHECK_THROWS_AS(writeFileAtomic(path,
                                  [](const ByteSink& sink) {
                                    const uint8_t half[] = {'n', 'e'};
                                    sink(half, sizeof half);
                                    throw std::runtime_error("producer failed");
                                  }),
                  std::runtime_error);
  CHECK(readTextFile(path) == "old");
  CHECK(entryCount(dir) == 1);
}

TEST_CASE("writing into a missing directory names the path") {
  const fs::path path = freshDir("file_io_missing") / "no" / "out.txt";
  try {
    writeTextFileAtomic(path, "x");
    FAIL("expected an error");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find(path.string()) != std::string::npos);
  }
}

TEST_CASE("commitTemporaryFile moves another writer's temporary into place") {
  const fs::path dir = freshDir("file_io_commit");
  const fs::path path = dir / "plot.png";
  const fs::path temporary = temporaryPathFor(path, ".png");
  CHECK(temporary.parent_path() == dir);
  CHECK(temporary.filename().string().starts_with("plot.png.tmp-"));
  std::ofstream(temporary) << "drawn";
  commitTemporaryFile(temporary, path);
  CHECK(readTextFile(path) == "drawn");
  CHECK(entryCount(dir) == 1);
  // A temporary that is not there: an error naming the output, nothing created.
  CHECK_THROWS_AS(commitTemporaryFile(temporary, dir / "other.png"), Error);
  CHECK(!fs::exists(dir / "other.png"));
}
