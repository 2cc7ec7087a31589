#include <doctest/doctest.h>

#include <cmath>

#include "core/error.h"
#include "core/math.h"
#include "storyboard/codec.h"
#include "storyboard/example.h"
#include "storyboard/storyboard_placement.h"

using namespace throng;
namespace sb = throng::storyboard;

namespace {
sb::Storyboard boardOf(int width, int height, std::vector<sb::Glyph> glyphs) {
  sb::canonicalizeGroups(glyphs, 0);
  return sb::decodeStoryboard(sb::encodeStoryboard(width, height, glyphs, sb::Legend{}), sb::Legend{});
}

glm::vec2 facing(float heading) { return {std::sin(heading), std::cos(heading)}; }
}  // namespace

TEST_CASE("placement: glyph headings face the image direction of their pointer") {
  // Image (dx, dy) → world (x, z): Top points up the image, i.e. towards −z.
  struct Case {
    sb::Heading heading;
    glm::vec2 direction;
  };
  const float d = std::sqrt(0.5f);
  const Case cases[] = {{sb::Heading::Top, {0, -1}},      {sb::Heading::Down, {0, 1}},     {sb::Heading::Left, {-1, 0}},
                        {sb::Heading::Right, {1, 0}},     {sb::Heading::TopLeft, {-d, -d}}, {sb::Heading::TopRight, {d, -d}},
                        {sb::Heading::LeftDown, {-d, d}}, {sb::Heading::RightDown, {d, d}}};
  for (const Case& c : cases) {
    CAPTURE(sb::headingName(c.heading));
    glm::vec2 f = facing(sb::headingAngle(c.heading));
    CHECK(f.x == doctest::Approx(c.direction.x).epsilon(1e-5));
    CHECK(f.y == doctest::Approx(c.direction.y).epsilon(1e-5));
    // ... and that is where the glyph's pointer pixel sits relative to its centre.
    sb::Offset pointer = sb::shapeOf(c.heading).pointer;
    CHECK(glm::dot(f, glm::normalize(glm::vec2(pointer.dx, pointer.dy))) == doctest::Approx(1.0f));
  }
}

TEST_CASE("placement: positions, state speeds, actions and groups of decoded glyphs") {
  std::vector<sb::Glyph> glyphs = {
      {5, 5, sb::Heading::Top, sb::State::Stroll, sb::Action::Walk, 0},
      {15, 5, sb::Heading::Right, sb::State::Hurried, sb::Action::Run, 1},
      {5, 15, sb::Heading::Down, sb::State::Hurried, sb::Action::Talk, 0},
      {15, 15, sb::Heading::LeftDown, sb::State::Stroll, sb::Action::Jump, 2},
  };
  sb::Storyboard board = boardOf(20, 20, glyphs);
  REQUIRE(board.glyphs.size() == 4);
  sb::PlacementOptions o;
  o.cellSize = 0.5f;
  o.jitter = 0.0f;
  o.slowSpeed = 1.0f;
  o.fastSpeed = 2.0f;
  sb::Placement p = sb::placeStoryboard(board, o);
  REQUIRE(p.crowd.size() == 4);
  // Centre pixel (5, 5) of a 20×20 board: (5.5 − 10) · 0.5 = −2.25 m on both axes.
  CHECK(p.crowd.placement[0].x == doctest::Approx(-2.25f));
  CHECK(p.crowd.placement[0].z == doctest::Approx(-2.25f));
  CHECK(p.crowd.placement[3].x == doctest::Approx(2.75f));
  CHECK(p.crowd.placement[0].w == doctest::Approx(kPi));
  CHECK(p.crowd.clipSet == std::vector<uint32_t>{0, 1, 2, 3});
  CHECK(p.tint == std::vector<uint32_t>{0, 1, 0, 2});
  for (size_t i = 0; i < 4; ++i) {
    const sb::State state = board.glyphs[i].state;
    const crowd::SpeedRange r = o.speeds[size_t(state)];
    CHECK(p.speedRange[i].min == r.min);
    CHECK(p.speed[i] >= r.min);
    CHECK(p.speed[i] <= r.max);
    CHECK(p.crowd.motion[i].y == doctest::Approx(crowd::speedWeight(p.speed[i], 1.0f, 2.0f)));
    CHECK(p.crowd.motion[i].z == p.crowd.motion[i].y);
  }
}

TEST_CASE("placement: jitter stays within bounds and is deterministic per seed") {
  sb::ExampleOptions example;
  example.seed = 4;
  std::vector<sb::Glyph> glyphs = sb::generateExampleGlyphs(example);
  sb::Storyboard board = boardOf(example.width, example.height, glyphs);
  REQUIRE(board.glyphs.size() > 20);
  sb::PlacementOptions o;
  o.jitter = 0.2f;
  sb::Placement a = sb::placeStoryboard(board, o);
  sb::Placement b = sb::placeStoryboard(board, o);
  o.seed = 2;
  sb::Placement c = sb::placeStoryboard(board, o);
  bool differs = false;
  for (size_t i = 0; i < board.glyphs.size(); ++i) {
    float x = (float(board.glyphs[a.glyph[i]].x) + 0.5f - 0.5f * float(board.width)) * o.cellSize;
    CHECK(std::abs(a.crowd.placement[i].x - x) <= 0.2f + 1e-5f);
    CHECK(a.crowd.placement[i] == b.crowd.placement[i]);
    differs |= a.crowd.placement[i] != c.crowd.placement[i];
  }
  CHECK(differs);
}

TEST_CASE("placement: impossible options are reported") {
  sb::Storyboard board;
  sb::PlacementOptions o;
  o.cellSize = 0.0f;
  CHECK_THROWS_WITH_AS(sb::placeStoryboard(board, o), doctest::Contains("cell size 0 m"), Error);
  o = {};
  o.jitter = -1.0f;
  CHECK_THROWS_WITH_AS(sb::placeStoryboard(board, o), doctest::Contains("jitter -1 m"), Error);
  o = {};
  o.speeds[1] = {2.0f, 1.0f};
  CHECK_THROWS_WITH_AS(sb::placeStoryboard(board, o), doctest::Contains("speed range of 'hurried'"), Error);
}

TEST_CASE("placement: agents are ordered by clip set in contiguous ranges, glyph order within a set") {
  std::vector<sb::Glyph> glyphs = {
      {5, 5, sb::Heading::Top, sb::State::Stroll, sb::Action::Jump, 0},
      {15, 5, sb::Heading::Right, sb::State::Hurried, sb::Action::Talk, 1},
      {25, 5, sb::Heading::Down, sb::State::Hurried, sb::Action::Walk, 0},
      {5, 15, sb::Heading::Left, sb::State::Stroll, sb::Action::Jump, 2},
      {15, 15, sb::Heading::LeftDown, sb::State::Stroll, sb::Action::Walk, 1},
      {25, 15, sb::Heading::Top, sb::State::Stroll, sb::Action::Talk, 0},
  };
  sb::Storyboard board = boardOf(30, 20, glyphs);
  REQUIRE(board.glyphs.size() == 6);
  sb::PlacementOptions o;
  o.jitter = 0.0f;
  o.actionSpeeds = std::array<sb::RootSpeeds, sb::kActionCount>{{{1.0f, 2.0f}, {2.5f, 4.5f}, {0.0f, 0.0f}, {1.0f, 2.0f}}};
  sb::Placement p = sb::placeStoryboard(board, o);
  CHECK(p.crowd.clipSet == std::vector<uint32_t>{0, 0, 2, 2, 3, 3});
  CHECK(p.setBegin == std::array<uint32_t, 5>{0, 2, 2, 4, 6});
  for (size_t i = 0; i < 6; ++i) {
    const sb::Glyph& g = board.glyphs[p.glyph[i]];
    CAPTURE(i);
    CHECK(p.crowd.clipSet[i] == sb::clipSetOf(g.action));
    CHECK(p.tint[i] == uint32_t(g.group));
    CHECK(p.crowd.placement[i].x == doctest::Approx((float(g.x) + 0.5f - 15.0f) * o.cellSize));
    CHECK(p.crowd.placement[i].w == doctest::Approx(sb::headingAngle(g.heading)));
    if (i > 0 && p.crowd.clipSet[i] == p.crowd.clipSet[i - 1]) CHECK(p.glyph[i] > p.glyph[i - 1]);
    // Travelling pairs map the drawn speed to w through their own root speeds; talkers get any w.
    if (g.action == sb::Action::Walk || g.action == sb::Action::Jump)
      CHECK(p.crowd.motion[i].y == doctest::Approx(crowd::speedWeight(p.speed[i], 1.0f, 2.0f)));
    CHECK(p.crowd.motion[i].y >= 0.0f);
    CHECK(p.crowd.motion[i].y <= 1.0f);
  }
}
