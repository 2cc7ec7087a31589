#include <doctest/doctest.h>

#include "core/error.h"
#include "storyboard/storyboard_json.h"

using namespace throng;
using namespace throng::storyboard;

TEST_CASE("storyboard json: the exact decode --json form") {
  Storyboard s;
  s.width = 90;
  s.height = 60;
  s.glyphs = {{10, 12, Heading::Down, State::Hurried, Action::Walk, 0},
              {40, 12, Heading::TopLeft, State::Stroll, Action::Talk, 1}};
  s.invalid = {{5, 50, "sum 19 is not a T glyph"}};
  CHECK(
      storyboardToJson(s) ==
      R"({"schema":"throng.storyboard","version":1,"width":90,"height":60,"agents":[{"x":10,"y":12,"heading":"Down","state":"hurried","action":"walk","group":0},)"
      R"({"x":40,"y":12,"heading":"TopLeft","state":"stroll","action":"talk","group":1}],)"
      R"("invalid":[{"x":5,"y":50,"reason":"sum 19 is not a T glyph"}]})");
  const Storyboard back = storyboardFromJson(storyboardToJson(s), "s.json");
  CHECK(back.width == 90);
  CHECK(back.height == 60);
  CHECK(back.glyphs == s.glyphs);
}

TEST_CASE("storyboard json: files without schema and version still read; others' are refused") {
  const Storyboard old = storyboardFromJson(R"({"width":9,"height":8,"agents":[]})", "old.json");
  CHECK(old.width == 9);
  CHECK(old.height == 8);
  CHECK_THROWS_WITH_AS(
      storyboardFromJson(R"({"schema":"throng.clip_info","width":9,"height":8,"agents":[]})",
                         "clip.json"),
      doctest::Contains("clip.json: expected \"schema\": \"throng.storyboard\""), Error);
  CHECK_THROWS_WITH_AS(
      storyboardFromJson(
          R"({"schema":"throng.storyboard","version":2,"width":9,"height":8,"agents":[]})",
          "v2.json"),
      doctest::Contains("v2.json: expected \"version\": 1"), Error);
}

TEST_CASE("storyboard json: errors name the agent and the expected values") {
  CHECK_THROWS_WITH_AS(storyboardFromJson("{", "a.json"),
                       doctest::Contains("a.json: not valid JSON"), Error);
  CHECK_THROWS_WITH_AS(storyboardFromJson(R"({"width":9,"agents":[]})", "b.json"),
                       doctest::Contains("b.json: expected an integer \"height\""), Error);
  CHECK_THROWS_WITH_AS(
      storyboardFromJson(
          R"({"width":9,"height":9,"agents":[{"x":4,"y":4,"heading":"Up","state":"stroll","action":"walk"}]})",
          "c.json"),
      doctest::Contains("c.json: agents[0]: heading \"Up\""), Error);
}

TEST_CASE("storyboard json: out-of-range numbers and repeated keys are errors naming the file") {
  CHECK_THROWS_WITH_AS(
      storyboardFromJson(R"({"width": 1e400, "height": 5, "agents": []})", "big.json"),
      doctest::Contains("big.json: key \"width\""), Error);
  CHECK_THROWS_WITH_AS(
      storyboardFromJson(R"({"width": 5, "width": 6, "height": 5, "agents": []})", "twice.json"),
      doctest::Contains("twice.json: duplicate key \"width\""), Error);
  CHECK_THROWS_WITH_AS(
      storyboardFromJson(R"({"width": 18446744073709551615, "height": 5, "agents": []})", "u.json"),
      doctest::Contains("u.json: expected an integer \"width\""), Error);
}
