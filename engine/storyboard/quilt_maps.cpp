#include <algorithm>

#include "storyboard/legend.h"
#include "storyboard/quilt_internal.h"

namespace throng::storyboard::quilt {

uint32_t glyphLabel(const Glyph& g) {
  return kPresent | uint32_t(g.heading) | uint32_t(g.state) << 3 | uint32_t(g.action) << 4 |
         (uint32_t(g.group) & 0xFFFFFFu) << 6;
}

double labelDistance(uint32_t a, uint32_t b) {
  if (a == b) return 0.0;
  if (!a || !b) return 1.0;
  // Heading weighs most: it is what the crowd's flow is made of.
  double d = 0.0;
  if ((a & 7u) != (b & 7u)) d += 0.4;
  if ((a >> 3 & 1u) != (b >> 3 & 1u)) d += 0.2;
  if ((a >> 4 & 3u) != (b >> 4 & 3u)) d += 0.2;
  if ((a >> 6) != (b >> 6)) d += 0.2;
  return d;
}

SampleMaps buildSampleMaps(const ImageRgba8& sample, const Storyboard& decoded, bool wrap, int pad) {
  SampleMaps m;
  m.sourceWidth = sample.width;
  m.sourceHeight = sample.height;
  m.wrap = wrap;
  m.width = sample.width + (wrap ? pad : 0);
  m.height = sample.height + (wrap ? pad : 0);
  const size_t n = size_t(m.width) * m.height;
  m.label.assign(n, 0);
  m.ink.assign(n, Ink{});
  m.centreOf.assign(n, -1);
  for (const Glyph& original : decoded.glyphs) {
    SampleGlyph s;
    s.glyph = original;
    s.label = glyphLabel(original);
    const std::array<Offset, 4> offsets = glyphPixels(original.heading);
    for (int k = 0; k < 4; ++k)
      s.colours[k] = flattenOnWhite(sample.at(original.x + offsets[k].dx, original.y + offsets[k].dy));
    for (int ty = 0; ty * sample.height < m.height; ++ty)
      for (int tx = 0; tx * sample.width < m.width; ++tx) {
        s.glyph.x = original.x + tx * sample.width;
        s.glyph.y = original.y + ty * sample.height;
        if (s.glyph.x > m.width - 2 || s.glyph.y > m.height - 2) continue;
        for (int k = 0; k < 4; ++k) {
          const size_t i = m.index(s.glyph.x + offsets[k].dx, s.glyph.y + offsets[k].dy);
          m.label[i] = s.label;
          m.ink[i] = Ink{int16_t(255 - s.colours[k].r), int16_t(255 - s.colours[k].g), int16_t(255 - s.colours[k].b)};
        }
        m.centreOf[m.index(s.glyph.x, s.glyph.y)] = int(m.glyphs.size());
        m.glyphs.push_back(s);
      }
  }
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      if (m.label[m.index(x, y)]) m.glyphPixels.push_back({x, y, m.label[m.index(x, y)], m.ink[m.index(x, y)]});
  const size_t stride = size_t(m.width) + 1;
  m.presenceSat.assign(stride * (m.height + 1), 0);
  m.inkSquaredSat.assign(stride * (m.height + 1), 0);
  for (int y = 0; y < m.height; ++y) {
    int32_t rowPresence = 0;
    int64_t rowInk = 0;
    for (int x = 0; x < m.width; ++x) {
      rowPresence += m.label[m.index(x, y)] ? 1 : 0;
      rowInk += m.ink[m.index(x, y)].squared();
      m.presenceSat[(y + 1) * stride + x + 1] = m.presenceSat[y * stride + x + 1] + rowPresence;
      m.inkSquaredSat[(y + 1) * stride + x + 1] = m.inkSquaredSat[y * stride + x + 1] + rowInk;
    }
  }
  return m;
}

bool Canvas::touchesPlaced(const SampleGlyph& glyph, int x, int y) const {
  for (Offset o : glyphPixels(glyph.glyph.heading))
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + o.dx + dx, ny = y + o.dy + dy;
        if (nx >= 0 && ny >= 0 && nx < width && ny < height && owner[index(nx, ny)] >= 0) return true;
      }
  return false;
}

void Canvas::place(const SampleGlyph& glyph, int sampleIndex, int x, int y) {
  const int32_t id = int32_t(glyphs.size());
  glyphs.push_back({x, y, sampleIndex, true});
  for (Offset o : glyphPixels(glyph.glyph.heading)) owner[index(x + o.dx, y + o.dy)] = id;
}

void Canvas::remove(int placedIndex) {
  PlacedGlyph& p = glyphs[size_t(placedIndex)];
  if (!p.alive) return;
  p.alive = false;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int32_t& o = owner[index(p.x + dx, p.y + dy)];
      if (o == placedIndex) o = -1;
    }
}

uint32_t Canvas::labelAt(const SampleMaps& sample, int x, int y) const {
  const int32_t o = owner[index(x, y)];
  return o < 0 ? 0u : sample.glyphs[size_t(glyphs[size_t(o)].sample)].label;
}

Ink Canvas::inkAt(const SampleMaps& sample, int x, int y) const {
  const int32_t o = owner[index(x, y)];
  if (o < 0) return {};
  const PlacedGlyph& p = glyphs[size_t(o)];
  const Glyph& g = sample.glyphs[size_t(p.sample)].glyph;
  return sample.ink[sample.index(g.x + x - p.x, g.y + y - p.y)];
}

std::vector<OverlapPixel> gatherOverlap(const Canvas& canvas, const SampleMaps& sample, const BlockGeometry& b) {
  std::vector<OverlapPixel> pixels;
  for (int ly = 0; ly < b.h; ++ly) {
    const int width = ly < b.top ? b.w : std::min(b.left, b.w);
    for (int lx = 0; lx < width; ++lx) {
      const int x = b.x + lx, y = b.y + ly;
      if (canvas.owner[canvas.index(x, y)] >= 0)
        pixels.push_back({lx, ly, canvas.labelAt(sample, x, y), canvas.inkAt(sample, x, y)});
    }
  }
  return pixels;
}

}  // namespace throng::storyboard::quilt
