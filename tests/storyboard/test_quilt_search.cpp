// The sparse candidate error (only glyph pixels visited) against the plain per-pixel sum.
#include <doctest/doctest.h>

#include "storyboard/quilt_internal.h"
#include "storyboard_fixtures.h"

using namespace throng;
using namespace throng::storyboard;
using namespace throng::storyboard::quilt;

namespace {
double bruteForce(const Canvas& canvas, const SampleMaps& s, const BlockGeometry& b, int sx, int sy, ErrorWeights w) {
  double error = 0;
  for (int ly = 0; ly < b.h; ++ly)
    for (int lx = 0; lx < b.w; ++lx) {
      if (!b.inOverlap(lx, ly)) continue;
      const uint32_t placed = canvas.labelAt(s, b.x + lx, b.y + ly);
      const size_t i = s.index(sx + lx, sy + ly);
      const Ink a = canvas.inkAt(s, b.x + lx, b.y + ly), c = s.ink[i];
      const Ink d{int16_t(a.r - c.r), int16_t(a.g - c.g), int16_t(a.b - c.b)};
      const double pixel = labelDistance(placed, s.label[i]) + w.colour / kColourNorm * d.squared();
      error += placed == 0 ? w.extraGlyph * pixel : pixel;
    }
  return error;
}
}  // namespace

TEST_CASE("quilt search: sparse candidate errors equal the per-pixel overlap error") {
  const ImageRgba8 image = test::exampleStoryboard(40, 8, 25.0);
  const Storyboard decoded = decodeStoryboard(image, Legend{});
  for (bool wrap : {false, true}) {
    const SampleMaps sample = buildSampleMaps(image, decoded, wrap, 12);
    Canvas canvas;
    canvas.width = canvas.height = 60;
    canvas.owner.assign(60 * 60, -1);
    // The sample itself, shifted by (13, 12): candidate (7, 5) for the block at (20, 17)
    // reproduces the placed overlap exactly.
    for (size_t g = 0; g < sample.glyphs.size(); ++g) {
      const Glyph& glyph = sample.glyphs[g].glyph;
      if (glyph.x < 40 && glyph.y < 40) canvas.place(sample.glyphs[g], int(g), glyph.x + 13, glyph.y + 12);
    }
    CHECK(canvas.glyphs.size() == decoded.glyphs.size());
    for (const ErrorWeights weights : {ErrorWeights{0.25, 1.0}, ErrorWeights{1.0, 0.3}}) {
      const BlockGeometry block{20, 17, 12, 12, 5, 5};
      const int nx = candidatesAlong(sample.sourceWidth, sample.width, block.w, wrap);
      const int ny = candidatesAlong(sample.sourceHeight, sample.height, block.h, wrap);
      CHECK(nx == (wrap ? 40 : 29));
      const std::vector<OverlapPixel> overlap = gatherOverlap(canvas, sample, block);
      CHECK(!overlap.empty());
      std::vector<double> errors;
      candidateErrors(sample, overlap, nx, ny, weights, whiteOverlapErrors(sample, block, nx, ny, weights), errors);
      REQUIRE(errors.size() == size_t(nx) * ny);
      int exactMatches = 0;
      for (int sy = 0; sy < ny; ++sy)
        for (int sx = 0; sx < nx; ++sx) {
          const double expected = bruteForce(canvas, sample, block, sx, sy, weights);
          CHECK(errors[size_t(sy) * nx + sx] == doctest::Approx(expected).epsilon(1e-9));
          exactMatches += expected == 0;
        }
      CHECK(errors[size_t(5) * nx + 7] == doctest::Approx(0.0));
      CHECK(exactMatches >= 1);
      CHECK(overlap.size() >= 8);
    }
  }
}

TEST_CASE("quilt search: the boundary cut goes around a placed glyph through white space") {
  // A sample with one glyph far from the candidate block, so the candidate's overlap is white.
  const std::vector<Glyph> glyphs = {{30, 30, Heading::Down, State::Stroll, Action::Walk, 0}};
  const ImageRgba8 image = encodeStoryboard(40, 40, glyphs, Legend{});
  const SampleMaps sample = buildSampleMaps(image, decodeStoryboard(image, Legend{}), false, 0);
  Canvas canvas;
  canvas.width = canvas.height = 40;
  canvas.owner.assign(40 * 40, -1);
  canvas.place(sample.glyphs[0], 0, 11, 6);  // block-local (1, 6), inside the left strip
  const BlockGeometry block{10, 0, 14, 14, 6, 0};
  const CutMask cut = computeCut(canvas, sample, block, 0, 0, 0.25);
  REQUIRE(cut.column.size() == 14);
  for (int ly = 0; ly < 14; ++ly) {
    CAPTURE(ly);
    CHECK(cut.column[size_t(ly)] < 6);
    if (ly > 0) CHECK(std::abs(cut.column[size_t(ly)] - cut.column[size_t(ly) - 1]) <= 1);
    // The glyph's cell plus a one-pixel margin (columns 0..3, rows 4..8) stays on the old side.
    if (ly >= 4 && ly <= 8) CHECK(cut.column[size_t(ly)] >= 4);
  }
  CHECK_FALSE(cut.isNew(1, 6));
  CHECK(cut.isNew(13, 6));
}
