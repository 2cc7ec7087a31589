#include <doctest/doctest.h>

#include <chrono>

#include "core/error.h"
#include "storyboard/quilt.h"
#include "storyboard_fixtures.h"

using namespace throng;
using namespace throng::storyboard;

namespace {
QuiltResult quilt(const ImageRgba8& sample, int size, uint64_t seed) {
  QuiltOptions options;
  options.width = options.height = size;
  options.seed = seed;
  return quiltStoryboard(sample, Legend{}, options);
}

// The output's glyphs, as the decoder sees them, are the quilter's (groups aside: the
// decoder renumbers them by first appearance).
void checkDecodesToItsGlyphs(const QuiltResult& result) {
  const Storyboard decoded = decodeStoryboard(result.image, Legend{});
  CHECK(decoded.invalid.empty());
  REQUIRE(decoded.glyphs.size() == result.glyphs.size());
  for (size_t i = 0; i < decoded.glyphs.size(); ++i) {
    Glyph a = decoded.glyphs[i], b = result.glyphs[i];
    a.group = b.group = 0;
    CHECK(a == b);
  }
}
}  // namespace

TEST_CASE("quilt: 300x300 from 60x60 decodes whole and keeps the sample's statistics") {
  for (uint64_t sampleSeed : {11u, 12u}) {
    const ImageRgba8 sample = test::exampleStoryboard(60, sampleSeed);
    for (uint64_t seed : {1u, 2u, 3u}) {
      CAPTURE(sampleSeed);
      CAPTURE(seed);
      const QuiltResult result = quilt(sample, 300, seed);
      const QuiltReport& r = result.report;
      CHECK(result.image.width == 300);
      CHECK(result.image.height == 300);
      checkDecodesToItsGlyphs(result);
      CHECK(r.sample.agents == 36);
      CHECK(r.output.agents == int(result.glyphs.size()));
      CHECK(r.output.density == doctest::Approx(r.sample.density).epsilon(0.3));
      CHECK(totalVariation(r.output.headings, r.sample.headings) < 0.25);
      CHECK(totalVariation(r.output.states, r.sample.states) < 0.25);
      CHECK(totalVariation(r.output.actions, r.sample.actions) < 0.25);
      CHECK(r.block == 20);
      CHECK(r.overlap == 4);
    }
  }
}

TEST_CASE("quilt: deterministic for a seed, different across seeds") {
  const ImageRgba8 sample = test::exampleStoryboard(60, 5);
  const QuiltResult a = quilt(sample, 150, 7), b = quilt(sample, 150, 7), c = quilt(sample, 150, 8);
  CHECK(a.image.pixels == b.image.pixels);
  CHECK(a.glyphs == b.glyphs);
  CHECK(a.image.pixels != c.image.pixels);
}

TEST_CASE("quilt: odd sizes, explicit blocks and a sample without wrapping") {
  const ImageRgba8 sample = test::exampleStoryboard(45, 9, 14.0);
  QuiltOptions options;
  options.width = 131;
  options.height = 77;
  options.block = 15;
  options.overlap = 5;
  options.tolerance = 0.3;
  options.seed = 4;
  checkDecodesToItsGlyphs(quiltStoryboard(sample, Legend{}, options));
  options.wrap = false;
  const QuiltResult unwrapped = quiltStoryboard(sample, Legend{}, options);
  checkDecodesToItsGlyphs(unwrapped);
  CHECK(unwrapped.report.candidatesPerBlock == 31 * 31);
  // Smaller than one block.
  options.width = options.height = 9;
  checkDecodesToItsGlyphs(quiltStoryboard(sample, Legend{}, options));
}

TEST_CASE("quilt: the walkable mask keeps agents off non-walkable pixels") {
  const ImageRgba8 sample = test::exampleStoryboard(60, 21);
  ImageRgba8 mask(10, 10, test::kWhite);  // scaled up to the output: left 40% blocked
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 4; ++x) mask.at(x, y) = Rgba8{0, 0, 0, 255};
  QuiltOptions options;
  options.width = options.height = 200;
  options.seed = 2;
  options.walkable = mask;
  const QuiltResult result = quiltStoryboard(sample, Legend{}, options);
  checkDecodesToItsGlyphs(result);
  CHECK(result.report.droppedMask > 50);
  CHECK(result.glyphs.size() > 150);
  for (const Glyph& g : result.glyphs) CHECK(g.x >= 80);
}

TEST_CASE("quilt: invalid sample components are not copied") {
  ImageRgba8 sample = test::exampleStoryboard(60, 3);
  for (int x = 0; x < 5; ++x) sample.at(x, 59) = Rgba8{0, 0, 0, 255};  // a stray line
  const QuiltResult result = quilt(sample, 120, 1);
  CHECK(result.report.ignoredSampleInvalid == 1);
  checkDecodesToItsGlyphs(result);
}

TEST_CASE("quilt: options that do not fit the sample are errors") {
  const ImageRgba8 sample = test::exampleStoryboard(40, 1);
  QuiltOptions options;
  options.width = options.height = 100;
  options.block = 41;
  CHECK_THROWS_WITH_AS(quiltStoryboard(sample, Legend{}, options), doctest::Contains("larger than the 40x40 sample"), Error);
  options.block = 12;
  options.overlap = 7;
  CHECK_THROWS_WITH_AS(quiltStoryboard(sample, Legend{}, options), doctest::Contains("at most half the block"), Error);
  options.overlap = 0;
  options.width = 0;
  CHECK_THROWS_AS(quiltStoryboard(sample, Legend{}, options), Error);
  options.width = 100;
  CHECK_THROWS_WITH_AS(quiltStoryboard(ImageRgba8(40, 40, test::kWhite), Legend{}, options),
                       doctest::Contains("no valid glyph"), Error);
}

TEST_CASE("quilt: 3000x3000 from 90x90 (timing, printed)") {
  const ImageRgba8 sample = test::exampleStoryboard(90, 7);
  const QuiltResult result = quilt(sample, 3000, 3);
  const QuiltReport& r = result.report;
  const auto start = std::chrono::steady_clock::now();
  const Storyboard decoded = decodeStoryboard(result.image, Legend{});
  const double decodeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(decoded.invalid.empty());
  CHECK(decoded.glyphs.size() == result.glyphs.size());
  CHECK(r.output.density == doctest::Approx(r.sample.density).epsilon(0.1));
  MESSAGE("quilt 3000x3000 from 90x90: ", r.seconds, " s (", r.blocks, " blocks of ", r.block, " px, ",
          r.candidatesPerBlock, " candidates each), ", r.output.agents, " agents; decoding it: ", decodeSeconds,
          " s\n", formatStats(r.output, &r.sample));
}

TEST_CASE("quilt: tiny samples get a block and overlap that fit") {
  std::vector<Glyph> glyphs = {{2, 2, Heading::Left, State::Hurried, Action::Talk, 0}};
  const ImageRgba8 sample = encodeStoryboard(5, 5, glyphs, Legend{});
  const QuiltResult result = quilt(sample, 40, 1);
  CHECK(result.report.block == 5);
  CHECK(result.report.overlap == 2);
  checkDecodesToItsGlyphs(result);
  CHECK(result.glyphs.size() > 20);
  for (const Glyph& g : result.glyphs) CHECK(g.heading == Heading::Left);
}
