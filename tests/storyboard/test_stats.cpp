#include <doctest/doctest.h>

#include <vector>

#include "storyboard/stats.h"

using namespace throng::storyboard;

TEST_CASE("stats: density and shares") {
  const std::vector<Glyph> glyphs = {{1, 1, Heading::Top, State::Stroll, Action::Walk, 0},
                                     {5, 1, Heading::Top, State::Hurried, Action::Run, 0},
                                     {9, 1, Heading::Left, State::Hurried, Action::Run, 1},
                                     {13, 1, Heading::RightDown, State::Hurried, Action::Jump, 1}};
  const StoryboardStats s = computeStats(glyphs, 2000.0);
  CHECK(s.agents == 4);
  CHECK(s.density == doctest::Approx(2.0));
  CHECK(s.headings[int(Heading::Top)] == doctest::Approx(0.5));
  CHECK(s.headings[int(Heading::RightDown)] == doctest::Approx(0.25));
  CHECK(s.states[int(State::Hurried)] == doctest::Approx(0.75));
  CHECK(s.actions[int(Action::Run)] == doctest::Approx(0.5));
  CHECK(s.actions[int(Action::Talk)] == 0.0);
  const StoryboardStats empty = computeStats({}, 100.0);
  CHECK(empty.density == 0.0);
  CHECK(empty.states[0] == 0.0);
}

TEST_CASE("stats: total variation distance") {
  const std::vector<double> a = {0.5, 0.5, 0.0}, b = {0.0, 0.5, 0.5}, c = {0.0, 0.0, 1.0};
  CHECK(totalVariation(a, a) == 0.0);
  CHECK(totalVariation(a, b) == doctest::Approx(0.5));
  CHECK(totalVariation(a, c) == doctest::Approx(1.0));
}

TEST_CASE("stats: the report names every share") {
  const std::vector<Glyph> glyphs = {{1, 1, Heading::Top, State::Stroll, Action::Walk, 0}};
  const StoryboardStats s = computeStats(glyphs, 1000.0);
  const std::string text = formatStats(s, &s);
  CHECK(text.find("density 1.00") != std::string::npos);
  CHECK(text.find("Top 100% (100%)") != std::string::npos);
  CHECK(text.find("TV distance 0.000") != std::string::npos);
}
