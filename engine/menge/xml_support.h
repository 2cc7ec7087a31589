#pragma once
// Helpers shared by the Menge XML readers: a parsed document that knows its file name and line
// numbers (pugixml reports byte offsets), typed attribute readers that throw
// "FILE:LINE: <Element>: what was expected", and warnings in the same form.
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

#include "core/error.h"
#include "menge/menge.h"

namespace throng::menge::detail {

class XmlDocument {
 public:
  // Parses `text`; a syntax error throws "FILE:LINE: malformed XML: <pugixml's reason>".
  XmlDocument(std::string_view text, const std::filesystem::path& source,
              std::vector<std::string>& warnings);

  // The document element, which must be named `name`.
  pugi::xml_node root(std::string_view name) const;
  const std::filesystem::path& source() const { return source_; }
  // The folder file_name attributes are resolved against.
  std::filesystem::path resolve(const std::string& fileName) const;

  int line(pugi::xml_node node) const;
  // "FILE:LINE: <Element type="t">"
  std::string where(pugi::xml_node node) const;

  template <typename... Args>
  [[noreturn]] void fail(pugi::xml_node node, const Args&... args) const {
    throng::fail(where(node), ": ", args...);
  }
  template <typename... Args>
  void warn(pugi::xml_node node, const Args&... args) const {
    warnings_.push_back(concat(where(node), ": ", args...));
  }
  // Warns once per attribute of `node` not in `known`.
  void checkAttributes(pugi::xml_node node, std::initializer_list<std::string_view> known) const;

  // Required attributes throw when absent or unparsable; optional ones return `fallback` when
  // absent and throw when present but unparsable.
  std::string requireString(pugi::xml_node node, const char* name) const;
  float requireFloat(pugi::xml_node node, const char* name) const;
  float optionalFloat(pugi::xml_node node, const char* name, float fallback) const;
  int64_t requireInt(pugi::xml_node node, const char* name) const;
  int64_t optionalInt(pugi::xml_node node, const char* name, int64_t fallback) const;
  // A count or index: an integer in [0, max].
  uint64_t requireCount(pugi::xml_node node, const char* name, uint64_t max) const;
  uint64_t optionalCount(pugi::xml_node node, const char* name, uint64_t fallback,
                         uint64_t max) const;
  // "1"/"0"/"true"/"false" (any case).
  bool optionalBool(pugi::xml_node node, const char* name, bool fallback) const;
  // Menge's distribution attributes, `prefix` before each name: dist ("c", "u", "n") and value,
  // min/max or mean/stddev, seed.
  Distribution readDistribution(pugi::xml_node node, const std::string& prefix) const;

 private:
  std::filesystem::path source_;
  std::vector<std::string>& warnings_;
  pugi::xml_document document_;
  std::vector<size_t> lineStarts_;  // byte offset of each line's first character
  int lineAt(ptrdiff_t offset) const;
};

// Element children only (comments and text skipped).
std::vector<pugi::xml_node> elements(pugi::xml_node parent);

bool contains(std::span<const std::string_view> names, std::string_view name);
inline bool contains(std::initializer_list<std::string_view> names, std::string_view name) {
  return contains(std::span<const std::string_view>(names.begin(), names.size()), name);
}

}  // namespace throng::menge::detail
