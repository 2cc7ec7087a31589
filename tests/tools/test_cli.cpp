// The command line itself: version, help, and usage errors in one style with one exit code.
#include <doctest/doctest.h>

#include <string>

#include "cli_support.h"

using throng::test::runThrong;

namespace {
bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}
}  // namespace

TEST_CASE("cli: --version and help") {
  auto version = runThrong("--version");
  CHECK(version.exitCode == 0);
  CHECK(contains(version.output, "throng "));

  auto help = runThrong("help render");
  CHECK(help.exitCode == 0);
  CHECK(contains(help.output, "--frames"));

  auto nested = runThrong("help cloth explore");
  CHECK(nested.exitCode == 0);
  CHECK(contains(nested.output, "--budget-seconds"));

  auto unknown = runThrong("help rendr");
  CHECK(unknown.exitCode == 2);
  CHECK(contains(unknown.output, "error: "));
  CHECK(contains(unknown.output, "did you mean 'render'?"));
}

TEST_CASE("cli: mistyped commands and options are usage errors (exit 2) with a suggestion") {
  auto command = runThrong("rendr");
  CHECK(command.exitCode == 2);
  CHECK(contains(command.output, "error: "));
  CHECK(contains(command.output, "'rendr': did you mean 'render'?"));

  auto subcommand = runThrong("cloth explor --out x.tsg");
  CHECK(subcommand.exitCode == 2);
  CHECK(contains(subcommand.output, "did you mean 'explore'?"));

  auto option = runThrong("render --frmes 3");
  CHECK(option.exitCode == 2);
  CHECK(contains(option.output, "'--frmes': did you mean '--frames'?"));
  CHECK(contains(option.output, "see 'throng render --help'"));

  auto value = runThrong("render --frames abc");
  CHECK(value.exitCode == 2);
  CHECK(contains(value.output, "error: "));

  auto none = runThrong("");
  CHECK(none.exitCode == 2);
  CHECK(contains(none.output, "one of: "));
}

TEST_CASE("cli: no CLI11 exit codes (104-114) leak out") {
  for (const char* arguments :
       {"render --size", "render --frames 1 --frames 2 --nonsense", "crowd", "cloth info"}) {
    auto r = runThrong(arguments);
    CAPTURE(arguments);
    CAPTURE(r.output);
    CHECK(r.exitCode == 2);
    CHECK(contains(r.output, "error: "));
  }
}
