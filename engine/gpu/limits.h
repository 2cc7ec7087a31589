#pragma once
// Device limits, checked before a Vulkan object is created, bound or dispatched: going past one
// is undefined behaviour (a validation error at best), so the engine throws LimitError instead.
// The tools catch it and name the option that asked for too much (-n, --size, resize, ...).
#include <cstdint>
#include <string>

#include "core/error.h"

namespace throng::gpu {

class Context;

class LimitError : public Error {
 public:
  // "<what> needs <needed> <unit>, more than <device>'s <limit> of <allowed> <unit>"
  LimitError(const std::string& what, const std::string& limit, uint64_t needed, uint64_t allowed,
             const std::string& unit, const std::string& device);
  const std::string& limit() const { return limit_; }
  uint64_t needed() const { return needed_; }
  uint64_t allowed() const { return allowed_; }

 private:
  std::string limit_;
  uint64_t needed_ = 0, allowed_ = 0;
};

// Throws LimitError when needed > allowed.
void checkLimit(const Context& context, const std::string& what, const std::string& limit,
                uint64_t needed, uint64_t allowed, const std::string& unit = "bytes");

// Width and height of an image against maxImageDimension2D, and, for an attachment, against
// maxFramebufferWidth/Height.
void checkImageSize(const Context& context, const std::string& what, uint32_t width,
                    uint32_t height, bool attachment);

}  // namespace throng::gpu
