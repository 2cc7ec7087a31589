#include <doctest/doctest.h>

#include <fstream>

#include "core/error.h"
#include "core/rng.h"
#include "storyboard_fixtures.h"
#include "test_support.h"

using namespace throng;
using namespace throng::storyboard;
using throng::test::drawSum;

namespace {
const InvalidGlyph* findInvalid(const Storyboard& s, int x, int y) {
  for (const InvalidGlyph& g : s.invalid)
    if (g.x == x && g.y == y) return &g;
  return nullptr;
}
}  // namespace

TEST_CASE("codec: every heading, state and action decodes from encoded glyphs") {
  std::vector<Glyph> glyphs;
  int group = 0;
  for (int h = 0; h < kHeadingCount; ++h)
    for (int s = 0; s < kStateCount; ++s)
      for (int a = 0; a < kActionCount; ++a)
        glyphs.push_back({2 + 5 * (s * kActionCount + a), 2 + 5 * h, Heading(h), State(s), Action(a), (group++) % 3});
  canonicalizeGroups(glyphs, 0);
  const ImageRgba8 image = encodeStoryboard(42, 42, glyphs, Legend{});
  const Storyboard decoded = decodeStoryboard(image, Legend{});
  CHECK(decoded.width == 42);
  CHECK(decoded.height == 42);
  CHECK(decoded.invalid.empty());
  REQUIRE(decoded.glyphs.size() == 64);
  CHECK(decoded.glyphs == glyphs);
  REQUIRE(decoded.groups.size() == 3);
  CHECK(decoded.groups[0].colour == paletteColour(0));
}

TEST_CASE("codec: random storyboards round-trip") {
  for (uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    ExampleOptions options;
    options.width = 70 + int(seed) * 7;
    options.height = 50;
    options.seed = seed;
    options.groups = int(seed);
    const std::vector<Glyph> glyphs = generateExampleGlyphs(options);
    CHECK(glyphs.size() > 20);
    const Storyboard decoded = decodeStoryboard(encodeStoryboard(options.width, 50, glyphs, Legend{}), Legend{});
    CHECK(decoded.invalid.empty());
    CHECK(decoded.glyphs == glyphs);
  }
}

TEST_CASE("codec: axis-aligned glyphs are found by shape, not by their 3x2 bounding box") {
  ImageRgba8 image(20, 20, test::kWhite);
  drawSum(image, 5, 5, 26, test::kOrange, test::kBlue);   // Top: bounding box 3 wide, 2 tall
  image.at(5, 4) = test::kGreen;                           // the pointer is the action
  const Storyboard s = decodeStoryboard(image, Legend{});
  REQUIRE(s.glyphs.size() == 1);
  CHECK(s.glyphs[0] == Glyph{5, 5, Heading::Top, State::Stroll, Action::Walk, 0});
}

TEST_CASE("codec: a drawn centre with a non-T sum never decodes as a glyph there") {
  int valid = 0;
  for (int sum = 0; sum < 256; ++sum) {
    if (__builtin_popcount(unsigned(sum)) != 3) continue;
    ImageRgba8 image(9, 9, test::kWhite);
    drawSum(image, 4, 4, sum, test::kRed, test::kGreen);
    const Storyboard s = decodeStoryboard(image, Legend{});
    const bool decodedHere = s.glyphs.size() == 1 && s.glyphs[0].x == 4 && s.glyphs[0].y == 4;
    CAPTURE(sum);
    CHECK(decodedHere == headingFromSum(sum).has_value());
    valid += decodedHere;
  }
  CHECK(valid == 8);
}

TEST_CASE("codec: each kind of invalid component is reported with its pixel and reason") {
  ImageRgba8 image(60, 30, test::kWhite);
  drawSum(image, 5, 5, 1 + 4 + 64, test::kOrange, test::kBlue);  // TL, TR, B: no T
  drawSum(image, 15, 5, 88, Rgba8{12, 34, 56, 255}, test::kBlue);
  drawSum(image, 25, 5, 88, test::kOrange, test::kBlue);
  image.at(25, 6) = Rgba8{90, 90, 250, 255};  // pointer of the Down glyph: no action colour
  drawSum(image, 35, 5, 88, test::kOrange, test::kBlue);
  image.at(35, 6) = test::kGreen;
  image.at(34, 5) = Rgba8{0, 0, 0, 255};      // one bar pixel black, the other blue
  // Two glyphs whose cells touch merge into one component of 8 pixels.
  drawSum(image, 45, 5, 88, test::kOrange, test::kBlue);
  drawSum(image, 48, 5, 88, test::kOrange, test::kBlue);
  image.at(7, 20) = test::kRed;                                   // a stray pixel
  for (int x = 20; x < 24; ++x) image.at(x, 20) = test::kBlue;   // a line: no centre
  drawSum(image, 40, 20, 82, test::kRed, test::kBlue);           // one valid glyph (Right)
  image.at(41, 20) = Rgba8{255, 255, 0, 255};

  const Storyboard s = decodeStoryboard(image, Legend{});
  REQUIRE(s.glyphs.size() == 1);
  CHECK(s.glyphs[0] == Glyph{40, 20, Heading::Right, State::Hurried, Action::Run, 0});
  REQUIRE(s.invalid.size() == 7);
  auto reason = [&](int x, int y) {
    const InvalidGlyph* g = findInvalid(s, x, y);
    return g ? g->reason : std::string("<not reported at this pixel>");
  };
  CHECK(reason(5, 5) == "sum 69 is not a T glyph");
  CHECK(reason(15, 5) == "unknown state colour (12,34,56)");
  CHECK(reason(25, 5) == "unknown action colour (90,90,250)");
  CHECK(reason(35, 5).rfind("bar pixels differ in colour", 0) == 0);
  CHECK(reason(44, 5) == "component of 8 pixels (touching glyphs?)");  // bounding-box top-left
  CHECK(reason(7, 20) == "component of 1 pixel (a glyph has 4)");
  CHECK(reason(20, 20).find("no centre pixel") != std::string::npos);
  // Reported in reading order.
  CHECK(s.invalid.front().y == 5);
  CHECK(s.invalid.back().y == 20);
}

TEST_CASE("codec: transparent pixels read as white background") {
  const ImageRgba8 opaque = test::exampleStoryboard(40, 3);
  ImageRgba8 transparent = opaque;
  for (Rgba8& p : transparent.pixels)
    if (p == test::kWhite) p = Rgba8{0, 0, 0, 0};
  const Storyboard a = decodeStoryboard(opaque, Legend{}), b = decodeStoryboard(transparent, Legend{});
  CHECK(b.invalid.empty());
  CHECK(a.glyphs == b.glyphs);
}

TEST_CASE("codec: near colours match within the tolerance") {
  auto draw = [](int shift) {
    ImageRgba8 image(12, 7, test::kWhite);
    auto near = [&](Rgba8 c) {
      auto move = [&](uint8_t v) { return uint8_t(v > 127 ? v - shift : v + shift); };
      return Rgba8{move(c.r), move(c.g), move(c.b), 255};
    };
    drawSum(image, 3, 3, 88, near(test::kOrange), near(test::kBlue));
    image.at(3, 4) = near(test::kGreen);
    drawSum(image, 8, 3, 88, test::kOrange, test::kBlue);  // exact colours: same group
    image.at(8, 4) = test::kGreen;
    return image;
  };
  Legend legend;  // tolerance 40
  Storyboard s = decodeStoryboard(draw(30), legend);
  CHECK(s.invalid.empty());
  REQUIRE(s.glyphs.size() == 2);
  CHECK(s.glyphs[0] == Glyph{3, 3, Heading::Down, State::Stroll, Action::Walk, 0});
  CHECK(s.glyphs[1].group == 0);

  s = decodeStoryboard(draw(50), legend);
  REQUIRE(s.invalid.size() == 1);
  CHECK(s.invalid[0].reason == "unknown state colour (205,78,50)");

  legend.tolerance = 10;
  s = decodeStoryboard(draw(30), legend);
  REQUIRE(s.invalid.size() == 1);
  CHECK(s.invalid[0].reason.rfind("unknown state colour", 0) == 0);
}

TEST_CASE("codec: groups are numbered by first appearance in reading order") {
  ImageRgba8 image(30, 12, test::kWhite);
  const Rgba8 purple{128, 0, 255, 255}, black{0, 0, 0, 255};
  drawSum(image, 20, 2, 88, test::kOrange, purple);  // first in reading order
  drawSum(image, 3, 6, 88, test::kOrange, black);
  drawSum(image, 12, 8, 88, test::kOrange, Rgba8{140, 10, 240, 255});  // near purple
  for (int x : {20, 3, 12}) image.at(x, x == 20 ? 3 : x == 3 ? 7 : 9) = test::kGreen;
  const Storyboard s = decodeStoryboard(image, Legend{});
  CHECK(s.invalid.empty());
  REQUIRE(s.glyphs.size() == 3);
  CHECK(s.glyphs[0].group == 0);
  CHECK(s.glyphs[1].group == 1);
  CHECK(s.glyphs[2].group == 0);
  REQUIRE(s.groups.size() == 2);
  CHECK(s.groups[0].colour == purple);
}

TEST_CASE("codec: the encoder refuses glyphs that leave the image or touch") {
  const Legend legend;
  std::vector<Glyph> glyphs = {{0, 5, Heading::Down, State::Stroll, Action::Walk, 0}};
  CHECK_THROWS_AS(encodeStoryboard(10, 10, glyphs, legend), Error);
  glyphs = {{3, 3, Heading::Down, State::Stroll, Action::Walk, 0}, {5, 5, Heading::Top, State::Stroll, Action::Walk, 0}};
  CHECK_THROWS_WITH_AS(encodeStoryboard(10, 10, glyphs, legend), doctest::Contains("touch"), Error);
  // Cells one pixel apart never touch.
  glyphs[1] = {7, 3, Heading::Down, State::Stroll, Action::Walk, 0};
  CHECK(decodeStoryboard(encodeStoryboard(10, 10, glyphs, legend), legend).glyphs.size() == 2);
  glyphs[1].group = 1000;
  CHECK_THROWS_WITH_AS(encodeStoryboard(10, 10, glyphs, legend), doctest::Contains("legend"), Error);
}

TEST_CASE("codec: --strict lists the invalid glyphs; unreadable PNGs name the file") {
  test::TempDir dir("throng-codec");
  ImageRgba8 image(20, 20, test::kWhite);
  drawSum(image, 5, 5, 1 + 4 + 64, test::kOrange, test::kBlue);
  const auto file = dir.path / "broken.png";
  writePngAtomic(file, image);
  CHECK(readStoryboard(file, Legend{}, false).invalid.size() == 1);
  CHECK_THROWS_WITH_AS(readStoryboard(file, Legend{}, true),
                       doctest::Contains("pixel (5,5): sum 69 is not a T glyph"), Error);

  const auto garbage = dir.path / "garbage.png";
  std::ofstream(garbage) << "this is not a PNG";
  CHECK_THROWS_WITH_AS(readStoryboard(garbage, Legend{}, false), doctest::Contains("garbage.png"), Error);
  CHECK_THROWS_WITH_AS(readStoryboard(dir.path / "missing.png", Legend{}, false),
                       doctest::Contains("missing.png"), Error);
}

TEST_CASE("codec: noise decodes without failing and every glyph found is a real T") {
  Rng rng(17);
  for (int round = 0; round < 20; ++round) {
    ImageRgba8 image(64, 48, test::kWhite);
    const float ink = 0.02f + 0.03f * float(round);
    const Rgba8 colours[] = {test::kOrange, test::kRed, test::kGreen, test::kBlue, Rgba8{255, 255, 0, 255},
                             Rgba8{uint8_t(rng.next()), uint8_t(rng.next()), uint8_t(rng.next()), uint8_t(rng.next())}};
    for (Rgba8& p : image.pixels)
      if (rng.uniform() < ink) p = colours[rng.next() % 6];
    const Storyboard s = decodeStoryboard(image, Legend{});
    CHECK(s.glyphs.size() + s.invalid.size() > 0);
    for (const Glyph& g : s.glyphs) {
      const ImageRgba8 alone = encodeStoryboard(64, 48, std::vector<Glyph>{Glyph{g.x, g.y, g.heading, g.state, g.action, 0}}, Legend{});
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          CHECK(isWhite(flattenOnWhite(image.at(g.x + dx, g.y + dy)), 40) == (alone.at(g.x + dx, g.y + dy) == test::kWhite));
    }
  }
}
