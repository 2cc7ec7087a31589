#pragma once
// Scripted input for the viewer (tests, demos, reproducible bug reports). One command per line,
// '#' starts a comment; every command becomes the input events of one or more frames:
//   wait N                             N frames without input
//   drag X0 Y0 X1 Y1 [N] [left|right|middle]
//                                      press at (X0,Y0), move to (X1,Y1) over N frames (10),
//                                      release
//   key NAME [N]                       hold a key for N frames (1): W, Q, 1, F12, SPACE, ESCAPE,
//   ... scroll STEPS                       mouse wheel (positive zooms in) resize W H ask the
//   window system for a W×H window respawn N [SCENARIO]               the panel's respawn: N
//   characters (scenario kept if absent) close                              close the window, as
//   its close button does
#include <filesystem>
#include <string>
#include <vector>

namespace throng::render {

struct ScriptEvent {
  enum class Kind { Cursor, Button, Scroll, Key, Resize, Respawn, Close };
  Kind kind = Kind::Cursor;
  double x = 0.0, y = 0.0;  // cursor position, scroll steps (x), window size (x, y)
  int code = 0;             // GLFW mouse button or key code
  bool pressed = false;
  std::string text;  // respawn: the scenario name (empty: keep)
};

struct InputScript {
  std::vector<std::vector<ScriptEvent>> frames;  // the events to deliver before each frame
};

// Throws Error "NAME:LINE: ..." naming the line and what was expected.
InputScript parseInputScript(const std::string& text, const std::string& name);
InputScript loadInputScript(const std::filesystem::path& path);

// GLFW key code for a name (letters, digits, F1..F12, SPACE, ESCAPE, TAB, ENTER, SHIFT, arrows);
// -1 when unknown.
int keyCodeFromName(const std::string& name);

}  // namespace throng::render
