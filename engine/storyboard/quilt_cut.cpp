// The minimum-error boundary cut of Efros & Freeman, computed by dynamic programming over the
// overlap strips. Unmatched glyphs (no identical glyph at the same place on the other side)
// add a penalty over their cell plus a one-pixel margin, so the cut prefers white space
// between glyphs; which side each glyph lands on is then decided by its centre alone.
#include <algorithm>
#include <limits>

#include "storyboard/quilt_internal.h"

namespace throng::storyboard::quilt {
namespace {
constexpr double kZonePenalty = 2.0;
constexpr int kZoneRadius = 2;  // 3×3 cell plus a one-pixel margin

// Path minimising the summed cost through a grid of `length` steps × `span` positions, moving
// at most one position per step; returns the position per step.
std::vector<int> minimumPath(int length, int span, auto cost) {
  std::vector<double> table(size_t(length) * span);
  for (int s = 0; s < length; ++s)
    for (int p = 0; p < span; ++p) {
      double best = 0;
      if (s > 0) {
        best = std::numeric_limits<double>::infinity();
        for (int q = std::max(0, p - 1); q <= std::min(span - 1, p + 1); ++q)
          best = std::min(best, table[size_t(s - 1) * span + q]);
      }
      table[size_t(s) * span + p] = best + cost(s, p);
    }
  std::vector<int> path(static_cast<size_t>(length));
  int p = int(std::min_element(table.end() - span, table.end()) - (table.end() - span));
  for (int s = length - 1; s >= 0; --s) {
    path[size_t(s)] = p;
    if (s == 0) break;
    int next = p;
    for (int q = std::max(0, p - 1); q <= std::min(span - 1, p + 1); ++q)
      if (table[size_t(s - 1) * span + q] < table[size_t(s - 1) * span + next]) next = q;
    p = next;
  }
  return path;
}
}  // namespace

CutMask computeCut(const Canvas& canvas, const SampleMaps& sample, const BlockGeometry& b, int sx, int sy,
                   double colourWeight) {
  const int left = std::min(b.left, b.w), top = std::min(b.top, b.h);
  CutMask mask;
  mask.column.assign(size_t(b.h), 0);
  mask.row.assign(size_t(b.w), 0);
  if (left == 0 && top == 0) return mask;

  std::vector<double> zone(size_t(b.w) * b.h, 0.0);
  auto addZone = [&](int cx, int cy) {
    for (int ly = std::max(0, cy - kZoneRadius); ly <= std::min(b.h - 1, cy + kZoneRadius); ++ly)
      for (int lx = std::max(0, cx - kZoneRadius); lx <= std::min(b.w - 1, cx + kZoneRadius); ++lx)
        zone[size_t(ly) * b.w + lx] += kZonePenalty;
  };
  // Placed glyphs near the block: matched when the candidate has the same glyph centred there.
  std::vector<int> seen;
  for (int y = std::max(0, b.y - kZoneRadius); y < std::min(canvas.height, b.y + b.h + kZoneRadius); ++y)
    for (int x = std::max(0, b.x - kZoneRadius); x < std::min(canvas.width, b.x + b.w + kZoneRadius); ++x) {
      const int32_t o = canvas.owner[canvas.index(x, y)];
      if (o < 0 || std::find(seen.begin(), seen.end(), o) != seen.end()) continue;
      seen.push_back(o);
      const PlacedGlyph& p = canvas.glyphs[size_t(o)];
      const int lx = p.x - b.x, ly = p.y - b.y, qx = sx + lx, qy = sy + ly;
      const bool matched = qx >= 0 && qy >= 0 && qx < sample.width && qy < sample.height &&
                           sample.centreOf[sample.index(qx, qy)] >= 0 &&
                           sample.label[sample.index(qx, qy)] == sample.glyphs[size_t(p.sample)].label;
      if (!matched) addZone(lx, ly);
    }
  // Candidate glyphs: matched when the same glyph is already placed with its centre there.
  for (const SampleGlyph& g : sample.glyphs) {
    const int lx = g.glyph.x - sx, ly = g.glyph.y - sy;
    if (lx < 0 || ly < 0 || lx >= b.w || ly >= b.h) continue;
    const int32_t o = canvas.owner[canvas.index(b.x + lx, b.y + ly)];
    const bool matched = o >= 0 && canvas.glyphs[size_t(o)].x == b.x + lx && canvas.glyphs[size_t(o)].y == b.y + ly &&
                         sample.glyphs[size_t(canvas.glyphs[size_t(o)].sample)].label == g.label;
    if (!matched) addZone(lx, ly);
  }

  const double inkScale = colourWeight / kColourNorm;
  auto cost = [&](int lx, int ly) {
    const int x = b.x + lx, y = b.y + ly;
    const size_t i = sample.index(sx + lx, sy + ly);
    const Ink a = canvas.inkAt(sample, x, y), c = sample.ink[i];
    const Ink d{int16_t(a.r - c.r), int16_t(a.g - c.g), int16_t(a.b - c.b)};
    return labelDistance(canvas.labelAt(sample, x, y), sample.label[i]) + inkScale * d.squared() +
           zone[size_t(ly) * b.w + lx];
  };
  if (left > 0) mask.column = minimumPath(b.h, left, [&](int ly, int lx) { return cost(lx, ly); });
  if (top > 0) mask.row = minimumPath(b.w, top, [&](int lx, int ly) { return cost(lx, ly); });
  return mask;
}

}  // namespace throng::storyboard::quilt
