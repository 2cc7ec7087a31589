#include "storyboard/codec.h"

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <optional>

#include "core/error.h"

namespace throng::storyboard {
namespace {

struct Pixel {
  int x, y;
};

std::string colourText(Rgba8 c) { return concat("(", int(c.r), ",", int(c.g), ",", int(c.b), ")"); }

struct Component {
  std::vector<Pixel> pixels;
  int minX = INT_MAX, minY = INT_MAX, maxX = INT_MIN, maxY = INT_MIN;
};

// A glyph before group numbering: groups depend on reading order over all glyphs.
struct Pending {
  Glyph glyph;
  Rgba8 barColour;
};

std::vector<Component> findComponents(const ImageRgba8& image, const std::vector<Rgba8>& flat, int tolerance) {
  const int w = image.width, h = image.height;
  std::vector<uint8_t> ink(flat.size());
  for (size_t i = 0; i < flat.size(); ++i) ink[i] = !isWhite(flat[i], tolerance);
  std::vector<Component> components;
  std::vector<Pixel> stack;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!ink[size_t(y) * w + x]) continue;
      Component c;
      ink[size_t(y) * w + x] = 0;
      stack.push_back({x, y});
      while (!stack.empty()) {
        Pixel p = stack.back();
        stack.pop_back();
        c.pixels.push_back(p);
        c.minX = std::min(c.minX, p.x), c.maxX = std::max(c.maxX, p.x);
        c.minY = std::min(c.minY, p.y), c.maxY = std::max(c.maxY, p.y);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            int nx = p.x + dx, ny = p.y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h || !ink[size_t(ny) * w + nx]) continue;
            ink[size_t(ny) * w + nx] = 0;
            stack.push_back({nx, ny});
          }
      }
      components.push_back(std::move(c));
    }
  return components;
}

int outerSum(const Component& c, Pixel centre) {
  int sum = 0;
  for (Pixel p : c.pixels) sum += outerCode(p.x - centre.x, p.y - centre.y);
  return sum;
}

// Either a pending glyph or an invalid report.
std::optional<Pending> classify(const Component& c, const std::vector<Rgba8>& flat, int width,
                                const Legend& legend, std::vector<InvalidGlyph>& invalid) {
  auto report = [&](int x, int y, std::string reason) {
    invalid.push_back({x, y, std::move(reason)});
    return std::nullopt;
  };
  const int n = int(c.pixels.size());
  if (n > 4) return report(c.minX, c.minY, concat("component of ", n, " pixels (touching glyphs?)"));
  if (n < 4) return report(c.minX, c.minY, concat("component of ", n, n == 1 ? " pixel" : " pixels", " (a glyph has 4)"));
  std::vector<Pixel> centres;  // pixels touching all others, in reading order
  for (Pixel p : c.pixels) {
    bool touchesAll = true;
    for (Pixel q : c.pixels) touchesAll = touchesAll && std::abs(q.x - p.x) <= 1 && std::abs(q.y - p.y) <= 1;
    if (touchesAll) centres.push_back(p);
  }
  std::sort(centres.begin(), centres.end(), [](Pixel a, Pixel b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  if (centres.empty())
    return report(c.minX, c.minY, concat("component of 4 pixels spanning ", c.maxX - c.minX + 1, "x",
                                         c.maxY - c.minY + 1, " has no centre pixel (not a T glyph)"));
  std::optional<Heading> heading;
  Pixel centre = centres.front();
  for (Pixel p : centres)
    if ((heading = headingFromSum(outerSum(c, p)))) {
      centre = p;
      break;
    }
  if (!heading) {
    // Report at the candidate nearest the bounding box's middle: where a person drew it.
    auto offMiddle = [&](Pixel p) { return std::abs(2 * p.x - c.minX - c.maxX) + std::abs(2 * p.y - c.minY - c.maxY); };
    for (Pixel p : centres)
      if (offMiddle(p) < offMiddle(centre)) centre = p;
    return report(centre.x, centre.y, concat("sum ", outerSum(c, centre), " is not a T glyph"));
  }
  auto colourAt = [&](Offset o) { return flat[size_t(centre.y + o.dy) * width + centre.x + o.dx]; };
  const HeadingShape& shape = shapeOf(*heading);
  Rgba8 centreColour = colourAt({0, 0}), pointerColour = colourAt(shape.pointer);
  Rgba8 bar0 = colourAt(shape.bar[0]), bar1 = colourAt(shape.bar[1]);
  int state = matchColour(centreColour, legend.states, legend.tolerance);
  if (state < 0) return report(centre.x, centre.y, concat("unknown state colour ", colourText(centreColour)));
  int action = matchColour(pointerColour, legend.actions, legend.tolerance);
  if (action < 0) return report(centre.x, centre.y, concat("unknown action colour ", colourText(pointerColour)));
  if (colourDistance(bar0, bar1) > legend.tolerance)
    return report(centre.x, centre.y,
                  concat("bar pixels differ in colour ", colourText(bar0), " vs ", colourText(bar1)));
  Pending pending;
  pending.glyph = {centre.x, centre.y, *heading, State(state), Action(action), 0};
  pending.barColour = bar0;
  return pending;
}

template <typename T>
void sortReadingOrder(std::vector<T>& items, auto position) {
  std::stable_sort(items.begin(), items.end(), [&](const T& a, const T& b) {
    auto [ax, ay] = position(a);
    auto [bx, by] = position(b);
    return ay != by ? ay < by : ax < bx;
  });
}

}  // namespace

Storyboard decodeStoryboard(const ImageRgba8& image, const Legend& legend) {
  Storyboard result;
  result.width = image.width;
  result.height = image.height;
  std::vector<Rgba8> flat(image.pixels.size());
  std::transform(image.pixels.begin(), image.pixels.end(), flat.begin(), flattenOnWhite);

  std::vector<Pending> pending;
  for (const Component& c : findComponents(image, flat, legend.tolerance))
    if (auto p = classify(c, flat, image.width, legend, result.invalid)) pending.push_back(*p);
  sortReadingOrder(pending, [](const Pending& p) { return std::pair{p.glyph.x, p.glyph.y}; });
  sortReadingOrder(result.invalid, [](const InvalidGlyph& g) { return std::pair{g.x, g.y}; });

  for (const NamedGroup& g : legend.groups) result.groups.push_back({g.colour, g.name});
  std::vector<Rgba8> namedColours, seenColours;
  for (const NamedGroup& g : legend.groups) namedColours.push_back(g.colour);
  for (Pending& p : pending) {
    int group = matchColour(p.barColour, namedColours, legend.tolerance);
    if (group < 0) {
      int seen = matchColour(p.barColour, seenColours, legend.tolerance);
      if (seen < 0) {
        seen = int(seenColours.size());
        seenColours.push_back(p.barColour);
        result.groups.push_back({p.barColour, {}});
      }
      group = int(namedColours.size()) + seen;
    }
    p.glyph.group = group;
    result.glyphs.push_back(p.glyph);
  }
  return result;
}

void requireAllValid(const Storyboard& storyboard, const std::string& source) {
  if (storyboard.invalid.empty()) return;
  std::string list;
  const size_t shown = std::min<size_t>(storyboard.invalid.size(), 20);
  for (size_t i = 0; i < shown; ++i) {
    const InvalidGlyph& g = storyboard.invalid[i];
    list += concat("\n  pixel (", g.x, ",", g.y, "): ", g.reason);
  }
  if (shown < storyboard.invalid.size()) list += concat("\n  ... and ", storyboard.invalid.size() - shown, " more");
  fail(source, ": ", storyboard.invalid.size(), " invalid glyph", storyboard.invalid.size() == 1 ? "" : "s",
       " (expected T glyphs of 4 pixels as in the legend):", list);
}

Storyboard readStoryboard(const std::filesystem::path& path, const Legend& legend, bool strict) {
  Storyboard storyboard = decodeStoryboard(readPng(path), legend);
  if (strict) requireAllValid(storyboard, path.string());
  return storyboard;
}

}  // namespace throng::storyboard
