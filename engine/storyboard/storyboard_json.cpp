#include "storyboard/storyboard_json.h"

#include "core/error.h"
#include "storyboard/json_document.h"

namespace throng::storyboard {
namespace {
using Json = JsonDocument;
constexpr int64_t kLimit = 1'000'000;
constexpr const char* kStoryboardSchema = "throng.storyboard";

int intField(const Json& object, const char* key, const std::string& where) {
  if (!object.contains(key) || !object[key].is_number_integer() ||
      (object[key].is_number_unsigned() && object[key].get<uint64_t>() > uint64_t(kLimit)) ||
      object[key].get<int64_t>() < -kLimit || object[key].get<int64_t>() > kLimit)
    fail(where, ": expected an integer \"", key, "\" within +-", kLimit);
  return object[key].get<int>();
}

std::string stringField(const Json& object, const char* key, const std::string& where) {
  if (!object.contains(key) || !object[key].is_string())
    fail(where, ": expected a string \"", key, "\"");
  return object[key].get<std::string>();
}
Storyboard storyboardFrom(const Json& root, const std::string& source);
}  // namespace

std::string storyboardToJson(const Storyboard& storyboard) {
  Json root;
  root["schema"] = kStoryboardSchema;
  root["version"] = 1;
  root["width"] = storyboard.width;
  root["height"] = storyboard.height;
  Json agents = Json::array();
  for (const Glyph& g : storyboard.glyphs) {
    Json a;
    a["x"] = g.x;
    a["y"] = g.y;
    a["heading"] = headingName(g.heading);
    a["state"] = stateName(g.state);
    a["action"] = actionName(g.action);
    a["group"] = g.group;
    agents.push_back(std::move(a));
  }
  root["agents"] = std::move(agents);
  Json invalid = Json::array();
  for (const InvalidGlyph& g : storyboard.invalid)
    invalid.push_back(Json{{"x", g.x}, {"y", g.y}, {"reason", g.reason}});
  root["invalid"] = std::move(invalid);
  return root.dump();
}

Storyboard storyboardFromJson(std::string_view text, const std::string& source) {
  const Json root = parseJsonDocument(text, source);
  return readJsonDocument(source, [&] { return storyboardFrom(root, source); });
}

namespace {
Storyboard storyboardFrom(const Json& root, const std::string& source) {
  if (!root.is_object()) fail(source, ": expected an object {\"width\", \"height\", \"agents\"}");
  // Files written before the schema was added have neither key; a file that names another
  // document or version is refused rather than misread.
  if (root.contains("schema") &&
      (!root["schema"].is_string() || root["schema"].get<std::string>() != kStoryboardSchema))
    fail(source, ": expected \"schema\": \"", kStoryboardSchema, "\" (agents of a storyboard)");
  if (root.contains("version") &&
      (!root["version"].is_number_integer() || root["version"].get<int64_t>() != 1))
    fail(source, ": expected \"version\": 1");
  Storyboard storyboard;
  storyboard.width = intField(root, "width", source);
  storyboard.height = intField(root, "height", source);
  if (!root.contains("agents") || !root["agents"].is_array())
    fail(source, ": expected an array \"agents\"");
  for (size_t i = 0; i < root["agents"].size(); ++i) {
    const Json& a = root["agents"][i];
    std::string where = concat(source, ": agents[", i, "]");
    if (!a.is_object()) fail(where, ": expected an object");
    Glyph g;
    g.x = intField(a, "x", where);
    g.y = intField(a, "y", where);
    std::string heading = stringField(a, "heading", where), state = stringField(a, "state", where),
                action = stringField(a, "action", where);
    auto h = parseHeading(heading);
    if (!h)
      fail(where, ": heading \"", heading,
           "\" (expected Top, Left, Down, Right, TopLeft, TopRight, LeftDown, RightDown)");
    auto s = parseState(state);
    if (!s) fail(where, ": state \"", state, "\" (expected stroll or hurried)");
    auto act = parseAction(action);
    if (!act) fail(where, ": action \"", action, "\" (expected walk, run, talk or jump)");
    g.heading = *h, g.state = *s, g.action = *act;
    g.group = a.contains("group") ? intField(a, "group", where) : 0;
    if (g.group < 0) fail(where, ": group must be >= 0");
    storyboard.glyphs.push_back(g);
  }
  return storyboard;
}

}  // namespace

}  // namespace throng::storyboard
