// Overlap error of candidate blocks (Efros & Freeman's "SSD over the overlap"), on labels and
// colour: per overlap pixel, labelDistance(placed, candidate) + colour × |ink difference|² / norm,
// where a candidate glyph pixel over placed white counts extraGlyph times.
#include <algorithm>

#include "storyboard/quilt_internal.h"

namespace throng::storyboard::quilt {

std::vector<double> whiteOverlapErrors(const SampleMaps& s, const BlockGeometry& b, int nx, int ny, ErrorWeights weights) {
  const int left = std::min(b.left, b.w), top = std::min(b.top, b.h);
  const double inkScale = weights.colour / kColourNorm;
  std::vector<double> errors(size_t(nx) * ny);
  for (int sy = 0; sy < ny; ++sy)
    for (int sx = 0; sx < nx; ++sx) {
      int64_t presence = 0, inkSquared = 0;
      if (left > 0) {
        presence += s.rectSum(s.presenceSat, sx, sy, sx + left, sy + b.h);
        inkSquared += s.rectSum(s.inkSquaredSat, sx, sy, sx + left, sy + b.h);
      }
      if (top > 0 && b.w > left) {
        presence += s.rectSum(s.presenceSat, sx + left, sy, sx + b.w, sy + top);
        inkSquared += s.rectSum(s.inkSquaredSat, sx + left, sy, sx + b.w, sy + top);
      }
      errors[size_t(sy) * nx + sx] = weights.extraGlyph * (double(presence) + inkScale * double(inkSquared));
    }
  return errors;
}

void candidateErrors(const SampleMaps& s, std::span<const OverlapPixel> overlap, int nx, int ny, ErrorWeights weights,
                     const std::vector<double>& white, std::vector<double>& errors) {
  const double inkScale = weights.colour / kColourNorm;
  double againstWhite = 0;  // every placed glyph pixel over candidate white: label 1 + its ink²
  for (const OverlapPixel& p : overlap) againstWhite += 1.0 + inkScale * p.ink.squared();
  errors.resize(white.size());
  for (size_t c = 0; c < white.size(); ++c) errors[c] = white[c] + againstWhite;
  // Where candidate c puts glyph pixel q under placed pixel p (c = q - p), the two terms
  // above assumed white on one side each; replace them by the true pixel error.
  for (const OverlapPixel& p : overlap)
    for (const OverlapPixel& q : s.glyphPixels) {
      const int sx = q.lx - p.lx, sy = q.ly - p.ly;
      if (sx < 0 || sy < 0 || sx >= nx || sy >= ny) continue;
      const double truth = labelDistance(p.label, q.label) +
                           inkScale * (p.ink.squared() + q.ink.squared() - 2.0 * p.ink.dot(q.ink));
      const double assumed = 1.0 + inkScale * p.ink.squared() + weights.extraGlyph * (1.0 + inkScale * q.ink.squared());
      errors[size_t(sy) * nx + sx] += truth - assumed;
    }
}

}  // namespace throng::storyboard::quilt
