#pragma once
// Running the built `throng` binary from tests ($THRONG_BIN, set by ctest).
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <doctest/doctest.h>

namespace throng::test {

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

inline std::string throngBinary() {
  const char* bin = std::getenv("THRONG_BIN");
  return bin ? bin : (std::string(THRONG_BINARY_DIR) + "/bin/throng");
}

inline CommandResult runThrong(const std::string& arguments) {
  CommandResult result;
  std::string command = "LP_NUM_THREADS=2 " + throngBinary() + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// A fresh empty directory under the build tree for one test.
inline std::filesystem::path freshDirectory(const std::string& name) {
  std::filesystem::path dir = std::filesystem::path(THRONG_BINARY_DIR) / "test_output" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace throng::test
