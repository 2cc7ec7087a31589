// The one check every GPU job's record() runs on its validate() problems.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "gpu/job_check.h"

TEST_CASE("throwIfInvalid names the job and lists every problem, and passes a valid job") {
  CHECK_NOTHROW(throng::gpu::throwIfInvalid("PoseJob", {}));
  try {
    throng::gpu::throwIfInvalid("PoseJob", {"no motion buffer", "joint count 0"});
    FAIL("expected an error");
  } catch (const throng::Error& e) {
    CHECK(std::string(e.what()) == "PoseJob is invalid:\n  - no motion buffer\n  - joint count 0");
  }
}
