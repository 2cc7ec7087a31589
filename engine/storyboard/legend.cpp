#include "storyboard/legend.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "core/error.h"
#include "core/file_io.h"
#include "storyboard/json_document.h"

namespace throng::storyboard {
namespace {
using Json = JsonDocument;

std::string colourText(Rgba8 c) {
  return concat("(", int(c.r), ",", int(c.g), ",", int(c.b), ")");
}

Rgba8 parseColour(const Json& value, const std::string& where) {
  if (value.is_string()) {
    const std::string text = value.get<std::string>();
    if (text.size() == 7 && text[0] == '#' &&
        std::all_of(text.begin() + 1, text.end(),
                    [](char ch) { return std::isxdigit(uint8_t(ch)); })) {
      unsigned long rgb = std::strtoul(text.c_str() + 1, nullptr, 16);
      return {uint8_t(rgb >> 16), uint8_t(rgb >> 8), uint8_t(rgb), 255};
    }
  } else if (value.is_array() && value.size() == 3 &&
             std::all_of(value.begin(), value.end(), [](const Json& v) {
               return v.is_number_integer() && v.get<int64_t>() >= 0 && v.get<int64_t>() <= 255;
             })) {
    return {uint8_t(value[0].get<int>()), uint8_t(value[1].get<int>()),
            uint8_t(value[2].get<int>()), 255};
  }
  fail(where, ": expected a colour [r,g,b] with integers 0..255 or \"#rrggbb\", got ",
       value.dump());
}

template <size_t N>
void parseNamedColours(const Json& object, const std::string& where,
                       std::string_view (*nameOf)(int), std::array<Rgba8, N>& colours) {
  if (!object.is_object()) fail(where, ": expected an object of name: colour");
  for (const auto& [key, value] : object.items()) {
    size_t index = N;
    for (size_t i = 0; i < N; ++i)
      if (nameOf(int(i)) == key) index = i;
    if (index == N) {
      std::string names;
      for (size_t i = 0; i < N; ++i) names += concat(i ? ", " : "", nameOf(int(i)));
      fail(where, ": unknown name \"", key, "\" (expected one of ", names, ")");
    }
    colours[index] = parseColour(value, concat(where, ".", key));
  }
}

void requireDistinct(std::span<const Rgba8> colours, int tolerance, const std::string& source,
                     std::string_view what) {
  for (size_t i = 0; i < colours.size(); ++i) {
    if (isWhite(colours[i], tolerance))
      fail(source, ": ", what, " colour ", colourText(colours[i]),
           " is indistinguishable from the white background");
    for (size_t j = 0; j < i; ++j)
      if (colourDistance(colours[i], colours[j]) <= tolerance)
        fail(source, ": ", what, " colours ", colourText(colours[j]), " and ",
             colourText(colours[i]), " are within the tolerance ", tolerance,
             " of each other (ambiguous)");
  }
}
Legend legendFrom(const Json& root, const std::string& source);
}  // namespace

Legend parseLegend(std::string_view text, const std::string& source) {
  const Json root = parseJsonDocument(text, source);
  return readJsonDocument(source, [&] { return legendFrom(root, source); });
}

Legend loadLegend(const std::filesystem::path& path) {
  return parseLegend(readTextFile(path), path.string());
}

namespace {
Legend legendFrom(const Json& root, const std::string& source) {
  if (!root.is_object())
    fail(source, ": expected a JSON object with states/actions/groups/tolerance");
  Legend legend;
  for (const auto& [key, value] : root.items()) {
    if (key == "tolerance") {
      if (!value.is_number_integer() || value.get<int64_t>() < 0 ||
          value.get<int64_t>() > kMaxTolerance)
        fail(source, ": tolerance: expected an integer 0..", kMaxTolerance, ", got ", value.dump());
      legend.tolerance = value.get<int>();
    } else if (key == "states") {
      parseNamedColours(
          value, source + ": states", [](int i) { return stateName(State(i)); }, legend.states);
    } else if (key == "actions") {
      parseNamedColours(
          value, source + ": actions", [](int i) { return actionName(Action(i)); }, legend.actions);
    } else if (key == "groups") {
      if (!value.is_array())
        fail(source, ": groups: expected an array of {\"name\": ..., \"colour\": [r,g,b]}");
      for (size_t i = 0; i < value.size(); ++i) {
        const Json& entry = value[i];
        std::string where = concat(source, ": groups[", i, "]");
        if (!entry.is_object() || !entry.contains("colour"))
          fail(where, ": expected {\"name\": ..., \"colour\": [r,g,b]}");
        NamedGroup group;
        group.colour = parseColour(entry["colour"], where + ".colour");
        if (entry.contains("name")) {
          if (!entry["name"].is_string()) fail(where, ".name: expected a string");
          group.name = entry["name"].get<std::string>();
        }
        legend.groups.push_back(group);
      }
    } else {
      fail(source, ": unknown key \"", key, "\" (expected tolerance, states, actions, groups)");
    }
  }
  requireDistinct(legend.states, legend.tolerance, source, "state");
  requireDistinct(legend.actions, legend.tolerance, source, "action");
  std::vector<Rgba8> groupColours;
  for (const NamedGroup& g : legend.groups) groupColours.push_back(g.colour);
  requireDistinct(groupColours, legend.tolerance, source, "group");
  return legend;
}
}  // namespace

int colourDistance(Rgba8 a, Rgba8 b) {
  return std::max({std::abs(int(a.r) - int(b.r)), std::abs(int(a.g) - int(b.g)),
                   std::abs(int(a.b) - int(b.b))});
}

int matchColour(Rgba8 colour, std::span<const Rgba8> palette, int tolerance) {
  int best = -1, bestDistance = tolerance + 1;
  for (size_t i = 0; i < palette.size(); ++i) {
    int d = colourDistance(colour, palette[i]);
    if (d < bestDistance) best = int(i), bestDistance = d;
  }
  return best;
}

Rgba8 flattenOnWhite(Rgba8 c) {
  if (c.a == 255) return c;
  auto mix = [&](uint8_t v) { return uint8_t((int(v) * c.a + 255 * (255 - c.a) + 127) / 255); };
  return {mix(c.r), mix(c.g), mix(c.b), 255};
}

bool isWhite(Rgba8 c, int tolerance) {
  int threshold = 255 - tolerance;
  return c.r >= threshold && c.g >= threshold && c.b >= threshold;
}

namespace {
const std::vector<Rgba8>& palette() {
  static const std::vector<Rgba8> colours = [] {
    // Most distinct first; then the rest of the grid in order.
    std::vector<Rgba8> list = {{0, 0, 255, 255},   {0, 0, 0, 255},       {128, 0, 255, 255},
                               {0, 255, 255, 255}, {128, 128, 128, 255}, {0, 128, 128, 255},
                               {255, 0, 255, 255}, {0, 0, 128, 255},     {128, 0, 0, 255}};
    const Legend defaults;
    for (int r : {0, 128, 255})
      for (int g : {0, 128, 255})
        for (int b : {0, 128, 255}) {
          Rgba8 c{uint8_t(r), uint8_t(g), uint8_t(b), 255};
          bool taken = std::find(list.begin(), list.end(), c) != list.end() ||
                       (r == 255 && g == 255 && b == 255);
          for (Rgba8 s : defaults.states) taken = taken || colourDistance(c, s) == 0;
          for (Rgba8 a : defaults.actions) taken = taken || colourDistance(c, a) == 0;
          if (!taken) list.push_back(c);
        }
    return list;
  }();
  return colours;
}
}  // namespace

int groupPaletteSize() {
  return int(palette().size());
}
Rgba8 paletteColour(int index) {
  return palette().at(size_t(index));
}

Rgba8 groupColour(const Legend& legend, int group) {
  if (group < 0) fail("group ", group, ": group numbers start at 0");
  if (size_t(group) < legend.groups.size()) return legend.groups[size_t(group)].colour;
  // Unnamed groups take palette colours that no named group could be mistaken for.
  int wanted = group - int(legend.groups.size());
  for (Rgba8 candidate : palette()) {
    bool clash = false;
    for (const NamedGroup& named : legend.groups)
      clash = clash || colourDistance(candidate, named.colour) <= 2 * legend.tolerance;
    if (!clash && wanted-- == 0) return candidate;
  }
  fail("group ", group, ": no colour for it (the built-in palette has ", palette().size(),
       " colours); name the group in the legend");
}

}  // namespace throng::storyboard
