#include <doctest/doctest.h>

#include <fstream>

#include "core/error.h"
#include "storyboard_fixtures.h"

using namespace throng;
using namespace throng::storyboard;
using throng::test::drawSum;

TEST_CASE("legend: the default is exactly docs/formats.md's") {
  const Legend legend;
  CHECK(legend.states[int(State::Stroll)] == Rgba8{255, 128, 0, 255});
  CHECK(legend.states[int(State::Hurried)] == Rgba8{255, 0, 0, 255});
  CHECK(legend.actions[int(Action::Walk)] == Rgba8{0, 200, 0, 255});
  CHECK(legend.actions[int(Action::Run)] == Rgba8{255, 255, 0, 255});
  CHECK(legend.actions[int(Action::Talk)] == Rgba8{255, 105, 180, 255});
  CHECK(legend.actions[int(Action::Jump)] == Rgba8{255, 0, 0, 255});
  CHECK(legend.groups.empty());
  const Legend parsed = parseLegend("{}", "empty.json");
  CHECK(parsed.states == legend.states);
  CHECK(parsed.actions == legend.actions);
  CHECK(parsed.tolerance == legend.tolerance);
}

TEST_CASE("legend: overrides change what colours mean") {
  const Legend legend = parseLegend(R"({
      "tolerance": 20,
      "states": {"stroll": [0, 0, 0], "hurried": "#808080"},
      "actions": {"talk": [0, 128, 255]},
      "groups": [{"name": "tourists", "colour": [0, 0, 255]}, {"name": "guides", "colour": "#ff00ff"}]})",
                                    "legend.json");
  CHECK(legend.tolerance == 20);
  CHECK(legend.states[1] == Rgba8{128, 128, 128, 255});
  CHECK(legend.actions[int(Action::Talk)] == Rgba8{0, 128, 255, 255});
  CHECK(legend.actions[int(Action::Walk)] == Rgba8{0, 200, 0, 255});  // untouched

  ImageRgba8 image(20, 7, test::kWhite);
  drawSum(image, 3, 3, 88, Rgba8{0, 0, 0, 255}, Rgba8{0, 200, 200, 255});  // unnamed group
  image.at(3, 4) = Rgba8{0, 128, 255, 255};
  drawSum(image, 9, 3, 88, Rgba8{128, 128, 128, 255}, Rgba8{255, 0, 255, 255});  // guides
  image.at(9, 4) = test::kGreen;
  drawSum(image, 15, 3, 88, test::kOrange, test::kBlue);  // orange is no state any more
  image.at(15, 4) = test::kGreen;
  const Storyboard s = decodeStoryboard(image, legend);
  REQUIRE(s.glyphs.size() == 2);
  CHECK(s.glyphs[0] ==
        Glyph{3, 3, Heading::Down, State::Stroll, Action::Talk, 2});  // after the named ones
  CHECK(s.glyphs[1] == Glyph{9, 3, Heading::Down, State::Hurried, Action::Walk, 1});
  REQUIRE(s.invalid.size() == 1);
  CHECK(s.invalid[0].reason == "unknown state colour (255,128,0)");
  REQUIRE(s.groups.size() == 3);
  CHECK(s.groups[0].name == "tourists");
  CHECK(s.groups[1].name == "guides");
  CHECK(s.groups[2].name.empty());

  // The encoder gives named groups their colours and unnamed ones palette colours far from them.
  std::vector<Glyph> glyphs = s.glyphs;
  CHECK(decodeStoryboard(encodeStoryboard(20, 7, glyphs, legend), legend).glyphs == glyphs);
}

TEST_CASE("legend: malformed files give errors naming the file and what was expected") {
  CHECK_THROWS_WITH_AS(parseLegend("{\"states\": ", "a.json"),
                       doctest::Contains("a.json: not valid JSON"), Error);
  CHECK_THROWS_WITH_AS(parseLegend("[1]", "b.json"),
                       doctest::Contains("b.json: expected a JSON object"), Error);
  CHECK_THROWS_WITH_AS(parseLegend(R"({"colours": {}})", "c.json"),
                       doctest::Contains("unknown key \"colours\""), Error);
  CHECK_THROWS_WITH_AS(parseLegend(R"({"states": {"sprint": [1,2,3]}})", "d.json"),
                       doctest::Contains("d.json: states: unknown name \"sprint\""), Error);
  CHECK_THROWS_WITH_AS(parseLegend(R"({"actions": {"run": [1,2]}})", "e.json"),
                       doctest::Contains("e.json: actions.run: expected a colour"), Error);
  CHECK_THROWS_WITH_AS(parseLegend(R"({"actions": {"run": [0,200,10]}})", "f.json"),
                       doctest::Contains("ambiguous"), Error);
  CHECK_THROWS_WITH_AS(parseLegend(R"({"states": {"stroll": [250,250,250]}})", "g.json"),
                       doctest::Contains("white background"), Error);
  CHECK_THROWS_WITH_AS(parseLegend(R"({"tolerance": 300})", "h.json"),
                       doctest::Contains("h.json: tolerance"), Error);
  CHECK_THROWS_WITH_AS(parseLegend(R"({"groups": [{"name": "x"}]})", "i.json"),
                       doctest::Contains("i.json: groups[0]"), Error);
  CHECK_THROWS_WITH_AS(loadLegend("/nonexistent/legend.json"),
                       doctest::Contains("/nonexistent/legend.json"), Error);
}

TEST_CASE("legend: colour helpers") {
  CHECK(colourDistance(Rgba8{10, 20, 30, 255}, Rgba8{15, 0, 31, 0}) == 20);
  const std::vector<Rgba8> palette = {{0, 0, 0, 255}, {100, 0, 0, 255}};
  CHECK(matchColour(Rgba8{60, 0, 0, 255}, palette, 40) == 1);
  CHECK(matchColour(Rgba8{50, 0, 0, 255}, palette, 40) == -1);
  CHECK(flattenOnWhite(Rgba8{0, 0, 0, 0}) == Rgba8{255, 255, 255, 255});
  CHECK(flattenOnWhite(Rgba8{0, 0, 0, 255}) == Rgba8{0, 0, 0, 255});
  CHECK(isWhite(Rgba8{230, 240, 250, 255}, 40));
  CHECK_FALSE(isWhite(Rgba8{255, 255, 0, 255}, 40));
  // Palette colours are far apart from each other.
  CHECK(groupPaletteSize() == 23);
  for (int i = 0; i < groupPaletteSize(); ++i)
    for (int j = 0; j < i; ++j) CHECK(colourDistance(paletteColour(i), paletteColour(j)) >= 127);
}

TEST_CASE("legend: numbers out of range and repeated keys name the file and key") {
  CHECK_THROWS_WITH_AS(parseLegend(R"({"tolerance": 1e400})", "big.json"),
                       doctest::Contains("big.json: key \"tolerance\""), Error);
  CHECK_THROWS_WITH_AS(parseLegend("{\"tolerance\": 20,\n \"tolerance\": 30}", "twice.json"),
                       doctest::Contains("twice.json: duplicate key \"tolerance\""), Error);
  CHECK_THROWS_WITH_AS(
      parseLegend(R"({"states": {"stroll": [0,0,0], "stroll": [9,9,9]}})", "nested.json"),
      doctest::Contains("nested.json: duplicate key \"states.stroll\""), Error);
  CHECK_THROWS_WITH_AS(parseLegend("{\n\"tolerance\": 20,\n\"states\": }", "line.json"),
                       doctest::Contains("line.json: not valid JSON (parse error at line 3"),
                       Error);
  // The same key in two different objects is not a repeat.
  const Legend legend = parseLegend(
      R"({"groups": [{"name": "a", "colour": [0,0,255]}, {"name": "b", "colour": [0,0,0]}]})",
      "ok.json");
  CHECK(legend.groups.size() == 2);
}
