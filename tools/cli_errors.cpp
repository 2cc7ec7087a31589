#include "cli_errors.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace throng::tools {
namespace {

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> subcommandNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::App* sub : command.get_subcommands([](const CLI::App*) { return true; }))
    if (!sub->get_name().empty()) names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> optionNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

// The words CLI11 lists after "not expected:" in an ExtrasError.
std::vector<std::string> unexpectedWords(const std::string& message) {
  std::vector<std::string> words;
  size_t colon = message.find(':');
  if (colon == std::string::npos) return words;
  std::istringstream in(message.substr(colon + 1));
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

std::string didYouMean(const std::string& word, const std::string& best) {
  return "'" + word + "': did you mean '" + best + "'?";
}

std::string suggestionFor(const CLI::App& command, const std::string& word) {
  bool isOption = word.size() > 1 && word[0] == '-';
  std::string name = isOption ? word.substr(0, word.find('=')) : word;
  std::string best = closestName(name, isOption ? optionNames(command) : subcommandNames(command));
  return best.empty() ? "" : didYouMean(name, best);
}

// Numbers as people write them: 0.05, 4000000, 1e+09 (no trailing zeros).
std::string numberText(double x) {
  std::ostringstream out;
  out << std::setprecision(10) << x;
  return out.str();
}

}  // namespace

CLI::Validator oneOf(const std::string& what, std::vector<std::string> names) {
  std::string list;
  for (size_t i = 0; i < names.size(); ++i)
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  auto check = [what, names, list](std::string& value) -> std::string {
    if (std::find(names.begin(), names.end(), value) != names.end()) return {};
    return "unknown " + what + " '" + value + "': expected " + list;
  };
  return CLI::Validator(check, "{" + CLI::detail::join(names, ",") + "}", "one of");
}

CLI::Validator inRange(double lo, double hi, const std::string& unit) {
  const std::string range =
      numberText(lo) + ".." + numberText(hi) + (unit.empty() ? "" : " " + unit);
  auto check = [lo, hi, range](std::string& value) -> std::string {
    double x = 0.0;
    // NaN fails both comparisons: "nan" is reported like any other value out of range.
    if (!CLI::detail::lexical_cast(value, x) || !(x >= lo && x <= hi))
      return "expected " + range + ", got " + value;
    return {};
  };
  return CLI::Validator(check, "[" + range + "]", "range");
}

CLI::Validator inInterval(End loEnd, double lo, double hi, End hiEnd, const std::string& unit) {
  const bool loOpen = loEnd == End::kOpen, hiOpen = hiEnd == End::kOpen;
  const bool bounded = !std::isinf(hi);
  const std::string interval =
      bounded ? (loOpen ? "(" : "[") + numberText(lo) + ", " + numberText(hi) + (hiOpen ? ")" : "]")
              : (loOpen ? "> " : ">= ") + numberText(lo);
  // "metres > 0", "seconds in (0, 1]": the unit first, so the message reads as words.
  const std::string range = unit.empty() ? interval : unit + (bounded ? " in " : " ") + interval;
  auto check = [=](std::string& value) -> std::string {
    double x = 0.0;
    // NaN fails every comparison, so it is reported like any other value outside.
    if (!CLI::detail::lexical_cast(value, x) || !(loOpen ? x > lo : x >= lo) ||
        !(hiOpen ? x < hi : x <= hi))
      return "expected " + range + ", got " + value;
    return {};
  };
  return CLI::Validator(check, interval + (unit.empty() ? "" : " " + unit), "interval");
}

std::string closestName(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t bestDistance = std::max<size_t>(1, word.size() / 3) + 1;
  for (const std::string& candidate : candidates) {
    size_t d = editDistance(word, candidate);
    if (d < bestDistance) {
      bestDistance = d;
      best = candidate;
    }
  }
  return best;
}

const CLI::App& commandNamedBy(const CLI::App& root, int argc, char** argv) {
  const CLI::App* command = &root;
  for (int i = 1; i < argc; ++i) {
    std::string word = argv[i];
    if (word.empty() || word[0] == '-') continue;
    const CLI::App* next = nullptr;
    for (const CLI::App* sub : command->get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == word) next = sub;
    if (next) command = next;
  }
  return *command;
}

std::string commandPath(const CLI::App& command) {
  std::string path;
  for (const CLI::App* c = &command; c; c = c->get_parent()) {
    std::string name = c->get_parent() ? c->get_name() : "throng";
    path = path.empty() ? name : name + " " + path;
  }
  return path;
}

std::string usageErrorMessage(const CLI::App& root, const CLI::ParseError& error, int argc,
                              char** argv) {
  const CLI::App& command = commandNamedBy(root, argc, argv);
  std::string message = error.what();
  std::vector<std::string> hints;
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    for (const std::string& word : unexpectedWords(message)) {
      std::string hint = suggestionFor(command, word);
      if (!hint.empty()) hints.push_back(hint);
    }
  } else if (dynamic_cast<const CLI::RequiredError*>(&error) && !subcommandNames(command).empty()) {
    // "A subcommand is required": a mistyped command name is the usual cause.
    for (int i = 1; i < argc; ++i) {
      std::string word = argv[i];
      if (word.empty() || word[0] == '-') continue;
      std::string hint = suggestionFor(command, word);
      if (!hint.empty()) {
        hints.push_back(hint);
        break;
      }
    }
    if (hints.empty())
      message += " (one of: " + CLI::detail::join(subcommandNames(command), ", ") + ")";
  }
  std::string text = message;
  for (const std::string& hint : hints) text += "\n  " + hint;
  text += "\n  see '" + commandPath(command) + " --help'";
  return text;
}

}  // namespace throng::tools
