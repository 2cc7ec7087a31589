#include "storyboard/glyph.h"

namespace throng::storyboard {
namespace {
constexpr std::array<std::string_view, kHeadingCount> kHeadingNames = {
    "Top", "Left", "Down", "Right", "TopLeft", "TopRight", "LeftDown", "RightDown"};
constexpr std::array<std::string_view, kStateCount> kStateNames = {"stroll", "hurried"};
constexpr std::array<std::string_view, kActionCount> kActionNames = {"walk", "run", "talk", "jump"};

constexpr Offset kTL{-1, -1}, kT{0, -1}, kTR{1, -1}, kL{-1, 0}, kR{1, 0}, kBL{-1, 1}, kB{0, 1},
    kBR{1, 1};

template <typename Enum, size_t N>
std::optional<Enum> parseName(const std::array<std::string_view, N>& names, std::string_view name) {
  for (size_t i = 0; i < N; ++i)
    if (names[i] == name) return static_cast<Enum>(i);
  return std::nullopt;
}
}  // namespace

const std::array<HeadingShape, kHeadingCount>& headingShapes() {
  static const std::array<HeadingShape, kHeadingCount> shapes = {{
      {Heading::Top, 26, kT, {kL, kR}},
      {Heading::Left, 74, kL, {kT, kB}},
      {Heading::Down, 88, kB, {kL, kR}},
      {Heading::Right, 82, kR, {kT, kB}},
      {Heading::TopLeft, 37, kTL, {kTR, kBL}},
      {Heading::TopRight, 133, kTR, {kTL, kBR}},
      {Heading::LeftDown, 161, kBL, {kTL, kBR}},
      {Heading::RightDown, 164, kBR, {kTR, kBL}},
  }};
  return shapes;
}

const HeadingShape& shapeOf(Heading heading) { return headingShapes()[static_cast<int>(heading)]; }

std::optional<Heading> headingFromSum(int sum) {
  for (const HeadingShape& shape : headingShapes())
    if (shape.sum == sum) return shape.heading;
  return std::nullopt;
}

int outerCode(int dx, int dy) {
  // Reading order skipping the centre: index 0..8 with 4 the centre.
  int index = (dy + 1) * 3 + (dx + 1);
  if (index == 4 || index < 0 || index > 8) return 0;
  return 1 << (index < 4 ? index : index - 1);
}

std::string_view headingName(Heading heading) { return kHeadingNames[static_cast<int>(heading)]; }
std::string_view stateName(State state) { return kStateNames[static_cast<int>(state)]; }
std::string_view actionName(Action action) { return kActionNames[static_cast<int>(action)]; }
std::optional<Heading> parseHeading(std::string_view name) {
  return parseName<Heading>(kHeadingNames, name);
}
std::optional<State> parseState(std::string_view name) { return parseName<State>(kStateNames, name); }
std::optional<Action> parseAction(std::string_view name) {
  return parseName<Action>(kActionNames, name);
}

}  // namespace throng::storyboard
