#pragma once
// The colour legend of a storyboard: which colours mean which state, action and (named)
// group. The built-in default is exactly docs/formats.md's; a JSON file may redefine any part:
//   {"tolerance": 40,
//    "states":  {"stroll": [255,128,0], "hurried": "#ff0000"},
//    "actions": {"walk": [0,200,0], "run": [255,255,0], "talk": [255,105,180], "jump": [255,0,0]},
//    "groups":  [{"name": "tourists", "colour": [0,0,255]}, ...]}
// Named groups get the numbers 0..n-1 in file order; other bar colours are numbered after
// them by first appearance in reading order.
#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/image.h"
#include "storyboard/glyph.h"

namespace throng::storyboard {

struct NamedGroup {
  std::string name;
  Rgba8 colour;
};

struct Legend {
  std::array<Rgba8, kStateCount> states = {{{255, 128, 0, 255}, {255, 0, 0, 255}}};
  std::array<Rgba8, kActionCount> actions = {
      {{0, 200, 0, 255}, {255, 255, 0, 255}, {255, 105, 180, 255}, {255, 0, 0, 255}}};
  std::vector<NamedGroup> groups;
  // Two colours are "the same" when no channel differs by more than this; a pixel is white
  // when every channel is at least 255 - tolerance.
  int tolerance = 40;
};

inline constexpr int kMaxTolerance = 100;

// Throws Error naming `source` and the offending key when the JSON is malformed.
Legend parseLegend(std::string_view json, const std::string& source);
Legend loadLegend(const std::filesystem::path& path);

// Largest per-channel difference of the RGB channels.
int colourDistance(Rgba8 a, Rgba8 b);
// Index of the nearest colour within `tolerance` (first on ties), or -1.
int matchColour(Rgba8 colour, std::span<const Rgba8> palette, int tolerance);
// Alpha composited over white, so transparent pixels read as background.
Rgba8 flattenOnWhite(Rgba8 colour);
bool isWhite(Rgba8 colour, int tolerance);

// Colour the encoder gives an unnamed group: 23 colours from the {0,128,255}³ grid (minus
// white and the default state/action colours), so any two differ by at least 127 per channel.
int groupPaletteSize();
Rgba8 paletteColour(int index);
// Colour of group `group` under `legend`: a named group's colour, else palette entry
// the (group - named)-th palette colour not near a named one. Throws Error when exhausted.
Rgba8 groupColour(const Legend& legend, int group);

}  // namespace throng::storyboard
