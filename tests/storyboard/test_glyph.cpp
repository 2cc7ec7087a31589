#include <doctest/doctest.h>

#include "storyboard/glyph.h"

using namespace throng::storyboard;

TEST_CASE("glyph: the heading table is docs/formats.md's and every entry is a T") {
  const int expected[kHeadingCount] = {26, 74, 88, 82, 37, 133, 161, 164};
  for (const HeadingShape& shape : headingShapes()) {
    CAPTURE(headingName(shape.heading));
    CHECK(shape.sum == expected[int(shape.heading)]);
    CHECK(outerCode(shape.pointer.dx, shape.pointer.dy) + outerCode(shape.bar[0].dx, shape.bar[0].dy) +
              outerCode(shape.bar[1].dx, shape.bar[1].dy) ==
          shape.sum);
    // The bar runs through the centre; the pointer sits perpendicular to it.
    CHECK(shape.bar[0].dx == -shape.bar[1].dx);
    CHECK(shape.bar[0].dy == -shape.bar[1].dy);
    CHECK(shape.pointer.dx * shape.bar[0].dx + shape.pointer.dy * shape.bar[0].dy == 0);
    CHECK(headingFromSum(shape.sum) == shape.heading);
  }
}

TEST_CASE("glyph: only the eight table sums name a heading") {
  int valid = 0;
  for (int sum = 0; sum < 256; ++sum) valid += headingFromSum(sum).has_value();
  CHECK(valid == 8);
  CHECK_FALSE(headingFromSum(19));
}

TEST_CASE("glyph: reading-order codes") {
  CHECK(outerCode(-1, -1) == 1);
  CHECK(outerCode(0, -1) == 2);
  CHECK(outerCode(1, -1) == 4);
  CHECK(outerCode(-1, 0) == 8);
  CHECK(outerCode(1, 0) == 16);
  CHECK(outerCode(-1, 1) == 32);
  CHECK(outerCode(0, 1) == 64);
  CHECK(outerCode(1, 1) == 128);
  CHECK(outerCode(0, 0) == 0);
}

TEST_CASE("glyph: names round-trip and unknown names are rejected") {
  for (int i = 0; i < kHeadingCount; ++i) CHECK(parseHeading(headingName(Heading(i))) == Heading(i));
  for (int i = 0; i < kStateCount; ++i) CHECK(parseState(stateName(State(i))) == State(i));
  for (int i = 0; i < kActionCount; ++i) CHECK(parseAction(actionName(Action(i))) == Action(i));
  CHECK(headingName(Heading::RightDown) == "RightDown");
  CHECK(stateName(State::Hurried) == "hurried");
  CHECK(actionName(Action::Talk) == "talk");
  CHECK_FALSE(parseHeading("down"));
  CHECK_FALSE(parseState("running"));
  CHECK_FALSE(parseAction(""));
}
