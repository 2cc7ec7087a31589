// throng: render, view, bench and the authoring commands. Each subcommand lives in its own
// tools/cmd_*.cpp; main only parses and turns errors into a message and an exit code.
#include <cstdio>
#include <exception>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "command.h"
#include "core/error.h"

namespace throng::tools {
namespace {
std::map<std::string, AddCommandFn>& registry() {
  static std::map<std::string, AddCommandFn> commands;
  return commands;
}

std::vector<char*>& arguments() {
  static std::vector<char*> argv;
  return argv;
}
}  // namespace

std::span<char* const> commandLine() {
  return arguments();
}

CommandRegistration::CommandRegistration(const char* name, AddCommandFn add) {
  registry()[name] = add;
}

void addRegisteredCommands(CLI::App& app) {
  for (auto& [name, add] : registry()) add(app);
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
  app.set_version_flag("--version", "throng " THRONG_VERSION);
  throng::tools::arguments().assign(argv, argv + argc);
  throng::tools::arguments().push_back(nullptr);
  throng::tools::addRegisteredCommands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Every other parse failure is a usage error: one style and one exit code, never CLI11's own.
    std::fprintf(stderr, "error: %s\n",
                 throng::tools::usageErrorMessage(app, e, argc, argv).c_str());
    return throng::tools::kUsageExitCode;
  } catch (const throng::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
