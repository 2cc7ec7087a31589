// Input scripts: each command's frames and events, and errors that name the line.
#include <doctest/doctest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/error.h"
#include "viewer/input_script.h"

using namespace throng;
using render::ScriptEvent;
using Kind = ScriptEvent::Kind;

TEST_CASE("input script: drag presses, moves linearly and releases") {
  render::InputScript s = render::parseInputScript("drag 10 20 110 70 4 right\n", "t");
  REQUIRE(s.frames.size() == 5);
  REQUIRE(s.frames[0].size() == 2);
  CHECK(s.frames[0][0].kind == Kind::Cursor);
  CHECK(s.frames[0][0].x == 10.0);
  CHECK(s.frames[0][1].kind == Kind::Button);
  CHECK(s.frames[0][1].code == GLFW_MOUSE_BUTTON_RIGHT);
  CHECK(s.frames[0][1].pressed);
  CHECK(s.frames[2][0].x == doctest::Approx(60.0));
  CHECK(s.frames[2][0].y == doctest::Approx(45.0));
  REQUIRE(s.frames[4].size() == 2);
  CHECK(s.frames[4][0].x == doctest::Approx(110.0));
  CHECK(s.frames[4][1].kind == Kind::Button);
  CHECK_FALSE(s.frames[4][1].pressed);
}

TEST_CASE("input script: defaults, keys, waits, scroll, resize, close and comments") {
  render::InputScript s = render::parseInputScript(
      "# a comment\n\ndrag 0 0 10 0\r\nkey w 3  # held for 3 frames\nwait 2\nscroll -1.5\nresize "
      "640 480\nclose\n"
      "respawn 500 circle\nrespawn 20\n",
      "t");
  // drag: 1 + 10 frames; key: 1 + 3; wait 2; scroll, resize, close, respawn 1 each.
  CHECK(s.frames.size() == 11 + 4 + 2 + 5);
  CHECK(s.frames[0][1].code == GLFW_MOUSE_BUTTON_LEFT);
  CHECK(s.frames[11][0].kind == Kind::Key);
  CHECK(s.frames[11][0].code == GLFW_KEY_W);
  CHECK(s.frames[11][0].pressed);
  CHECK(s.frames[14][0].kind == Kind::Key);
  CHECK_FALSE(s.frames[14][0].pressed);
  CHECK(s.frames[15].empty());
  CHECK(s.frames[17][0].kind == Kind::Scroll);
  CHECK(s.frames[17][0].x == -1.5);
  CHECK(s.frames[18][0].kind == Kind::Resize);
  CHECK(s.frames[18][0].y == 480.0);
  CHECK(s.frames[19][0].kind == Kind::Close);
  CHECK(s.frames[20][0].kind == Kind::Respawn);
  CHECK(s.frames[20][0].x == 500.0);
  CHECK(s.frames[20][0].text == "circle");
  CHECK(s.frames[21][0].text.empty());
}

TEST_CASE("input script: resize and respawn remember their line for later errors") {
  render::InputScript script =
      render::parseInputScript("wait 1\nresize 640 480\n\nrespawn 20\n", "s.txt");
  REQUIRE(script.frames.size() == 3);
  CHECK(script.frames[1][0].where == "s.txt:2");
  CHECK(script.frames[2][0].where == "s.txt:4");
  // Off-window drags within the bound are kept as given.
  script = render::parseInputScript("drag -5000 2 99999 4 1\n", "s.txt");
  CHECK(script.frames[1][0].x == 99999.0);
}

TEST_CASE("input script: lod and cache switch the panel's checkboxes, one frame each") {
  render::InputScript s =
      render::parseInputScript("lod off\ncache on  # a comment\nwait 1\nlod\tOn\ncache OFF\n", "t");
  REQUIRE(s.frames.size() == 5);
  REQUIRE(s.frames[0].size() == 1);
  CHECK(s.frames[0][0].kind == Kind::Lod);
  CHECK_FALSE(s.frames[0][0].pressed);
  CHECK(s.frames[1][0].kind == Kind::Cache);
  CHECK(s.frames[1][0].pressed);
  CHECK(s.frames[2].empty());
  // The values are not case-sensitive (as mouse button names).
  CHECK(s.frames[3][0].kind == Kind::Lod);
  CHECK(s.frames[3][0].pressed);
  CHECK(s.frames[4][0].kind == Kind::Cache);
  CHECK_FALSE(s.frames[4][0].pressed);
}

TEST_CASE("input script: key names") {
  CHECK(render::keyCodeFromName("a") == GLFW_KEY_A);
  CHECK(render::keyCodeFromName("7") == GLFW_KEY_7);
  CHECK(render::keyCodeFromName("F12") == GLFW_KEY_F12);
  CHECK(render::keyCodeFromName("space") == GLFW_KEY_SPACE);
  CHECK(render::keyCodeFromName("Esc") == GLFW_KEY_ESCAPE);
  CHECK(render::keyCodeFromName("F13") == -1);
  CHECK(render::keyCodeFromName("F") == GLFW_KEY_F);
  CHECK(render::keyCodeFromName("hyper") == -1);
}

TEST_CASE("input script: errors name the file, the line and what was expected") {
  struct Case {
    const char* text;
    const char* message;
  };
  const Case cases[] = {
      {"wait 1\nfly 3\n", "s.txt:2: unknown command 'fly'"},
      {"wait\n", "s.txt:1: expected a frame count"},
      {"wait 0\n", "s.txt:1: expected a frame count in 1..100000, got '0'"},
      {"wait 2.5\n", "s.txt:1: expected a frame count in 1..100000, got '2.5'"},
      {"drag 1 2 3\n", "s.txt:1: expected Y1"},
      {"drag 1 2 3 x\n", "s.txt:1: expected Y1, got 'x'"},
      {"drag 1 2 3 4 5 sideways\n",
       "s.txt:1: expected a mouse button (left, right or middle), got 'sideways'"},
      {"key HYPER\n", "s.txt:1: unknown key 'HYPER'"},
      {"key W 2 extra\n", "s.txt:1: unexpected 'extra'"},
      {"resize 0 10\n", "s.txt:1: expected a width in 1..16384, got '0'"},
      {"scroll nan\n", "s.txt:1: expected wheel steps, got 'nan'"},
      {"respawn 0\n", "s.txt:1: expected a character count in 1..4000000, got '0'"},
      {"respawn 10 circle extra\n", "s.txt:1: unexpected 'extra'"},
      {"wait 1\nlod\n", "s.txt:2: expected 'on' or 'off' after 'lod'"},
      {"lod yes\n", "s.txt:1: expected 'on' or 'off' after 'lod', got 'yes'"},
      {"lod 1\n", "s.txt:1: expected 'on' or 'off' after 'lod', got '1'"},
      {"lod on off\n", "s.txt:1: unexpected 'off' at the end of the line"},
      {"cache\n", "s.txt:1: expected 'on' or 'off' after 'cache'"},
      {"cache onn\n", "s.txt:1: expected 'on' or 'off' after 'cache', got 'onn'"},
      {"cache off 3\n", "s.txt:1: unexpected '3' at the end of the line"},
      // Finite but absurd values would overflow the camera's floats.
      {"wait 1\ndrag 1e308 2 3 4\n", "s.txt:2: expected X0 in -100000..100000, got '1e308'"},
      {"drag 1 2 3 -2e5\n", "s.txt:1: expected Y1 in -100000..100000, got '-2e5'"},
      {"drag inf 2 3 4\n", "s.txt:1: expected X0, got 'inf'"},
      {"scroll 1e30\n", "s.txt:1: expected wheel steps in -1000..1000, got '1e30'"},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    CHECK_THROWS_WITH_AS(render::parseInputScript(c.text, "s.txt"), doctest::Contains(c.message),
                         Error);
  }
  CHECK_THROWS_WITH_AS(render::loadInputScript("/nonexistent/script.txt"),
                       doctest::Contains("/nonexistent/script.txt"), Error);
}
