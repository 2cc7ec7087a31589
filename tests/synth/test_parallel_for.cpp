// synth::parallelFor, which the CPU twins run on: every index once, and an error in one range
// reaches the caller as an exception (an exception leaving a std::thread would end the process).
#include <doctest/doctest.h>

#include <atomic>
#include <vector>

#include "core/error.h"
#include "synth/cpu_synth.h"

using namespace throng;

TEST_CASE("parallelFor: every index once, on any number of threads") {
  for (unsigned threads : {1u, 2u, 3u, 16u}) {
    CAPTURE(threads);
    std::vector<std::atomic<int>> seen(1001);
    synth::parallelFor(seen.size(), threads, [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) ++seen[i];
    });
    size_t once = 0;
    for (const std::atomic<int>& s : seen) once += s == 1;
    CHECK(once == seen.size());
  }
}

TEST_CASE("parallelFor: an error in a worker's range is rethrown after every worker joined") {
  std::atomic<int> finished{0};
  CHECK_THROWS_WITH_AS(synth::parallelFor(100, 4,
                                          [&](size_t begin, size_t) {
                                            if (begin == 0) fail("the first range failed");
                                            ++finished;
                                          }),
                       "the first range failed", Error);
  CHECK(finished == 3);
}
