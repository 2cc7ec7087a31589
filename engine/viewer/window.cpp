#include "viewer/window.h"

#include <algorithm>
#include <cstdlib>

// volk (through gpu/handle.h) has declared the Vulkan types, so GLFW exposes its Vulkan helpers.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/error.h"
#include "gpu/vk_check.h"

namespace throng::render {
namespace {

std::string& lastGlfwError() {
  static std::string message;
  return message;
}

void onGlfwError(int code, const char* description) {
  lastGlfwError() = concat(description ? description : "unknown error", " (GLFW error ", code, ")");
}

std::string envOrEmpty(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

}  // namespace

Window::Window(const WindowOptions& options) {
  // GLFW would print its own error and fail later; say what is wrong and what to do instead.
  const std::string display = envOrEmpty("DISPLAY");
  if (display.empty() && envOrEmpty("WAYLAND_DISPLAY").empty())
    fail("no display: ", kNoDisplayHint);
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit())
    fail("no display: cannot open display '", display, "': ", lastGlfwError(), "; ",
         kNoDisplayHint);
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    fail("GLFW cannot present with Vulkan on this display (", lastGlfwError(),
         "); use `throng render`");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(static_cast<int>(options.width), static_cast<int>(options.height),
                             options.title.c_str(), nullptr, nullptr);
  if (!window_) {
    std::string why = lastGlfwError();
    glfwTerminate();
    fail("cannot create a ", options.width, "x", options.height, " window: ", why);
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetFramebufferSizeCallback(window_,
                                 [](GLFWwindow* w, int, int) { from(w)->resized_ = true; });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    if (auto& f = from(w)->callbacks_.cursor) f(x, y);
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    if (auto& f = from(w)->callbacks_.mouseButton) f(button, action == GLFW_PRESS);
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
    if (auto& f = from(w)->callbacks_.scroll) f(dy);
  });
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (auto& f = from(w)->callbacks_.key) f(key, action != GLFW_RELEASE, action == GLFW_REPEAT);
  });
}

Window::~Window() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

Window* Window::from(GLFWwindow* window) {
  return static_cast<Window*>(glfwGetWindowUserPointer(window));
}

std::vector<std::string> Window::requiredInstanceExtensions() const {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) fail("GLFW reports no Vulkan surface extensions: ", lastGlfwError());
  return {names, names + count};
}

gpu::Handle<VkSurfaceKHR> Window::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VK_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
  return gpu::Handle<VkSurfaceKHR>(
      surface, [instance](VkSurfaceKHR s) { vkDestroySurfaceKHR(instance, s, nullptr); });
}

VkExtent2D Window::framebufferSize() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {static_cast<uint32_t>(std::max(w, 0)), static_cast<uint32_t>(std::max(h, 0))};
}

bool Window::minimized() const {
  VkExtent2D size = framebufferSize();
  return size.width == 0 || size.height == 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED);
}

bool Window::shouldClose() const {
  return glfwWindowShouldClose(window_);
}
void Window::requestClose() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void Window::resize(uint32_t width, uint32_t height) {
  glfwSetWindowSize(window_, static_cast<int>(width), static_cast<int>(height));
}

void Window::iconify() {
  glfwIconifyWindow(window_);
}
void Window::setTitle(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}
void Window::pollEvents() {
  glfwPollEvents();
}
void Window::waitEvents(double timeoutSeconds) {
  glfwWaitEventsTimeout(timeoutSeconds);
}
void Window::setCallbacks(WindowCallbacks callbacks) {
  callbacks_ = std::move(callbacks);
}

bool Window::takeResized() {
  bool r = resized_;
  resized_ = false;
  return r;
}

}  // namespace throng::render
