#include "storyboard/example.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/rng.h"
#include "storyboard/codec.h"

namespace throng::storyboard {
namespace {
struct GroupStyle {
  float x, y;  // seed point
  Heading heading;
  State state;
  Action action;
};

int randomBelow(Rng& rng, int n) { return int(rng.next() % uint32_t(n)); }
}  // namespace

std::vector<Glyph> generateExampleGlyphs(const ExampleOptions& o) {
  if (o.width < 3 || o.height < 3 || long(o.width) * o.height > kMaxStoryboardPixels)
    fail("example storyboard of ", o.width, "x", o.height, ": expected at least 3x3 and at most ",
         kMaxStoryboardPixels, " pixels");
  if (o.spacing < 4) fail("example spacing ", o.spacing, ": expected >= 4 so glyphs never touch");
  if (o.groups < 1) fail("example groups ", o.groups, ": expected >= 1");
  if (!(o.density > 0)) fail("example density ", o.density, ": expected > 0");
  Rng rng(o.seed);
  std::vector<GroupStyle> styles;
  for (int i = 0; i < o.groups; ++i)
    styles.push_back({rng.uniform(0.f, float(o.width)), rng.uniform(0.f, float(o.height)),
                      Heading(randomBelow(rng, kHeadingCount)), State(randomBelow(rng, kStateCount)),
                      rng.uniform() < 0.7f ? Action::Walk : Action(randomBelow(rng, kActionCount))});

  const long target = std::lround(o.density * double(o.width) * o.height / 1000.0);
  std::vector<uint8_t> taken(size_t(o.width) * o.height, 0);
  auto isFree = [&](int x, int y) {
    for (int dy = -(o.spacing - 1); dy <= o.spacing - 1; ++dy)
      for (int dx = -(o.spacing - 1); dx <= o.spacing - 1; ++dx) {
        int nx = x + dx, ny = y + dy;
        if (nx >= 0 && ny >= 0 && nx < o.width && ny < o.height && taken[size_t(ny) * o.width + nx]) return false;
      }
    return true;
  };
  std::vector<Glyph> glyphs;
  for (long attempt = 0; attempt < 60 * target + 100 && long(glyphs.size()) < target; ++attempt) {
    int x = 1 + randomBelow(rng, std::max(1, o.width - 2)), y = 1 + randomBelow(rng, std::max(1, o.height - 2));
    if (x > o.width - 2 || y > o.height - 2 || !isFree(x, y)) continue;
    taken[size_t(y) * o.width + x] = 1;
    int group = 0;
    float best = 1e30f;
    for (int i = 0; i < o.groups; ++i) {
      float d = std::hypot(styles[i].x - float(x), styles[i].y - float(y));
      if (d < best) best = d, group = i;
    }
    const GroupStyle& s = styles[group];
    Glyph g{x, y, s.heading, s.state, s.action, group};
    if (rng.uniform() < 0.35f) g.heading = Heading(randomBelow(rng, kHeadingCount));
    if (rng.uniform() < 0.15f) g.state = State(randomBelow(rng, kStateCount));
    if (rng.uniform() < 0.25f) g.action = Action(randomBelow(rng, kActionCount));
    glyphs.push_back(g);
  }
  canonicalizeGroups(glyphs, 0);
  return glyphs;
}

}  // namespace throng::storyboard
