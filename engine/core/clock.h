#pragma once
// Wall-clock intervals for the figures the tools print (frame loops, encoders, CPU twins).
#include <chrono>

namespace throng {

// Milliseconds of steady-clock time since `start`.
inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace throng
