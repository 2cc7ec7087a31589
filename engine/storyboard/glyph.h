#pragma once
// The storyboard glyph (docs/design.md, "Storyboard crowds"): a T of 4 pixels in a 3×3 cell. The outer
// pixels are numbered in reading order (TL=1 T=2 TR=4 L=8 R=16 BL=32 B=64 BR=128) and their
// sum names one of eight headings.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace throng::storyboard {

enum class Heading : uint8_t { Top, Left, Down, Right, TopLeft, TopRight, LeftDown, RightDown };
enum class State : uint8_t { Stroll, Hurried };
enum class Action : uint8_t { Walk, Run, Talk, Jump };

inline constexpr int kHeadingCount = 8;
inline constexpr int kStateCount = 2;
inline constexpr int kActionCount = 4;

struct Offset {
  int dx = 0, dy = 0;
};

// One row of the heading table (docs/formats.md): the code sum, the pointer and the two bar pixels.
struct HeadingShape {
  Heading heading;
  int sum;
  Offset pointer;
  std::array<Offset, 2> bar;  // in reading order
};

const std::array<HeadingShape, kHeadingCount>& headingShapes();
const HeadingShape& shapeOf(Heading heading);
std::optional<Heading> headingFromSum(int sum);
// Reading-order code of an outer pixel (dx, dy in -1..1, not both 0).
int outerCode(int dx, int dy);

std::string_view headingName(Heading heading);
std::string_view stateName(State state);
std::string_view actionName(Action action);
std::optional<Heading> parseHeading(std::string_view name);
std::optional<State> parseState(std::string_view name);
std::optional<Action> parseAction(std::string_view name);

// A decoded agent: (x, y) is the centre pixel.
struct Glyph {
  int x = 0, y = 0;
  Heading heading = Heading::Down;
  State state = State::Stroll;
  Action action = Action::Walk;
  int group = 0;
  friend bool operator==(const Glyph&, const Glyph&) = default;
};

}  // namespace throng::storyboard
