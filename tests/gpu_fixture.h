#pragma once
// One Vulkan context per test executable (lavapipe in CI), validation always on; tests check
// validationMessageCount() stays zero.
#include "gpu/context.h"

namespace throng::test {
inline gpu::Context& gpuContext() {
  static gpu::Context context([] {
    gpu::ContextOptions options;
    options.validation = true;
    options.quiet = true;
    return options;
  }());
  return context;
}
}  // namespace throng::test
