#include "storyboard/quilt.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "core/rng.h"
#include "storyboard/quilt_internal.h"
#include <map>

namespace throng::storyboard {
namespace {
using namespace quilt;

struct Resolved {
  int block = 0, overlap = 0;
};

Resolved resolveOptions(const QuiltOptions& o, int sampleWidth, int sampleHeight) {
  if (o.width < 3 || o.height < 3) fail("quilt output size ", o.width, "x", o.height, ": expected at least 3x3");
  if (long(o.width) * o.height > kMaxStoryboardPixels)
    fail("quilt output size ", o.width, "x", o.height, ": more than ", kMaxStoryboardPixels, " pixels");
  if (!(o.tolerance >= 0)) fail("quilt tolerance ", o.tolerance, ": expected >= 0");
  if (!(o.colourWeight >= 0)) fail("quilt colour weight ", o.colourWeight, ": expected >= 0");
  const int smaller = std::min(sampleWidth, sampleHeight);
  Resolved r;
  r.block = o.block > 0 ? o.block : std::clamp(smaller / 3, 8, 48);
  r.block = std::min(r.block, smaller);
  if (o.block > smaller)
    fail("quilt block ", o.block, ": larger than the ", sampleWidth, "x", sampleHeight, " sample");
  if (r.block < 4) fail("quilt block ", r.block, ": expected at least 4 pixels (sample ", sampleWidth, "x", sampleHeight, ")");
  r.overlap = o.overlap > 0 ? o.overlap : std::min(r.block / 2, std::max(3, r.block / 5));
  if (r.overlap * 2 > r.block) fail("quilt overlap ", r.overlap, ": expected at most half the block (", r.block, ")");
  return r;
}

// Candidate of least error, or one drawn among those within (1 + tolerance) of it.
long chooseCandidate(const std::vector<double>& errors, double tolerance, Rng& rng) {
  const double best = *std::min_element(errors.begin(), errors.end());
  const double threshold = best + tolerance * std::fabs(best) + 1e-9;
  long eligible = 0;
  for (double e : errors) eligible += e <= threshold;
  long pick = long(rng.next() % uint32_t(eligible));
  for (size_t c = 0; c < errors.size(); ++c)
    if (errors[c] <= threshold && pick-- == 0) return long(c);
  return 0;
}

// After the cut, each glyph goes whole to the side holding its centre: placed glyphs centred
// on the new side give way, candidate glyphs centred there come in unless they would touch.
void resolveGlyphs(Canvas& canvas, const SampleMaps& sample, const BlockGeometry& b, int sx, int sy, const CutMask& cut,
                   QuiltReport& report) {
  for (int ly = 0; ly < b.h; ++ly)
    for (int lx = 0; lx < b.w; ++lx) {
      const int32_t o = canvas.owner[canvas.index(b.x + lx, b.y + ly)];
      if (o >= 0 && canvas.glyphs[size_t(o)].x == b.x + lx && canvas.glyphs[size_t(o)].y == b.y + ly &&
          cut.isNew(lx, ly))
        canvas.remove(o);
    }
  for (size_t i = 0; i < sample.glyphs.size(); ++i) {
    const SampleGlyph& g = sample.glyphs[i];
    const int lx = g.glyph.x - sx, ly = g.glyph.y - sy;
    if (lx < 0 || ly < 0 || lx >= b.w || ly >= b.h || !cut.isNew(lx, ly)) continue;
    const int x = b.x + lx, y = b.y + ly;
    if (!canvas.cellInside(x, y)) ++report.droppedOutside;
    else if (canvas.touchesPlaced(g, x, y)) ++report.droppedTouching;
    else canvas.place(g, int(i), x, y);
  }
}

// Keeps the glyphs whose centre maps onto a walkable (light) pixel of the mask.
bool walkableAt(const ImageRgba8& mask, int x, int y, int width, int height) {
  const int mx = std::min(mask.width - 1, int((x + 0.5) * mask.width / width));
  const int my = std::min(mask.height - 1, int((y + 0.5) * mask.height / height));
  const Rgba8 c = flattenOnWhite(mask.at(mx, my));
  return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b >= 128.0;
}
}  // namespace

QuiltResult quiltStoryboard(const ImageRgba8& sampleImage, const Legend& legend, const QuiltOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Storyboard decoded = decodeStoryboard(sampleImage, legend);
  if (decoded.glyphs.empty())
    fail("quilt sample of ", sampleImage.width, "x", sampleImage.height, " pixels holds no valid glyph (",
         decoded.invalid.size(), " invalid components)");
  const Resolved r = resolveOptions(options, sampleImage.width, sampleImage.height);
  const SampleMaps sample = buildSampleMaps(sampleImage, decoded, options.wrap, r.block);
  if (options.walkable && (options.walkable->width <= 0 || options.walkable->height <= 0))
    fail("walkable mask is empty");

  QuiltResult result;
  QuiltReport& report = result.report;
  report.block = r.block;
  report.overlap = r.overlap;
  report.ignoredSampleInvalid = int(decoded.invalid.size());
  report.candidatesPerBlock = long(candidatesAlong(sample.sourceWidth, sample.width, r.block, sample.wrap)) *
                              candidatesAlong(sample.sourceHeight, sample.height, r.block, sample.wrap);

  Canvas canvas;
  canvas.width = options.width;
  canvas.height = options.height;
  canvas.owner.assign(size_t(options.width) * options.height, -1);
  Rng rng(options.seed);
  const ErrorWeights weights{options.colourWeight, options.extraGlyphWeight};
  std::map<std::array<int, 4>, std::vector<double>> whiteErrors;  // by block w, h, left, top
  std::vector<double> errors;
  const int step = r.block - r.overlap;

  for (int by = 0; by < options.height && (by == 0 || by + r.overlap < options.height); by += step)
    for (int bx = 0; bx < options.width && (bx == 0 || bx + r.overlap < options.width); bx += step) {
      BlockGeometry b{bx, by, std::min(r.block, options.width - bx), std::min(r.block, options.height - by),
                      bx > 0 ? r.overlap : 0, by > 0 ? r.overlap : 0};
      const int nx = candidatesAlong(sample.sourceWidth, sample.width, b.w, sample.wrap);
      const int ny = candidatesAlong(sample.sourceHeight, sample.height, b.h, sample.wrap);
      const long count = long(nx) * ny;
      long chosen = 0;
      if (b.left == 0 && b.top == 0) {
        chosen = long(rng.next() % uint32_t(count));
      } else {
        const std::vector<OverlapPixel> overlap = gatherOverlap(canvas, sample, b);
        auto [cached, fresh] = whiteErrors.try_emplace({b.w, b.h, b.left, b.top});
        if (fresh) cached->second = whiteOverlapErrors(sample, b, nx, ny, weights);
        candidateErrors(sample, overlap, nx, ny, weights, cached->second, errors);
        chosen = chooseCandidate(errors, options.tolerance, rng);
      }
      const int sx = int(chosen % nx), sy = int(chosen / nx);

      resolveGlyphs(canvas, sample, b, sx, sy, computeCut(canvas, sample, b, sx, sy, options.colourWeight), report);
      ++report.blocks;
    }

  result.image = ImageRgba8(options.width, options.height, Rgba8{255, 255, 255, 255});
  for (const PlacedGlyph& p : canvas.glyphs) {
    if (!p.alive) continue;
    if (options.walkable && !walkableAt(*options.walkable, p.x, p.y, options.width, options.height)) {
      ++report.droppedMask;
      continue;
    }
    const SampleGlyph& s = sample.glyphs[size_t(p.sample)];
    Glyph g = s.glyph;
    g.x = p.x, g.y = p.y;
    result.glyphs.push_back(g);
    const std::array<Offset, 4> offsets = glyphPixels(g.heading);
    for (int k = 0; k < 4; ++k) result.image.at(p.x + offsets[k].dx, p.y + offsets[k].dy) = s.colours[k];
  }
  std::sort(result.glyphs.begin(), result.glyphs.end(),
            [](const Glyph& a, const Glyph& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  report.sample = computeStats(decoded.glyphs, double(sample.sourceWidth) * sample.sourceHeight);
  report.output = computeStats(result.glyphs, double(options.width) * options.height);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace throng::storyboard
