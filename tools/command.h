#pragma once
// Each tools/cmd_*.cpp registers its subcommands with a file-scope CommandRegistration, so
// adding a command never touches main.cpp.
#include <span>

#include <CLI/CLI.hpp>

namespace throng::tools {

using AddCommandFn = void (*)(CLI::App& app);

struct CommandRegistration {
  CommandRegistration(const char* name, AddCommandFn add);
};

void addRegisteredCommands(CLI::App& app);

// The program's argv as main received it, ending in a null pointer (for handing the same
// command line to another executable).
std::span<char* const> commandLine();

// A command group that several cmd_*.cpp files add subcommands to (e.g. `cloth`): the first
// caller creates it (requiring one subcommand), later ones get the same one.
CLI::App* commandGroup(CLI::App& app, const char* name, const char* description);

}  // namespace throng::tools
