// throng: render, view, bench and the authoring commands. Each subcommand lives in its own
// tools/cmd_*.cpp; main only parses and turns errors into a message and an exit code.
#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "command.h"
#include "core/error.h"

namespace throng::tools {
namespace {
std::map<std::string, AddCommandFn>& registry() {
  static std::map<std::string, AddCommandFn> commands;
  return commands;
}
}  // namespace

CommandRegistration::CommandRegistration(const char* name, AddCommandFn add) {
  registry()[name] = add;
}

void addRegisteredCommands(CLI::App& app, int& exitCode) {
  for (auto& [name, add] : registry()) add(app, exitCode);
}

CLI::App* commandGroup(CLI::App& app, const char* name, const char* description) {
  // CLI11 2.1 has no get_subcommand_no_throw.
  try {
    return app.get_subcommand(name);
  } catch (const CLI::OptionNotFound&) {
    CLI::App* group = app.add_subcommand(name, description);
    group->require_subcommand(1);
    return group;
  }
}
}  // namespace throng::tools

int main(int argc, char** argv) {
  CLI::App app{"Throng: GPU crowd animation (motion synthesis, storyboards, secondary motion)"};
  app.require_subcommand(1);
  int exitCode = 0;
  throng::tools::addRegisteredCommands(app, exitCode);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const throng::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "internal error: %s\n", e.what());
    return 2;
  }
  return exitCode;
}
