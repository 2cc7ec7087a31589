#include "viewer/view_controls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "render/camera_control.h"

namespace throng::render {

void ViewControls::cursor(double x, double y) {
  if (haveCursor_ && dragButton_ >= 0) {
    float dx = float(x - x_), dy = float(y - y_);
    if (dragButton_ == GLFW_MOUSE_BUTTON_LEFT) {
      orbitX_ += dx;
      orbitY_ += dy;
    } else {
      panX_ += dx;
      panY_ += dy;
    }
  }
  x_ = x;
  y_ = y;
  haveCursor_ = true;
}

void ViewControls::button(int glfwButton, bool pressed, bool uiCaptured) {
  if (!pressed) {
    if (glfwButton == dragButton_) dragButton_ = -1;
    return;
  }
  // A drag that starts on the panel belongs to the panel until the button is released.
  if (uiCaptured || dragButton_ >= 0) return;
  if (glfwButton == GLFW_MOUSE_BUTTON_LEFT || glfwButton == GLFW_MOUSE_BUTTON_RIGHT ||
      glfwButton == GLFW_MOUSE_BUTTON_MIDDLE)
    dragButton_ = glfwButton;
}

void ViewControls::scroll(double steps, bool uiCaptured) {
  if (!uiCaptured) scroll_ += float(steps);
}

void ViewControls::key(int glfwKey, bool pressed, bool repeat, bool uiCaptured) {
  if (!pressed) {
    held_.erase(glfwKey);
    return;
  }
  if (uiCaptured) return;
  held_.insert(glfwKey);
  if (repeat) return;
  switch (glfwKey) {
    case GLFW_KEY_R:
      actions_.push_back(ViewAction::ResetCamera);
      break;
    case GLFW_KEY_1:
      actions_.push_back(ViewAction::PresetWide);
      break;
    case GLFW_KEY_2:
      actions_.push_back(ViewAction::PresetTop);
      break;
    case GLFW_KEY_3:
      actions_.push_back(ViewAction::PresetStreet);
      break;
    case GLFW_KEY_4:
      actions_.push_back(ViewAction::PresetCloseup);
      break;
    case GLFW_KEY_SPACE:
      actions_.push_back(ViewAction::TogglePause);
      break;
    case GLFW_KEY_N:
      actions_.push_back(ViewAction::Step);
      break;
    case GLFW_KEY_TAB:
    case GLFW_KEY_F1:
      actions_.push_back(ViewAction::TogglePanel);
      break;
    case GLFW_KEY_V:
      actions_.push_back(ViewAction::ToggleVsync);
      break;
    case GLFW_KEY_F12:
      actions_.push_back(ViewAction::Screenshot);
      break;
    case GLFW_KEY_ESCAPE:
      actions_.push_back(ViewAction::Quit);
      break;
    default:
      break;
  }
}

std::vector<ViewAction> ViewControls::update(Camera& camera, float seconds, float viewportHeight) {
  moved_ = false;
  if (orbitX_ != 0.0f || orbitY_ != 0.0f) {
    orbitCamera(camera, orbitX_, orbitY_);
    moved_ = true;
  }
  if (panX_ != 0.0f || panY_ != 0.0f) {
    panCamera(camera, panX_, panY_, viewportHeight);
    moved_ = true;
  }
  if (scroll_ != 0.0f) {
    zoomCamera(camera, scroll_);
    moved_ = true;
  }
  orbitX_ = orbitY_ = panX_ = panY_ = scroll_ = 0.0f;

  auto axis = [&](int negative, int positive) {
    return (held_.count(positive) ? 1.0f : 0.0f) - (held_.count(negative) ? 1.0f : 0.0f);
  };
  glm::vec3 axes(axis(GLFW_KEY_A, GLFW_KEY_D), axis(GLFW_KEY_Q, GLFW_KEY_E),
                 axis(GLFW_KEY_S, GLFW_KEY_W));
  if (axes != glm::vec3(0.0f) && seconds > 0.0f) {
    bool fast = held_.count(GLFW_KEY_LEFT_SHIFT) || held_.count(GLFW_KEY_RIGHT_SHIFT);
    flyCamera(camera, axes, seconds, fast ? 4.0f : 1.0f);
    moved_ = true;
  }
  std::vector<ViewAction> actions;
  actions.swap(actions_);
  return actions;
}

}  // namespace throng::render
