#pragma once
// Checks of the one JSON style (docs/formats.md, "JSON"): snake_case keys everywhere.
#include <algorithm>
#include <string>

#include <nlohmann/json.hpp>

namespace throng::test {

// The first key anywhere in `j` that is not snake_case ("" when every key is).
inline std::string firstNonSnakeKey(const nlohmann::json& j) {
  auto snake = [](const std::string& key) {
    return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
  };
  if (!j.is_structured()) return {};
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (j.is_object() && !snake(it.key())) return it.key();
    if (std::string inner = firstNonSnakeKey(*it); !inner.empty()) return inner;
  }
  return {};
}

}  // namespace throng::test
