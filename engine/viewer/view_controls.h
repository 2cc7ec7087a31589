#pragma once
// The viewer's mouse and keyboard bindings, independent of where events come from (GLFW
// callbacks or an input script): drags orbit (left) or pan (right, middle), the wheel zooms,
// held W/A/S/D/Q/E fly (Shift: faster), and single presses become actions.
#include <set>
#include <vector>

#include "render/camera.h"

namespace throng::render {

enum class ViewAction {
  ResetCamera,    // R
  PresetWide,     // 1
  PresetTop,      // 2
  PresetStreet,   // 3
  PresetCloseup,  // 4
  TogglePause,    // Space
  Step,           // N (one frame while paused)
  TogglePanel,    // Tab or F1
  ToggleVsync,    // V
  Screenshot,     // F12
  Quit,           // Escape
};

class ViewControls {
 public:
  // `uiCaptured`: the panel wants this event (it is then ignored, except releases).
  void cursor(double x, double y);
  void button(int glfwButton, bool pressed, bool uiCaptured);
  void scroll(double steps, bool uiCaptured);
  void key(int glfwKey, bool pressed, bool repeat, bool uiCaptured);

  // Applies the moves gathered since the last call to `camera` (flight over `seconds`) and
  // returns the actions pressed meanwhile, in order.
  std::vector<ViewAction> update(Camera& camera, float seconds, float viewportHeight);

  bool dragging() const { return dragButton_ >= 0; }
  // Whether the camera moved in the last update (for "camera changed" statistics).
  bool cameraMoved() const { return moved_; }

 private:
  double x_ = 0.0, y_ = 0.0;
  bool haveCursor_ = false;
  int dragButton_ = -1;
  float orbitX_ = 0.0f, orbitY_ = 0.0f, panX_ = 0.0f, panY_ = 0.0f, scroll_ = 0.0f;
  std::set<int> held_;
  std::vector<ViewAction> actions_;
  bool moved_ = false;
};

}  // namespace throng::render
