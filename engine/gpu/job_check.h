#pragma once
// Every GPU job's validate() returns its problems; record() refuses to run with any.
#include <string>
#include <vector>

namespace throng::gpu {

// Throws Error "<job> is invalid:" followed by every problem, one a line; nothing when there
// are none.
void throwIfInvalid(const std::string& job, const std::vector<std::string>& problems);

}  // namespace throng::gpu
