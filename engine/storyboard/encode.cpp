#include <algorithm>
#include <map>

#include "core/error.h"
#include "storyboard/codec.h"

namespace throng::storyboard {

std::array<Offset, 4> glyphPixels(Heading heading) {
  const HeadingShape& shape = shapeOf(heading);
  return {Offset{0, 0}, shape.pointer, shape.bar[0], shape.bar[1]};
}

ImageRgba8 encodeStoryboard(int width, int height, std::span<const Glyph> glyphs, const Legend& legend) {
  if (width < 3 || height < 3 || long(width) * height > kMaxStoryboardPixels)
    fail("storyboard of ", width, "x", height, " pixels: expected at least 3x3 and at most ", kMaxStoryboardPixels,
         " pixels");
  ImageRgba8 image(width, height, Rgba8{255, 255, 255, 255});
  std::vector<int> owner(size_t(width) * height, -1);
  for (size_t i = 0; i < glyphs.size(); ++i) {
    const Glyph& g = glyphs[i];
    if (g.x < 1 || g.y < 1 || g.x > width - 2 || g.y > height - 2)
      fail("glyph ", i, " at (", g.x, ",", g.y, "): its 3x3 cell leaves the ", width, "x", height, " image");
    if (int(g.heading) >= kHeadingCount || int(g.state) >= kStateCount || int(g.action) >= kActionCount)
      fail("glyph ", i, " at (", g.x, ",", g.y, "): heading/state/action out of range");
    const std::array<Offset, 4> offsets = glyphPixels(g.heading);
    const Rgba8 bar = groupColour(legend, g.group);
    const std::array<Rgba8, 4> colours = {legend.states[int(g.state)], legend.actions[int(g.action)], bar, bar};
    for (int k = 0; k < 4; ++k) {
      int x = g.x + offsets[k].dx, y = g.y + offsets[k].dy;
      // 8-neighbours owned by another glyph would merge both into one component.
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          int other = owner[size_t(ny) * width + nx];
          if (other >= 0 && other != int(i))
            fail("glyphs at (", glyphs[other].x, ",", glyphs[other].y, ") and (", g.x, ",", g.y,
                 ") touch: they would merge into one component");
        }
      owner[size_t(y) * width + x] = int(i);
      image.at(x, y) = colours[k];
    }
  }
  return image;
}

void canonicalizeGroups(std::vector<Glyph>& glyphs, int namedGroups) {
  std::stable_sort(glyphs.begin(), glyphs.end(),
                   [](const Glyph& a, const Glyph& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  std::map<int, int> renumber;
  for (Glyph& g : glyphs) {
    if (g.group < namedGroups) continue;
    auto [it, inserted] = renumber.try_emplace(g.group, namedGroups + int(renumber.size()));
    g.group = it->second;
  }
}

}  // namespace throng::storyboard
