#pragma once
// A GLFW window for the viewer (no OpenGL context: Vulkan presents into it). Owns GLFW's
// lifetime, so one Window exists at a time. Without a display it throws a clear Error that
// points people at the headless `throng render`.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gpu/handle.h"

struct GLFWwindow;

namespace throng::render {

struct WindowOptions {
  uint32_t width = 1280, height = 720;
  std::string title = "throng view";
};

// Input as it arrives from GLFW (positions in window pixels, GLFW key and button codes).
struct WindowCallbacks {
  std::function<void(double x, double y)> cursor;
  std::function<void(int button, bool pressed)> mouseButton;
  std::function<void(double dy)> scroll;
  std::function<void(int key, bool pressed, bool repeat)> key;
};

// The message when no display can be opened (tests look for it).
constexpr const char* kNoDisplayHint = "set DISPLAY or use `throng render` for headless frames";

class Window {
 public:
  explicit Window(const WindowOptions& options);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  // What vkCreateInstance needs for this window's surface (VK_KHR_surface + the platform's).
  std::vector<std::string> requiredInstanceExtensions() const;
  gpu::Handle<VkSurfaceKHR> createSurface(VkInstance instance) const;

  // Framebuffer size in pixels; 0×0 while minimised.
  VkExtent2D framebufferSize() const;
  bool minimized() const;
  bool shouldClose() const;
  void requestClose();
  // Asks the window system for a new client size (applied asynchronously).
  void resize(uint32_t width, uint32_t height);
  void iconify();
  void setTitle(const std::string& title);

  void pollEvents();
  void waitEvents(double timeoutSeconds);

  // Installed before a UI library chains its own callbacks in front of them.
  void setCallbacks(WindowCallbacks callbacks);
  // True once after the framebuffer changed size.
  bool takeResized();

 private:
  GLFWwindow* window_ = nullptr;
  WindowCallbacks callbacks_;
  bool resized_ = false;

  static Window* from(GLFWwindow* window);
};

}  // namespace throng::render
