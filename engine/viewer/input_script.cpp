#include "viewer/input_script.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/error.h"
#include "core/file_io.h"

namespace throng::render {
namespace {

constexpr long kMaxFrames = 100000;
// Cursor positions may leave the window (at most 16384 pixels a side) but not by absurd
// amounts; wheel steps per line are bounded alike. Past these the camera's floats overflow.
constexpr double kMaxCursorPixels = 100000.0;
constexpr double kMaxScrollSteps = 1000.0;

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

struct LineReader {
  std::istringstream words;
  std::string where;  // "name:line"

  std::string word(const char* what) {
    std::string w;
    if (!(words >> w)) fail(where, ": expected ", what);
    return w;
  }
  bool optionalWord(std::string& w) { return static_cast<bool>(words >> w); }
  double number(const std::string& text, const char* what) {
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v))
      fail(where, ": expected ", what, ", got '", text, "'");
    return v;
  }
  double bounded(const std::string& text, const char* what, double limit) {
    double v = number(text, what);
    if (std::fabs(v) > limit)
      fail(where, ": expected ", what, " in ", -limit, "..", limit, ", got '", text, "'");
    return v;
  }
  double pixel(const char* what) { return bounded(word(what), what, kMaxCursorPixels); }
  long count(const std::string& text, const char* what, long lo, long hi) {
    double v = number(text, what);
    if (v != std::floor(v) || v < lo || v > hi)
      fail(where, ": expected ", what, " in ", lo, "..", hi, ", got '", text, "'");
    return static_cast<long>(v);
  }
  void end() {
    std::string extra;
    if (words >> extra) fail(where, ": unexpected '", extra, "' at the end of the line");
  }
};

int mouseButtonFromName(const std::string& name, const std::string& where) {
  std::string n = upper(name);
  if (n == "LEFT") return GLFW_MOUSE_BUTTON_LEFT;
  if (n == "RIGHT") return GLFW_MOUSE_BUTTON_RIGHT;
  if (n == "MIDDLE") return GLFW_MOUSE_BUTTON_MIDDLE;
  fail(where, ": expected a mouse button (left, right or middle), got '", name, "'");
}

void addEmptyFrames(InputScript& script, long n) {
  for (long i = 0; i < n; ++i) script.frames.emplace_back();
}

void parseDrag(LineReader& line, InputScript& script) {
  double x0 = line.pixel("X0"), y0 = line.pixel("Y0");
  double x1 = line.pixel("X1"), y1 = line.pixel("Y1");
  long frames = 10;
  int button = GLFW_MOUSE_BUTTON_LEFT;
  std::string w;
  if (line.optionalWord(w)) {
    if (std::isdigit(static_cast<unsigned char>(w[0]))) {
      frames = line.count(w, "a frame count", 1, kMaxFrames);
      if (line.optionalWord(w)) button = mouseButtonFromName(w, line.where);
    } else {
      button = mouseButtonFromName(w, line.where);
    }
  }
  line.end();
  script.frames.push_back(
      {{ScriptEvent::Kind::Cursor, x0, y0}, {ScriptEvent::Kind::Button, 0, 0, button, true}});
  for (long i = 1; i <= frames; ++i) {
    double t = double(i) / double(frames);
    std::vector<ScriptEvent> events{
        {ScriptEvent::Kind::Cursor, x0 + (x1 - x0) * t, y0 + (y1 - y0) * t}};
    if (i == frames) events.push_back({ScriptEvent::Kind::Button, 0, 0, button, false});
    script.frames.push_back(events);
  }
}

// `lod on|off`, `cache on|off`: one frame that sets the panel's checkbox.
void parseSwitch(LineReader& line, InputScript& script, const std::string& command,
                 ScriptEvent::Kind kind) {
  std::string value;
  line.optionalWord(value);
  const std::string v = upper(value);
  if (v != "ON" && v != "OFF")
    fail(line.where, ": expected 'on' or 'off' after '", command, "'",
         value.empty() ? "" : concat(", got '", value, "'"));
  line.end();
  ScriptEvent e{kind};
  e.pressed = v == "ON";
  script.frames.push_back({e});
}

void parseLine(LineReader& line, InputScript& script) {
  std::string command = line.word("a command");
  if (command == "wait") {
    long n = line.count(line.word("a frame count"), "a frame count", 1, kMaxFrames);
    line.end();
    addEmptyFrames(script, n);
  } else if (command == "drag") {
    parseDrag(line, script);
  } else if (command == "key") {
    std::string name = line.word("a key name");
    int code = keyCodeFromName(name);
    if (code < 0)
      fail(line.where, ": unknown key '", name,
           "' (letters, digits, F1..F12, SPACE, ESCAPE, TAB, ...)");
    long frames = 1;
    std::string w;
    if (line.optionalWord(w)) frames = line.count(w, "a frame count", 1, kMaxFrames);
    line.end();
    script.frames.push_back({{ScriptEvent::Kind::Key, 0, 0, code, true}});
    addEmptyFrames(script, frames - 1);
    script.frames.push_back({{ScriptEvent::Kind::Key, 0, 0, code, false}});
  } else if (command == "scroll") {
    double steps = line.bounded(line.word("wheel steps"), "wheel steps", kMaxScrollSteps);
    line.end();
    script.frames.push_back({{ScriptEvent::Kind::Scroll, steps}});
  } else if (command == "resize") {
    long w = line.count(line.word("a width"), "a width", 1, 16384);
    long h = line.count(line.word("a height"), "a height", 1, 16384);
    line.end();
    ScriptEvent e{ScriptEvent::Kind::Resize, double(w), double(h)};
    e.where = line.where;
    script.frames.push_back({e});
  } else if (command == "respawn") {
    long n = line.count(line.word("a character count"), "a character count", 1, 4000000);
    ScriptEvent e{ScriptEvent::Kind::Respawn, double(n)};
    e.where = line.where;
    line.optionalWord(e.text);
    line.end();
    script.frames.push_back({e});
  } else if (command == "lod") {
    parseSwitch(line, script, command, ScriptEvent::Kind::Lod);
  } else if (command == "cache") {
    parseSwitch(line, script, command, ScriptEvent::Kind::Cache);
  } else if (command == "close") {
    line.end();
    script.frames.push_back({{ScriptEvent::Kind::Close}});
  } else {
    fail(line.where, ": unknown command '", command,
         "' (expected wait, drag, key, scroll, resize, respawn, lod, cache or close)");
  }
}

}  // namespace

int keyCodeFromName(const std::string& name) {
  static const std::map<std::string, int> kNamed = {
      {"SPACE", GLFW_KEY_SPACE}, {"ESCAPE", GLFW_KEY_ESCAPE},   {"ESC", GLFW_KEY_ESCAPE},
      {"TAB", GLFW_KEY_TAB},     {"ENTER", GLFW_KEY_ENTER},     {"SHIFT", GLFW_KEY_LEFT_SHIFT},
      {"LEFT", GLFW_KEY_LEFT},   {"RIGHT", GLFW_KEY_RIGHT},     {"UP", GLFW_KEY_UP},
      {"DOWN", GLFW_KEY_DOWN},   {"PAGE_UP", GLFW_KEY_PAGE_UP}, {"PAGE_DOWN", GLFW_KEY_PAGE_DOWN}};
  std::string n = upper(name);
  if (n.size() == 1 && n[0] >= 'A' && n[0] <= 'Z') return GLFW_KEY_A + (n[0] - 'A');
  if (n.size() == 1 && n[0] >= '0' && n[0] <= '9') return GLFW_KEY_0 + (n[0] - '0');
  // F1..F12: at most two digits, so the number always fits an int.
  if (n.size() >= 2 && n.size() <= 3 && n[0] == 'F' &&
      std::all_of(n.begin() + 1, n.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) {
    int f = std::stoi(n.substr(1));
    if (f >= 1 && f <= 12) return GLFW_KEY_F1 + (f - 1);
  }
  auto it = kNamed.find(n);
  return it == kNamed.end() ? -1 : it->second;
}

InputScript parseInputScript(const std::string& text, const std::string& name) {
  InputScript script;
  std::istringstream lines(text);
  std::string raw;
  for (int number = 1; std::getline(lines, raw); ++number) {
    if (size_t hash = raw.find('#'); hash != std::string::npos) raw.resize(hash);
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    if (raw.find_first_not_of(" \t") == std::string::npos) continue;
    LineReader line{std::istringstream(raw), concat(name, ":", number)};
    parseLine(line, script);
    if (script.frames.size() > size_t(10 * kMaxFrames))
      fail(line.where, ": the script is longer than ", 10 * kMaxFrames, " frames");
  }
  return script;
}

InputScript loadInputScript(const std::filesystem::path& path) {
  return parseInputScript(readTextFile(path), path.string());
}

}  // namespace throng::render
