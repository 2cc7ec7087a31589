#pragma once
// clang-format off
// Scripted input for the viewer (tests, demos, reproducible bug reports). One command per line,
// '#' starts a comment; every command becomes the input events of one or more frames:
//   wait N                          N frames without input
//   drag X0 Y0 X1 Y1 [N] [BUTTON]   press at (X0,Y0), move to (X1,Y1) over N frames (10),
//                                   release; BUTTON is left (default), right or middle
//   key NAME [N]                    hold a key for N frames (1): W, Q, 1, F12, SPACE, ESCAPE, ...
//   scroll STEPS                    mouse wheel (positive zooms in), at most 1000 steps
//   resize W H                      ask the window system for a W×H window
//   respawn N [SCENARIO]            the panel's respawn: N characters (scenario kept if absent)
//   lod on|off                      the panel's "coverage LOD" checkbox (switching respawns)
//   cache on|off                    the panel's "motion cache" checkbox (applies at a respawn)
//   close                           close the window, as its close button does
// clang-format on
#include <filesystem>
#include <string>
#include <vector>

namespace throng::render {

struct ScriptEvent {
  enum class Kind { Cursor, Button, Scroll, Key, Resize, Respawn, Lod, Cache, Close };
  Kind kind = Kind::Cursor;
  double x = 0.0, y = 0.0;  // cursor position, scroll steps (x), window size (x, y)
  int code = 0;             // GLFW mouse button or key code
  bool pressed = false;     // button, key: pressed; lod, cache: on
  std::string text;         // respawn: the scenario name (empty: keep)
  std::string where;        // resize, respawn: "NAME:LINE" of the command, for errors about it
};

struct InputScript {
  std::vector<std::vector<ScriptEvent>> frames;  // the events to deliver before each frame
};

// Throws Error "NAME:LINE: ..." naming the line and what was expected: for unknown commands,
// non-numbers, non-finite numbers and absurd ones (cursor positions beyond ±100000 pixels,
// more than 1000 wheel steps, counts out of range).
InputScript parseInputScript(const std::string& text, const std::string& name);
InputScript loadInputScript(const std::filesystem::path& path);

// GLFW key code for a name (letters, digits, F1..F12, SPACE, ESCAPE, TAB, ENTER, SHIFT, arrows);
// -1 when unknown.
int keyCodeFromName(const std::string& name);

}  // namespace throng::render
