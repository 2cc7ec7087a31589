#pragma once
// Command-line mistakes in the project's error style: `error: what was wrong`, a "did you mean"
// for mistyped commands and options, and where to find the right ones. Usage errors exit 2.
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace throng::tools {

inline constexpr int kUsageExitCode = 2;

// The candidate closest to `word` by edit distance, or "" when none is close enough to be a
// plausible typo (at most a third of the word's letters wrong).
std::string closestName(const std::string& word, const std::vector<std::string>& candidates);

// The message for a parse error of `root` given the command line it was parsing.
std::string usageErrorMessage(const CLI::App& root, const CLI::ParseError& error, int argc,
                              char** argv);

// The deepest subcommand of `root` that the command line `argv` names (root when none).
const CLI::App& commandNamedBy(const CLI::App& root, int argc, char** argv);

// "throng render" for the render subcommand: the words a user types to reach `command`.
std::string commandPath(const CLI::App& command);

// A CLI11 check that the value is one of `names`; otherwise a usage error that lists them, e.g.
// "--scene: unknown scene 'x': expected random, circle or storyboard". `what` names the kind.
CLI::Validator oneOf(const std::string& what, std::vector<std::string> names);

// A CLI11 check that the value is a number in [lo, hi]; otherwise a usage error in the tools'
// words, e.g. "--fov: expected 1..170 degrees, got 0" (`unit` may be empty).
CLI::Validator inRange(double lo, double hi, const std::string& unit = "");

// Whether an end of an interval belongs to it.
enum class End { kOpen, kClosed };

// The `hi` of an interval without an upper end.
inline constexpr double kNoEnd = std::numeric_limits<double>::infinity();

// A CLI11 check that the value lies between `lo` and `hi`, each end included or not, for ranges
// inRange cannot say: inInterval(End::kOpen, 0, 1, End::kClosed, "seconds") is (0, 1] and fails
// with "--dt: expected seconds in (0, 1], got 0"; an infinite `hi` leaves the range open-ended,
// "--target-error: expected metres > 0, got -1".
CLI::Validator inInterval(End loEnd, double lo, double hi, End hiEnd, const std::string& unit = "");

}  // namespace throng::tools
