#include "storyboard/json_document.h"

#include <set>
#include <vector>

#include "core/error.h"

namespace throng::storyboard {
namespace {

// The keys seen so far in each open object, and the path of keys to the value being read.
struct KeyTracker {
  std::vector<std::set<std::string>> seen;
  std::vector<std::string> path;  // one entry per open object: its current key ("" before any)
  std::string duplicate;          // set when a key repeats

  std::string where() const {
    std::string out;
    for (const std::string& key : path)
      if (!key.empty()) out += (out.empty() ? "" : ".") + key;
    return out;
  }

  bool onEvent(nlohmann::json::parse_event_t event, const JsonDocument& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (event == Event::object_start) {
      seen.emplace_back();
      path.emplace_back();
    } else if (event == Event::object_end && !seen.empty()) {
      seen.pop_back();
      path.pop_back();
    } else if (event == Event::key && !seen.empty()) {
      const std::string key = parsed.get<std::string>();
      path.back() = key;
      if (!seen.back().insert(key).second) {
        duplicate = where();
        throw Error("duplicate key");  // stops the parser; reported below with the line
      }
    }
    return true;
  }
};

// The message without nlohmann's "[json.exception.parse_error.101] " prefix.
std::string plainMessage(const nlohmann::json::exception& e) {
  std::string message = e.what();
  if (!message.empty() && message[0] == '[') {
    size_t close = message.find("] ");
    if (close != std::string::npos) message = message.substr(close + 2);
  }
  return message;
}

}  // namespace

JsonDocument parseJsonDocument(std::string_view text, const std::string& source) {
  KeyTracker keys;
  auto callback = [&keys](int /*depth*/, nlohmann::json::parse_event_t event,
                          JsonDocument& parsed) { return keys.onEvent(event, parsed); };
  try {
    return JsonDocument::parse(text.begin(), text.end(), callback);
  } catch (const Error&) {
    fail(source, ": duplicate key \"", keys.duplicate, "\" (expected each key once per object)");
  } catch (const nlohmann::json::parse_error& e) {
    fail(source, ": not valid JSON (", plainMessage(e), ")");  // the message has line and column
  } catch (const nlohmann::json::exception& e) {
    // Out-of-range numbers (1e400) end the parse without a byte offset: name the key instead.
    const std::string key = keys.where();
    fail(source, ": ", key.empty() ? "" : concat("key \"", key, "\": "), plainMessage(e),
         " (expected numbers within the range of a double)");
  }
}

}  // namespace throng::storyboard
