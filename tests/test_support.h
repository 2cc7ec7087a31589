#pragma once
// Helpers shared by the test suites: where the third-party data lives, and how to skip
// clearly when it is absent.
#include <filesystem>
#include <string>

#include <doctest/doctest.h>

namespace throng::test {

inline std::filesystem::path sharedDataDir() { return THRONG_SHARED_DATA_DIR; }
inline std::filesystem::path sourceDir() { return THRONG_SOURCE_DIR; }
inline std::filesystem::path binaryDir() { return THRONG_BINARY_DIR; }

// True when ../shared/data/<relative> exists; otherwise prints why the check is skipped.
inline bool haveSharedData(const std::string& relative) {
  if (std::filesystem::exists(sharedDataDir() / relative)) return true;
  MESSAGE("SKIPPED: ", (sharedDataDir() / relative).string(),
          " is absent (third-party data lives in ../shared/data beside the repository)");
  return false;
}

}  // namespace throng::test
