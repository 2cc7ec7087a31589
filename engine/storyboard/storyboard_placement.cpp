#include "storyboard/storyboard_placement.h"

#include <cmath>

#include "core/error.h"
#include "core/math.h"
#include "core/rng.h"

namespace throng::storyboard {

float headingAngle(Heading heading) {
  // Image (dx, dy) → world (x, z) = (dx, dy); heading θ faces (sin θ, cos θ).
  switch (heading) {
    case Heading::Down: return 0.0f;
    case Heading::Right: return 0.5f * kPi;
    case Heading::Top: return kPi;
    case Heading::Left: return -0.5f * kPi;
    case Heading::RightDown: return 0.25f * kPi;
    case Heading::TopRight: return 0.75f * kPi;
    case Heading::TopLeft: return -0.75f * kPi;
    case Heading::LeftDown: return -0.25f * kPi;
  }
  return 0.0f;
}

uint32_t clipSetOf(Action action) { return uint32_t(action); }

Placement placeStoryboard(const Storyboard& storyboard, const PlacementOptions& o) {
  if (!(o.cellSize > 0.0f) || !std::isfinite(o.cellSize)) fail("cell size ", o.cellSize, " m: expected > 0");
  if (!(o.jitter >= 0.0f) || !std::isfinite(o.jitter)) fail("jitter ", o.jitter, " m: expected >= 0");
  for (int s = 0; s < kStateCount; ++s) {
    const crowd::SpeedRange r = o.speeds[size_t(s)];
    if (!(r.min >= 0.0f && r.min <= r.max && std::isfinite(r.max)))
      fail("speed range of '", stateName(State(s)), "' [", r.min, ", ", r.max, "] m/s: expected 0 <= min <= max");
  }
  if (!(o.minScale > 0.0f && o.minScale <= o.maxScale)) fail("scale range must be positive and ordered");
  Placement p;
  const size_t n = storyboard.glyphs.size();
  p.crowd.resize(n);
  p.tint.resize(n);
  p.speedRange.resize(n);
  p.speed.resize(n);
  // Stable order by clip set: counting sort on the action.
  for (const Glyph& g : storyboard.glyphs) ++p.setBegin[size_t(clipSetOf(g.action)) + 1];
  for (int k = 0; k < kActionCount; ++k) p.setBegin[size_t(k) + 1] += p.setBegin[size_t(k)];
  p.glyph.resize(n);
  std::array<uint32_t, kActionCount + 1> next = p.setBegin;
  for (size_t g = 0; g < n; ++g) p.glyph[next[clipSetOf(storyboard.glyphs[g].action)]++] = uint32_t(g);
  // Random draws in glyph order, so an agent's jitter and speed do not depend on the others' actions.
  Rng rng(o.seed, 0x5b0a);
  const float cx = 0.5f * float(storyboard.width), cy = 0.5f * float(storyboard.height);
  std::vector<uint32_t> agentOf(n);
  for (size_t i = 0; i < n; ++i) agentOf[p.glyph[i]] = uint32_t(i);
  for (size_t gi = 0; gi < n; ++gi) {
    const Glyph& g = storyboard.glyphs[gi];
    const size_t i = agentOf[gi];
    float x = (float(g.x) + 0.5f - cx) * o.cellSize + rng.uniform(-o.jitter, o.jitter);
    float z = (float(g.y) + 0.5f - cy) * o.cellSize + rng.uniform(-o.jitter, o.jitter);
    p.crowd.placement[i] = glm::vec4(x, 0.0f, z, headingAngle(g.heading));
    const crowd::SpeedRange range = o.speeds[size_t(g.state)];
    const float speed = rng.uniform(range.min, range.max);
    RootSpeeds root{o.slowSpeed, o.fastSpeed};
    if (o.actionSpeeds) root = (*o.actionSpeeds)[size_t(g.action)];
    const bool standing = o.actionSpeeds && root.slow == 0.0f && root.fast == 0.0f;
    const float w = standing ? rng.uniform() : crowd::speedWeight(speed, root.slow, root.fast);
    p.crowd.motion[i] = glm::vec4(rng.uniform(), w, w, rng.uniform(o.minScale, o.maxScale));
    p.crowd.clipSet[i] = clipSetOf(g.action);
    p.tint[i] = uint32_t(g.group);
    p.speedRange[i] = range;
    p.speed[i] = speed;
  }
  return p;
}

}  // namespace throng::storyboard
