#pragma once
// One exception type for every user-facing failure: the message names the file, line or pixel
// and what was expected, so the command line can print it and exit non-zero.
#include <sstream>
#include <stdexcept>
#include <string>

namespace throng {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <typename... Args>
std::string concat(const Args&... args) {
  std::ostringstream out;
  (out << ... << args);
  return out.str();
}

template <typename... Args>
[[noreturn]] void fail(const Args&... args) {
  throw Error(concat(args...));
}

// Internal invariants that must hold in release builds too (never assert()).
#define THRONG_CHECK(cond, ...)                                                          \
  do {                                                                                   \
    if (!(cond)) ::throng::fail(__FILE__, ":", __LINE__, ": ", #cond, " failed: ", __VA_ARGS__); \
  } while (0)

}  // namespace throng
