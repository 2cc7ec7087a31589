#pragma once
// Strict JSON for the storyboard module's readers (legends, `storyboard encode` input): every
// nlohmann exception becomes an Error naming the file and the line or the key it was reading;
// a key repeated within one object is an error, not "last wins".
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/error.h"

namespace throng::storyboard {

using JsonDocument = nlohmann::ordered_json;

// Throws Error naming `source` and the line and column (malformed JSON) or the key (numbers out
// of range such as 1e400, duplicate keys).
JsonDocument parseJsonDocument(std::string_view text, const std::string& source);

// Runs `read` on a parsed document, turning a type or range exception thrown while the values
// are read into an Error naming `source`.
template <typename Read>
auto readJsonDocument(const std::string& source, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const nlohmann::json::exception& e) {
    throw Error(source + ": " + e.what());
  }
}

}  // namespace throng::storyboard
