#pragma once
// Where each value of a JSON text starts: a map from the value's JSON pointer ("/groups/1/count")
// to its 1-based line, so that readers of JSON files can report `FILE:LINE: key: what was
// expected` (nlohmann's parser reports lines only for syntax errors).
#include <map>
#include <string>
#include <string_view>

namespace throng::scene {

class JsonLines {
 public:
  // Indexes `text`; text that is not valid JSON is indexed as far as it goes (the parser reports
  // the syntax error itself).
  explicit JsonLines(std::string_view text);
  // The line of the value at `pointer`, or of its nearest indexed parent (1 for the root).
  int line(const std::string& pointer) const;

 private:
  std::map<std::string, int> lines_;
};

// "/groups/1/count" → "groups[1].count" (how errors name a key).
std::string keyPath(const std::string& pointer);

}  // namespace throng::scene
