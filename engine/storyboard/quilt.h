#pragma once
// Glyph-preserving image quilting (Efros & Freeman 2001) of a small storyboard into a large
// one. Blocks are copied in scan-line order; the error of a candidate block over the overlap
// with what is already placed compares per-pixel glyph-attribute labels (presence, heading,
// state, action, group) and colour; one candidate within (1 + tolerance) of the best is drawn
// at random; a minimum-error boundary cut (dynamic programming) splits the overlap, steered
// around glyphs, and then every glyph goes whole to the side holding its centre. A new glyph
// that would touch a kept one is dropped, so every glyph of the output decodes.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/image.h"
#include "storyboard/codec.h"
#include "storyboard/legend.h"
#include "storyboard/stats.h"

namespace throng::storyboard {

struct QuiltOptions {
  int width = 0, height = 0;  // output size in pixels
  int block = 0;              // block side; 0 = a third of the sample's smaller side, in 8..48
  int overlap = 0;            // 0 = block / 5, at least 3 (at most block / 2)
  uint64_t seed = 1;
  double tolerance = 0.1;     // candidates within (1 + tolerance) × best error are eligible
  double colourWeight = 0.25; // colour error weight next to the label error (per pixel, 0..1 each)
  // Error of a candidate's glyph pixel over white already placed. Below 1 it offsets the pull
  // of plain pixel error toward empty overlaps, which would thin the crowd out.
  double extraGlyphWeight = 0.5;
  // Treat the sample as periodic, so its edges are copied as often as its middle (keeps the
  // heading/state/action mix); agents meeting across the seam are kept apart like any others.
  bool wrap = true;
  std::optional<ImageRgba8> walkable;  // white = walkable, black = not; scaled to the output
};

struct QuiltReport {
  StoryboardStats sample, output;
  int block = 0, overlap = 0;
  int blocks = 0;
  long candidatesPerBlock = 0;  // of a full-size block
  int ignoredSampleInvalid = 0; // invalid components of the sample, not copied
  int droppedTouching = 0;      // new glyphs that would have touched a kept one
  int droppedOutside = 0;       // glyphs whose cell would leave the output image
  int droppedMask = 0;          // glyphs centred on non-walkable pixels
  double seconds = 0;           // synthesis time (no PNG I/O)
};

struct QuiltResult {
  ImageRgba8 image;
  std::vector<Glyph> glyphs;  // reading order; groups numbered as in the sample
  QuiltReport report;
};

// Throws Error when the options do not fit the sample or the sample holds no valid glyph.
QuiltResult quiltStoryboard(const ImageRgba8& sample, const Legend& legend, const QuiltOptions& options);

}  // namespace throng::storyboard
