#pragma once
// Running `throng view` under the suite's private Xvfb and reading its --print-stats line.
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "xvfb_server.h"

namespace throng::test {

struct ViewRun {
  CommandResult result;
  nlohmann::json stats;  // the --print-stats line (null when absent)
};

inline ViewRun runView(const std::string& args) {
  XvfbServer& x = XvfbServer::instance();
  REQUIRE_MESSAGE(!x.display().empty(), x.error());
  useDisplay(x.display());
  ViewRun run{runThrong("view " + args + " --print-stats"), nullptr};
  std::istringstream lines(run.result.output);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] == '{') run.stats = nlohmann::json::parse(line, nullptr, false);
  return run;
}

// The first key anywhere in `j` that is not snake_case ("" when every key is).
inline std::string firstNonSnakeKey(const nlohmann::json& j) {
  auto snake = [](const std::string& key) {
    return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
  };
  if (!j.is_structured()) return {};
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (j.is_object() && !snake(it.key())) return it.key();
    if (std::string inner = firstNonSnakeKey(*it); !inner.empty()) return inner;
  }
  return {};
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

}  // namespace throng::test
