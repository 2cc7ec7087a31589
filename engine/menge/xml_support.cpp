#include "menge/xml_support.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace throng::menge::detail {

namespace {

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
    text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    text.remove_suffix(1);
  return text;
}

bool parseFloat(std::string_view text, float& out) {
  text = trimmed(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
}

bool parseInt(std::string_view text, int64_t& out) {
  text = trimmed(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

XmlDocument::XmlDocument(std::string_view text, const std::filesystem::path& source,
                         std::vector<std::string>& warnings)
    : source_(source), warnings_(warnings) {
  lineStarts_.push_back(0);
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') lineStarts_.push_back(i + 1);
  }
  const pugi::xml_parse_result result =
      document_.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!result) {
    throng::fail(source_.string(), ":", lineAt(result.offset),
                 ": malformed XML: ", result.description());
  }
}

int XmlDocument::lineAt(ptrdiff_t offset) const {
  if (offset < 0) return 1;
  const auto next =
      std::upper_bound(lineStarts_.begin(), lineStarts_.end(), static_cast<size_t>(offset));
  return static_cast<int>(next - lineStarts_.begin());
}

int XmlDocument::line(pugi::xml_node node) const {
  return lineAt(node.offset_debug());
}

pugi::xml_node XmlDocument::root(std::string_view name) const {
  const pugi::xml_node element = document_.document_element();
  if (!element) throng::fail(source_.string(), ":1: expected a <", name, "> element");
  if (name != element.name()) fail(element, "expected <", name, "> as the document element");
  return element;
}

std::filesystem::path XmlDocument::resolve(const std::string& fileName) const {
  return (source_.parent_path() / fileName).lexically_normal();
}

std::string XmlDocument::where(pugi::xml_node node) const {
  std::string text = concat(source_.string(), ":", line(node), ": <", node.name());
  if (const pugi::xml_attribute type = node.attribute("type")) {
    text += concat(" type=\"", type.value(), "\"");
  }
  return text + ">";
}

void XmlDocument::checkAttributes(pugi::xml_node node,
                                  std::initializer_list<std::string_view> known) const {
  for (const pugi::xml_attribute attribute : node.attributes()) {
    if (!contains(known, attribute.name())) {
      warn(node, "attribute '", attribute.name(), "' is not supported and was ignored");
    }
  }
}

std::string XmlDocument::requireString(pugi::xml_node node, const char* name) const {
  const pugi::xml_attribute attribute = node.attribute(name);
  if (!attribute) fail(node, "expected a '", name, "' attribute");
  return attribute.value();
}

float XmlDocument::requireFloat(pugi::xml_node node, const char* name) const {
  const pugi::xml_attribute attribute = node.attribute(name);
  if (!attribute) fail(node, "expected a '", name, "' attribute (a number)");
  float value = 0.0f;
  if (!parseFloat(attribute.value(), value)) {
    fail(node, "expected '", name, "' to be a finite number, got \"", attribute.value(), "\"");
  }
  return value;
}

float XmlDocument::optionalFloat(pugi::xml_node node, const char* name, float fallback) const {
  return node.attribute(name) ? requireFloat(node, name) : fallback;
}

int64_t XmlDocument::requireInt(pugi::xml_node node, const char* name) const {
  const pugi::xml_attribute attribute = node.attribute(name);
  if (!attribute) fail(node, "expected a '", name, "' attribute (an integer)");
  int64_t value = 0;
  if (!parseInt(attribute.value(), value)) {
    fail(node, "expected '", name, "' to be an integer, got \"", attribute.value(), "\"");
  }
  return value;
}

int64_t XmlDocument::optionalInt(pugi::xml_node node, const char* name, int64_t fallback) const {
  return node.attribute(name) ? requireInt(node, name) : fallback;
}

uint64_t XmlDocument::requireCount(pugi::xml_node node, const char* name, uint64_t max) const {
  const int64_t value = requireInt(node, name);
  if (value < 0 || static_cast<uint64_t>(value) > max) {
    fail(node, "expected '", name, "' in [0, ", max, "], got ", value);
  }
  return static_cast<uint64_t>(value);
}

uint64_t XmlDocument::optionalCount(pugi::xml_node node, const char* name, uint64_t fallback,
                                    uint64_t max) const {
  return node.attribute(name) ? requireCount(node, name, max) : fallback;
}

bool XmlDocument::optionalBool(pugi::xml_node node, const char* name, bool fallback) const {
  const pugi::xml_attribute attribute = node.attribute(name);
  if (!attribute) return fallback;
  std::string value(trimmed(attribute.value()));
  std::transform(value.begin(), value.end(), value.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (value == "1" || value == "true") return true;
  if (value == "0" || value == "false") return false;
  fail(node, "expected '", name, "' to be 1, 0, true or false, got \"", attribute.value(), "\"");
}

Distribution XmlDocument::readDistribution(pugi::xml_node node, const std::string& prefix) const {
  const std::string dist = requireString(node, (prefix + "dist").c_str());
  const auto number = [&](const char* name) { return requireFloat(node, (prefix + name).c_str()); };
  Distribution out;
  if (dist == "c") {
    out.kind = Distribution::Kind::Constant;
    out.value = number("value");
  } else if (dist == "u") {
    out.kind = Distribution::Kind::Uniform;
    out.min = number("min");
    out.max = number("max");
    if (out.min > out.max) fail(node, "expected ", prefix, "min <= ", prefix, "max");
  } else if (dist == "n") {
    out.kind = Distribution::Kind::Normal;
    out.mean = number("mean");
    out.stddev = number("stddev");
    if (out.stddev < 0.0f) fail(node, "expected ", prefix, "stddev >= 0");
  } else {
    fail(node, "expected ", prefix, "dist to be c, u or n, got \"", dist, "\"");
  }
  const std::string seedName = prefix + "seed";
  if (node.attribute(seedName.c_str())) {
    out.hasSeed = true;
    out.seed = static_cast<uint32_t>(requireCount(node, seedName.c_str(), UINT32_MAX));
  }
  return out;
}

std::vector<pugi::xml_node> elements(pugi::xml_node parent) {
  std::vector<pugi::xml_node> out;
  for (const pugi::xml_node child : parent.children()) {
    if (child.type() == pugi::node_element) out.push_back(child);
  }
  return out;
}

bool contains(std::span<const std::string_view> names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace throng::menge::detail
