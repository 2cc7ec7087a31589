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

TEST_CASE("cli: bad choices and numbers out of range are usage errors that say what is allowed") {
  struct Case {
    std::string arguments, message;
  };
  const Case cases[] = {
      {"render --scene foo",
       "error: --scene: unknown scene 'foo': expected random, circle, storyboard, menge or "
       "corridor"},
      {"view --scene foo",
       "error: --scene: unknown scene 'foo': expected random, circle, storyboard, menge or "
       "corridor"},
      {"render --camera foo",
       "error: --camera: unknown camera preset 'foo': expected wide, top, "
       "street or closeup"},
      {"view --camera foo", "error: --camera: unknown camera preset 'foo'"},
      {"render --policy boids", "error: --policy: unknown policy 'boids': expected anticipatory"},
      {"render --characters -5", "error: --characters: expected 1..4000000, got -5"},
      {"view -n 4000001", "error: --characters: expected 1..4000000, got 4000001"},
      {"render --fov 0", "error: --fov: expected 1..170 degrees, got 0"},
      {"view --fov nan", "error: --fov: expected 1..170 degrees, got nan"},
      {"render --speed-max 1.5", "error: --speed-max: expected 0..1, got 1.5"},
      {"render --cache-budget -1", "error: --cache-budget: expected 0..65536 MB, got -1"},
      {"render --radius 0", "error: --radius: expected 0.01..10 metres, got 0"},
      {"cloth compress /etc/passwd --out y.tsc --max-bases 0",
       "error: --max-bases: Value 0 not in range 1 to 4096"},
      // Ranges with an open end: the end itself is refused.
      {"render --dt 0", "error: --dt: expected seconds in (0, 1], got 0"},
      {"view --dt 1.5", "error: --dt: expected seconds in (0, 1], got 1.5"},
      {"render --bucket-width -0.5", "error: --bucket-width: expected (0, 1], got -0.5"},
      {"crowd simulate --storyboard a.png --trajectories t.txt --dt 0",
       "error: --dt: expected seconds in (0, 1], got 0"},
      {"crowd simulate --storyboard a.png --trajectories t.txt --radius 0",
       "error: --radius: expected metres in (0, 10], got 0"},
      {"crowd metrics --trajectories t.txt --body-radius 10.5",
       "error: --body-radius: expected metres in (0, 10], got 10.5"},
      {"cloth compress /etc/passwd --out y.tsc --quantum 1",
       "error: --quantum: expected metres in (0, 1), got 1"},
      {"cloth compress /etc/passwd --out y.tsc --coefficient-quantum -0.001",
       "error: --coefficient-quantum: expected metres in [0, 1), got -0.001"},
      {"cloth compress /etc/passwd --out y.tsc --bucket-width 0",
       "error: --bucket-width: expected (0, 1], got 0"},
      {"cloth compress /etc/passwd --out y.tsc --target-error 0",
       "error: --target-error: expected metres > 0, got 0"},
      {"cloth compress /etc/passwd --out y.tsc --target-error nan",
       "error: --target-error: expected metres > 0, got nan"},
      {"cloth explore --out x.tsg --target-error -1",
       "error: --target-error: expected 0..1000 metres, got -1"},
  };
  for (const Case& c : cases) {
    auto r = runThrong(c.arguments);
    CAPTURE(c.arguments);
    CAPTURE(r.output);
    CHECK(r.exitCode == 2);
    CHECK(contains(r.output, c.message));
  }
  // In range and among the choices: no usage error (help stops before any work).
  for (const char* arguments :
       {"render --scene circle --camera top --fov 170 -n 1 --help",
        "view --speed-max 1 --cache-budget 0 --help", "render --dt 1 --bucket-width 1 --help",
        "crowd metrics --trajectories t.txt --dt 0.001 --radius 10 --body-radius 1e-6 --help",
        "cloth compress /etc/passwd --out y.tsc --quantum 0.999 --coefficient-quantum 0 "
        "--bucket-width 1 --target-error 1e9 --help"}) {
    auto r = runThrong(arguments);
    CAPTURE(arguments);
    CAPTURE(r.output);
    CHECK(r.exitCode == 0);
  }
}
