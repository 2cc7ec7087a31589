#pragma once
// Device limits in the tools' words: a gpu::LimitError thrown while a step runs becomes an Error
// that starts with the option (or script command) that asked for too much, e.g.
// "-n 1350000: joint_splat.comp binding 4 needs 135000000 bytes, more than llvmpipe's
// maxStorageBufferRange of 134217728 bytes".
#include <string>
#include <utility>

#include "core/error.h"
#include "gpu/limits.h"

namespace throng::tools {

template <typename Step>
decltype(auto) namingOption(const std::string& option, Step&& step) {
  try {
    return std::forward<Step>(step)();
  } catch (const gpu::LimitError& e) {
    fail(option, ": ", e.what());
  }
}

}  // namespace throng::tools
