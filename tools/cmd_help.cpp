// `throng help [command [subcommand]]`: the help text of any command, like `COMMAND --help`.
#include <cstdio>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "command.h"

namespace throng::tools {
namespace {

void printHelp(const CLI::App& root, const std::vector<std::string>& words) {
  const CLI::App* command = &root;
  for (const std::string& word : words) {
    const CLI::App* next = nullptr;
    std::vector<std::string> names;
    for (const CLI::App* sub : command->get_subcommands([](const CLI::App*) { return true; })) {
      names.push_back(sub->get_name());
      if (sub->get_name() == word) next = sub;
    }
    if (!next) {
      std::string best = closestName(word, names);
      throw CLI::ValidationError("help",
                                 "'" + commandPath(*command) + "' has no command '" + word + "'" +
                                     (best.empty() ? "" : " (did you mean '" + best + "'?)"));
    }
    command = next;
  }
  std::fputs(command->help().c_str(), stdout);
}

void addHelpCommand(CLI::App& app) {
  auto words = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand(
      "help", "Show the help of a command: throng help render, throng help cloth explore");
  cmd->add_option("command", *words, "The command (and subcommand) to describe");
  const CLI::App* root = &app;
  cmd->callback([root, words] { printHelp(*root, *words); });
}

const CommandRegistration kRegistration("help", addHelpCommand);

}  // namespace
}  // namespace throng::tools
