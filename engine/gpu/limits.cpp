#include "gpu/limits.h"

#include "gpu/context.h"

namespace throng::gpu {

LimitError::LimitError(const std::string& what, const std::string& limit, uint64_t needed,
                       uint64_t allowed, const std::string& unit, const std::string& device)
    : Error(concat(what, " needs ", needed, " ", unit, ", more than ", device, "'s ", limit, " of ",
                   allowed, " ", unit)),
      limit_(limit),
      needed_(needed),
      allowed_(allowed) {}

void checkLimit(const Context& context, const std::string& what, const std::string& limit,
                uint64_t needed, uint64_t allowed, const std::string& unit) {
  if (needed > allowed) throw LimitError(what, limit, needed, allowed, unit, context.info().name);
}

void checkImageSize(const Context& context, const std::string& what, uint32_t width,
                    uint32_t height, bool attachment) {
  const DeviceInfo& info = context.info();
  checkLimit(context, concat(what, " width"), "maxImageDimension2D", width,
             info.maxImageDimension2D, "pixels");
  checkLimit(context, concat(what, " height"), "maxImageDimension2D", height,
             info.maxImageDimension2D, "pixels");
  if (!attachment) return;
  checkLimit(context, concat(what, " width"), "maxFramebufferWidth", width,
             info.maxFramebufferWidth, "pixels");
  checkLimit(context, concat(what, " height"), "maxFramebufferHeight", height,
             info.maxFramebufferHeight, "pixels");
}

}  // namespace throng::gpu
