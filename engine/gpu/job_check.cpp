#include "gpu/job_check.h"

#include "core/error.h"

namespace throng::gpu {

void throwIfInvalid(const std::string& job, const std::vector<std::string>& problems) {
  if (problems.empty()) return;
  std::string message = job + " is invalid:";
  for (const std::string& p : problems) message += "\n  - " + p;
  throw Error(message);
}

}  // namespace throng::gpu
