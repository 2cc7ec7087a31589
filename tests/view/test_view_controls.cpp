// Mouse and keyboard bindings: which drag does what, what the panel swallows, held keys fly,
// presses become actions once (not on repeat).
#include <doctest/doctest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "render/camera_control.h"
#include "viewer/view_controls.h"

using namespace throng;
using render::Camera;
using render::ViewAction;

namespace {
Camera sample() {
  Camera c;
  c.eye = {0.0f, 30.0f, -40.0f};
  c.target = {0.0f, 0.0f, 0.0f};
  return c;
}
void drag(render::ViewControls& controls, int button, double dx, double dy,
          bool uiCaptured = false) {
  controls.cursor(300.0, 200.0);
  controls.button(button, true, uiCaptured);
  controls.cursor(300.0 + dx, 200.0 + dy);
  controls.button(button, false, uiCaptured);
}
}  // namespace

TEST_CASE("controls: nothing happened, nothing moves (bit-identical camera)") {
  render::ViewControls controls;
  Camera c = sample();
  controls.cursor(10, 10);
  controls.cursor(50, 80);  // moving without a button is not a drag
  CHECK(controls.update(c, 0.1f, 720.0f).empty());
  CHECK(c.eye == sample().eye);
  CHECK(c.target == sample().target);
  CHECK_FALSE(controls.cameraMoved());
}

TEST_CASE("controls: left drag orbits, right and middle drags pan") {
  render::ViewControls controls;
  Camera c = sample();
  drag(controls, GLFW_MOUSE_BUTTON_LEFT, 50, 0);
  controls.update(c, 0.0f, 720.0f);
  CHECK(controls.cameraMoved());
  CHECK(c.target == sample().target);
  CHECK(render::cameraDistance(c) ==
        doctest::Approx(render::cameraDistance(sample())).epsilon(1e-5));
  CHECK(glm::length(c.eye - sample().eye) > 1.0f);

  for (int button : {GLFW_MOUSE_BUTTON_RIGHT, GLFW_MOUSE_BUTTON_MIDDLE}) {
    Camera p = sample();
    drag(controls, button, 40, 0);
    controls.update(p, 0.0f, 720.0f);
    CHECK(glm::length(p.target - sample().target) > 0.1f);
    CHECK(glm::length((p.eye - sample().eye) - (p.target - sample().target)) < 1e-4f);
  }
}

TEST_CASE("controls: a drag that starts on the panel belongs to the panel") {
  render::ViewControls controls;
  Camera c = sample();
  drag(controls, GLFW_MOUSE_BUTTON_LEFT, 80, 30, /*uiCaptured=*/true);
  controls.scroll(3.0, true);
  controls.key(GLFW_KEY_R, true, false, true);
  CHECK(controls.update(c, 0.1f, 720.0f).empty());
  CHECK(c.eye == sample().eye);
}

TEST_CASE("controls: the wheel zooms, held WASDQE fly until released") {
  render::ViewControls controls;
  Camera c = sample();
  controls.scroll(1.0, false);
  controls.update(c, 0.0f, 720.0f);
  CHECK(render::cameraDistance(c) ==
        doctest::Approx(render::cameraDistance(sample()) * render::kZoomPerStep));

  Camera f = sample();
  controls.key(GLFW_KEY_W, true, false, false);
  controls.update(f, 0.5f, 720.0f);
  glm::vec3 moved = f.eye - sample().eye;
  CHECK(glm::length(moved) == doctest::Approx(0.5f * render::flySpeed(sample())).epsilon(1e-4));
  controls.update(f, 0.5f, 720.0f);  // still held
  CHECK(glm::length(f.eye - sample().eye) ==
        doctest::Approx(2.0f * glm::length(moved)).epsilon(1e-3));
  controls.key(GLFW_KEY_W, false, false, false);
  glm::vec3 stopped = f.eye;
  controls.update(f, 0.5f, 720.0f);
  CHECK(f.eye == stopped);

  Camera e = sample();
  controls.key(GLFW_KEY_E, true, false, false);
  controls.key(GLFW_KEY_LEFT_SHIFT, true, false, false);
  controls.update(e, 0.25f, 720.0f);
  CHECK(e.eye.y - sample().eye.y ==
        doctest::Approx(4.0f * 0.25f * render::flySpeed(sample())).epsilon(1e-4));
}

TEST_CASE("controls: key presses become actions once, in order") {
  render::ViewControls controls;
  Camera c = sample();
  const int keys[] = {GLFW_KEY_R,     GLFW_KEY_1,      GLFW_KEY_2,   GLFW_KEY_3,  GLFW_KEY_4,
                      GLFW_KEY_SPACE, GLFW_KEY_N,      GLFW_KEY_TAB, GLFW_KEY_F1, GLFW_KEY_V,
                      GLFW_KEY_F12,   GLFW_KEY_ESCAPE, GLFW_KEY_X};
  for (int key : keys) {
    controls.key(key, true, false, false);
    controls.key(key, true, true, false);  // auto-repeat adds nothing
    controls.key(key, false, false, false);
  }
  std::vector<ViewAction> expected = {
      ViewAction::ResetCamera,  ViewAction::PresetWide,    ViewAction::PresetTop,
      ViewAction::PresetStreet, ViewAction::PresetCloseup, ViewAction::TogglePause,
      ViewAction::Step,         ViewAction::TogglePanel,   ViewAction::TogglePanel,
      ViewAction::ToggleVsync,  ViewAction::Screenshot,    ViewAction::Quit};
  CHECK(controls.update(c, 0.0f, 720.0f) == expected);
  CHECK(controls.update(c, 0.0f, 720.0f).empty());
}
