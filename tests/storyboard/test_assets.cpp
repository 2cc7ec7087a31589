// The committed storyboard assets are what their documented commands make.
#include <doctest/doctest.h>

#include "storyboard_fixtures.h"
#include "test_support.h"

using namespace throng;
using namespace throng::storyboard;

TEST_CASE("assets: plaza_small.png is `throng storyboard example --size 90x90 --seed 7`") {
  const ImageRgba8 committed = readPng(test::sourceDir() / "assets/storyboards/plaza_small.png");
  CHECK(committed.pixels == test::exampleStoryboard(90, 7).pixels);
  const Storyboard s = decodeStoryboard(committed, Legend{});
  CHECK(s.invalid.empty());
  CHECK(s.glyphs.size() == 81);
}

TEST_CASE("assets: legend_example.json names two groups over the default colours") {
  const Legend legend = loadLegend(test::sourceDir() / "assets/storyboards/legend_example.json");
  const Legend defaults;
  CHECK(legend.states == defaults.states);
  CHECK(legend.actions == defaults.actions);
  REQUIRE(legend.groups.size() == 2);
  CHECK(legend.groups[1].name == "commuters");
  const Storyboard s = decodeStoryboard(readPng(test::sourceDir() / "assets/storyboards/plaza_small.png"), legend);
  CHECK(s.groups[0].name == "tourists");  // blue
  CHECK(s.groups[1].name == "commuters"); // black
  CHECK(s.glyphs.size() == 81);
}
