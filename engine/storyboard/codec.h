#pragma once
// Storyboard PNG <-> glyphs. Glyphs are the 8-connected components of non-white pixels (no
// grid is assumed). A component is one valid glyph when it has exactly 4 pixels, one of them
// (the centre) touches the other three and their reading-order code sum is a T heading, the
// centre and pointer colours are legend state/action colours and both bar pixels share one
// colour. Axis-aligned T's have a 3×2 bounding box, so the centre is found by shape, not as
// the bounding box's middle. Everything else is reported as invalid: at the centre pixel when
// one was found, otherwise at the component's bounding-box top-left.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/image.h"
#include "storyboard/glyph.h"
#include "storyboard/legend.h"

namespace throng::storyboard {

struct InvalidGlyph {
  int x = 0, y = 0;
  std::string reason;
  friend bool operator==(const InvalidGlyph&, const InvalidGlyph&) = default;
};

struct GroupInfo {
  Rgba8 colour;
  std::string name;  // empty unless the legend names it
};

struct Storyboard {
  int width = 0, height = 0;
  std::vector<Glyph> glyphs;          // reading order of centres (y, then x)
  std::vector<InvalidGlyph> invalid;  // reading order of positions
  std::vector<GroupInfo> groups;      // indexed by group number
};

Storyboard decodeStoryboard(const ImageRgba8& image, const Legend& legend);
// Reads and decodes a PNG; with `strict`, any invalid glyph is an Error listing them.
Storyboard readStoryboard(const std::filesystem::path& path, const Legend& legend, bool strict);
// Throws Error naming `source` and listing the invalid glyphs, if any.
void requireAllValid(const Storyboard& storyboard, const std::string& source);

// Glyphs on a white background. Throws Error when a cell leaves the image, two glyphs would
// touch (they would merge into one component) or the image would exceed kMaxStoryboardPixels.
inline constexpr long kMaxStoryboardPixels = 100'000'000;
ImageRgba8 encodeStoryboard(int width, int height, std::span<const Glyph> glyphs, const Legend& legend);

// Sorts into reading order and renumbers the groups not named by the legend (numbers >=
// namedGroups) by first appearance, as the decoder numbers them; then
// decode(encode(g)) == g.
void canonicalizeGroups(std::vector<Glyph>& glyphs, int namedGroups);

// Pixel offsets of a glyph's 4 pixels: centre, pointer, bar[0], bar[1].
std::array<Offset, 4> glyphPixels(Heading heading);

}  // namespace throng::storyboard
