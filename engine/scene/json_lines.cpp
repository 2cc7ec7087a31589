#include "scene/json_lines.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace throng::scene {

namespace {

// A container being scanned: its pointer, whether it is an object, the next array index or the
// last key read, and whether a key was just read (objects) so the next value belongs to it.
struct Frame {
  std::string pointer;
  bool object = false;
  size_t index = 0;
  std::string key;
};

std::string escapePointer(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

// The string starting at text[i] == '"' (escapes kept simple: \x skips x); returns the index
// after the closing quote and the string in `out`.
size_t readString(std::string_view text, size_t i, int& line, std::string& out) {
  out.clear();
  for (++i; i < text.size() && text[i] != '"'; ++i) {
    if (text[i] == '\n') ++line;
    if (text[i] == '\\' && i + 1 < text.size()) ++i;
    out += text[i];
  }
  return i + 1;
}

}  // namespace

JsonLines::JsonLines(std::string_view text) {
  std::vector<Frame> stack;
  int line = 1;
  bool expectKey = false;
  std::string str;
  auto valuePointer = [&]() -> std::string {
    if (stack.empty()) return "";
    Frame& f = stack.back();
    if (f.object) return f.pointer + "/" + escapePointer(f.key);
    return f.pointer + "/" + std::to_string(f.index);
  };
  auto startValue = [&]() {
    const std::string pointer = valuePointer();
    lines_.emplace(pointer, line);
    return pointer;
  };
  for (size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c)) || c == ':') {
      ++i;
    } else if (c == ',') {
      if (!stack.empty() && !stack.back().object) ++stack.back().index;
      expectKey = !stack.empty() && stack.back().object;
      ++i;
    } else if (c == '{' || c == '[') {
      const std::string pointer = startValue();
      stack.push_back({pointer, c == '{', 0, ""});
      expectKey = c == '{';
      ++i;
    } else if (c == '}' || c == ']') {
      if (!stack.empty()) stack.pop_back();
      expectKey = false;
      ++i;
    } else if (c == '"') {
      const bool isKey = expectKey && !stack.empty() && stack.back().object;
      if (!isKey) startValue();
      i = readString(text, i, line, str);
      if (isKey) {
        stack.back().key = str;
        expectKey = false;
      }
    } else {
      startValue();  // a number or literal
      while (i < text.size() && text[i] != ',' && text[i] != '}' && text[i] != ']' &&
             text[i] != '\n' && !std::isspace(static_cast<unsigned char>(text[i])))
        ++i;
    }
  }
}

int JsonLines::line(const std::string& pointer) const {
  std::string p = pointer;
  while (true) {
    auto it = lines_.find(p);
    if (it != lines_.end()) return it->second;
    const size_t slash = p.rfind('/');
    if (slash == std::string::npos || p.empty()) return 1;
    p.resize(slash);
  }
}

std::string keyPath(const std::string& pointer) {
  std::string out;
  size_t i = 0;
  while (i < pointer.size()) {
    const size_t next = pointer.find('/', i + 1);
    std::string token =
        pointer.substr(i + 1, next == std::string::npos ? std::string::npos : next - i - 1);
    const bool index = !token.empty() && std::all_of(token.begin(), token.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c));
    });
    if (index)
      out += "[" + token + "]";
    else
      out += (out.empty() ? "" : ".") + token;
    if (next == std::string::npos) break;
    i = next;
  }
  return out;
}

}  // namespace throng::scene
