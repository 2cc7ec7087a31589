#pragma once
// Running `throng view` under the suite's private Xvfb and reading its --print-stats line.
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "xvfb_server.h"
#include "json_keys.h"

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


inline void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

}  // namespace throng::test
