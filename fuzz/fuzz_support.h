#pragma once
// Shared by the libFuzzer harnesses. A parser answers bad input with throng::Error naming the
// file and what was expected; anything else is a finding: another exception type, an internal
// check (THRONG_CHECK) firing, and of course a crash, hang or unbounded allocation (which the
// sanitizers and libFuzzer's limits catch on their own).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "core/error.h"

namespace throng::fuzz {

// The bytes as a file, for readers that only take a path: an anonymous in-memory file
// (memfd) reached through /proc/self/fd, gone when this object is destroyed.
class MemoryFile {
 public:
  explicit MemoryFile(std::span<const uint8_t> bytes);
  ~MemoryFile();
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  int fd_ = -1;
  std::filesystem::path path_;
};

// Prints why the input is a finding and aborts (libFuzzer saves the input as a crash).
[[noreturn]] void finding(std::string_view what, std::string_view message);

// The exception's type as C++ spells it ("std::out_of_range").
std::string typeName(const std::exception& e);

// True for the message of a THRONG_CHECK: "<source dir>/engine/...:LINE: cond failed: ...".
bool isInternalCheck(std::string_view message);

// Runs `parse`; a throng::Error that is not an internal check is the expected answer to bad
// input, every other exception is a finding.
template <typename Body>
void expectParseOrError(Body&& parse) {
  try {
    parse();
  } catch (const Error& e) {
    if (isInternalCheck(e.what())) finding("internal check failed", e.what());
  } catch (const std::exception& e) {
    finding(typeName(e), e.what());
  }
}

inline std::string_view asText(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace throng::fuzz
