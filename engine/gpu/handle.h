#pragma once
// Move-only ownership of one Vulkan handle plus the function that destroys it.
#include <functional>
#include <utility>

#include <volk.h>

namespace throng::gpu {

template <typename T>
class Handle {
 public:
  Handle() = default;
  Handle(T handle, std::function<void(T)> destroy) : handle_(handle), destroy_(std::move(destroy)) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept { *this = std::move(other); }
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
      destroy_ = std::move(other.destroy_);
    }
    return *this;
  }
  ~Handle() { reset(); }

  void reset() {
    if (handle_ != VK_NULL_HANDLE && destroy_) destroy_(handle_);
    handle_ = VK_NULL_HANDLE;
  }
  T get() const { return handle_; }
  operator T() const { return handle_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

 private:
  T handle_ = VK_NULL_HANDLE;
  std::function<void(T)> destroy_;
};

}  // namespace throng::gpu
