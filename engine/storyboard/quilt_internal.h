#pragma once
// Shared by the quilting sources only: the sample's per-pixel maps, the output canvas of
// placed glyphs, block geometry, candidate search and the boundary cut.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/image.h"
#include "storyboard/codec.h"

namespace throng::storyboard::quilt {

inline constexpr uint32_t kPresent = 1u << 31;
inline constexpr double kColourNorm = 3.0 * 255.0 * 255.0;

// Attributes of the glyph a pixel belongs to; 0 on white.
uint32_t glyphLabel(const Glyph& glyph);
// 0 equal, 1 presence differs, else the weighted share of differing attributes.
double labelDistance(uint32_t a, uint32_t b);

struct Ink {
  int16_t r = 0, g = 0, b = 0;  // 255 - colour: white is 0
  int squared() const { return r * r + g * g + b * b; }
  int dot(const Ink& o) const { return r * o.r + g * o.g + b * o.b; }
};

// A glyph pixel: placed inside a block's overlap (block-local coordinates) or in the sample.
struct OverlapPixel {
  int lx = 0, ly = 0;
  uint32_t label = 0;
  Ink ink;
};

struct SampleGlyph {
  Glyph glyph;
  uint32_t label = 0;
  std::array<Rgba8, 4> colours;  // centre, pointer, bar, bar: exactly as drawn
};

// With wrapping, the maps extend the sample periodically by `pad` pixels right and down, so
// every sample pixel starts a candidate block: without it, pixels near the sample's edges
// fall in far fewer candidates than central ones and their agents become rare in the output.
struct SampleMaps {
  int width = 0, height = 0;          // of the maps (the sample plus the periodic pad)
  std::vector<uint32_t> label;
  std::vector<Ink> ink;
  std::vector<int> centreOf;           // glyph index whose centre is this pixel, else -1
  std::vector<int32_t> presenceSat;    // (width+1)×(height+1) summed-area tables
  std::vector<int64_t> inkSquaredSat;
  std::vector<SampleGlyph> glyphs;  // every copy whose cell lies inside the maps
  std::vector<OverlapPixel> glyphPixels;  // every glyph pixel of the maps (lx, ly = x, y)
  int sourceWidth = 0, sourceHeight = 0;
  bool wrap = false;
  size_t index(int x, int y) const { return size_t(y) * width + x; }
  // Sum over [x0,x1)×[y0,y1) of a summed-area table.
  template <typename T>
  T rectSum(const std::vector<T>& sat, int x0, int y0, int x1, int y1) const {
    const size_t stride = size_t(width) + 1;
    return sat[y1 * stride + x1] - sat[y0 * stride + x1] - sat[y1 * stride + x0] + sat[y0 * stride + x0];
  }
};

// Only the decoded valid glyphs are kept, re-drawn on pure white.
SampleMaps buildSampleMaps(const ImageRgba8& sample, const Storyboard& decoded, bool wrap, int pad);
// Number of candidate positions along x and y for a block of w×h.
inline int candidatesAlong(int source, int maps, int block, bool wrap) { return wrap ? source : maps - block + 1; }

struct PlacedGlyph {
  int x = 0, y = 0;
  int sample = 0;  // index into SampleMaps::glyphs
  bool alive = true;
};

struct Canvas {
  int width = 0, height = 0;
  std::vector<int32_t> owner;  // placed glyph owning this glyph pixel, else -1
  std::vector<PlacedGlyph> glyphs;
  size_t index(int x, int y) const { return size_t(y) * width + x; }
  bool cellInside(int x, int y) const { return x >= 1 && y >= 1 && x <= width - 2 && y <= height - 2; }
  // True when a pixel of the glyph would be 8-adjacent to (or on) a pixel of a placed glyph.
  bool touchesPlaced(const SampleGlyph& glyph, int x, int y) const;
  void place(const SampleGlyph& glyph, int sampleIndex, int x, int y);
  void remove(int placedIndex);
  uint32_t labelAt(const SampleMaps& sample, int x, int y) const;
  Ink inkAt(const SampleMaps& sample, int x, int y) const;
};

// A block of the output in scan-line order; its overlap region is the left strip of width
// `left` plus the top strip of height `top` (0 at the image's first column/row).
struct BlockGeometry {
  int x = 0, y = 0, w = 0, h = 0;
  int left = 0, top = 0;
  bool inOverlap(int lx, int ly) const { return lx < left || ly < top; }
};

std::vector<OverlapPixel> gatherOverlap(const Canvas& canvas, const SampleMaps& sample, const BlockGeometry& block);

struct ErrorWeights {
  double colour = 0.25;     // of the colour error next to the label error (both 0..1 per pixel)
  double extraGlyph = 1.0;  // of a candidate glyph pixel over placed white
};

// Candidate c sits at sample (c % nx, c / nx). The overlap error of every candidate as if the
// placed overlap were all white; it depends only on the block's geometry, so it is cached.
std::vector<double> whiteOverlapErrors(const SampleMaps& sample, const BlockGeometry& block, int nx, int ny,
                                       ErrorWeights weights);
// The full overlap error of every candidate: the white-overlap error plus, for each placed
// glyph pixel, its error against white and a correction at the few candidates that put a
// glyph pixel under it. Cost ~ (placed glyph pixels x sample glyph pixels), not candidates x
// overlap area: storyboards are mostly white.
void candidateErrors(const SampleMaps& sample, std::span<const OverlapPixel> overlap, int nx, int ny,
                     ErrorWeights weights, const std::vector<double>& white, std::vector<double>& errors);

// Which block pixels take the new block: right of the vertical cut and below the horizontal.
struct CutMask {
  std::vector<int> column;  // per block row: first new column (0 without a left strip)
  std::vector<int> row;     // per block column: first new row (0 without a top strip)
  bool isNew(int lx, int ly) const { return lx >= column[ly] && ly >= row[lx]; }
};

CutMask computeCut(const Canvas& canvas, const SampleMaps& sample, const BlockGeometry& block, int sx, int sy,
                   double colourWeight);

}  // namespace throng::storyboard::quilt
