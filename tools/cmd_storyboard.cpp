// throng storyboard decode|encode|example|quilt: the glyph storyboards of docs/design.md.
#include <charconv>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/image.h"
#include "storyboard/codec.h"
#include "storyboard/example.h"
#include "storyboard/quilt.h"
#include "storyboard/stats.h"
#include "storyboard/storyboard_json.h"

namespace throng::tools {
namespace {
namespace sb = throng::storyboard;

struct Size {
  int width = 0, height = 0;
};

Size parseSize(const std::string& text, const char* option) {
  Size size;
  const char* end = text.data() + text.size();
  auto [afterWidth, e1] = std::from_chars(text.data(), end, size.width);
  bool ok = e1 == std::errc() && afterWidth != end && *afterWidth == 'x';
  if (ok) {
    auto [afterHeight, e2] = std::from_chars(afterWidth + 1, end, size.height);
    ok = e2 == std::errc() && afterHeight == end;
  }
  if (!ok || size.width <= 0 || size.height <= 0)
    fail(option, " \"", text, "\": expected WxH in pixels, e.g. 300x300");
  return size;
}

struct LegendOptions {
  std::string path;
  int tolerance = -1;
  sb::Legend load() const {
    sb::Legend legend = path.empty() ? sb::Legend{} : sb::loadLegend(path);
    if (tolerance >= 0) {
      if (tolerance > sb::kMaxTolerance) fail("--colour-tolerance ", tolerance, ": expected 0..", sb::kMaxTolerance);
      legend.tolerance = tolerance;
    }
    return legend;
  }
  void add(CLI::App* command) {
    command->add_option("--legend", path, "Colour legend JSON (default: the default colours of docs/formats.md)");
    command->add_option("--colour-tolerance", tolerance, "Largest per-channel difference of near colours (default 40)");
  }
};

std::string colourText(Rgba8 c) { return concat("(", int(c.r), ",", int(c.g), ",", int(c.b), ")"); }

void printSummary(const std::string& file, const sb::Storyboard& s) {
  std::printf("%s: %dx%d pixels, %zu agents, %zu invalid\n", file.c_str(), s.width, s.height, s.glyphs.size(),
              s.invalid.size());
  std::printf("%s", sb::formatStats(sb::computeStats(s.glyphs, double(s.width) * s.height)).c_str());
  std::map<int, int> perGroup;
  for (const sb::Glyph& g : s.glyphs) ++perGroup[g.group];
  for (size_t i = 0; i < s.groups.size(); ++i)
    std::printf("  group %zu %s%s%s: %d agents\n", i, colourText(s.groups[i].colour).c_str(),
                s.groups[i].name.empty() ? "" : " ", s.groups[i].name.c_str(), perGroup[int(i)]);
  for (const sb::InvalidGlyph& g : s.invalid) std::printf("  invalid at pixel (%d,%d): %s\n", g.x, g.y, g.reason.c_str());
}

void addDecode(CLI::App& parent) {
  auto* command = parent.add_subcommand("decode", "Decode a storyboard PNG into agents");
  struct Args {
    std::string file;
    LegendOptions legend;
    bool strict = false, json = false;
  };
  auto args = std::make_shared<Args>();
  command->add_option("file", args->file, "Storyboard PNG")->required();
  args->legend.add(command);
  command->add_flag("--strict", args->strict, "Invalid glyphs are an error");
  command->add_flag("--json", args->json, "Print {width, height, agents, invalid} as JSON");
  command->callback([args] {
    const sb::Storyboard s = sb::readStoryboard(args->file, args->legend.load(), args->strict);
    if (args->json) std::printf("%s\n", sb::storyboardToJson(s).c_str());
    else printSummary(args->file, s);
  });
}

void addEncode(CLI::App& parent) {
  auto* command = parent.add_subcommand("encode", "Write agents (the JSON of decode --json) as a storyboard PNG");
  struct Args {
    std::string file, out;
    LegendOptions legend;
  };
  auto args = std::make_shared<Args>();
  command->add_option("file", args->file, "Agents JSON")->required();
  command->add_option("--out", args->out, "Output PNG")->required();
  args->legend.add(command);
  command->callback([args] {
    const sb::Storyboard s = sb::storyboardFromJson(readTextFile(args->file), args->file);
    const sb::Legend legend = args->legend.load();
    ImageRgba8 image;
    try {
      image = sb::encodeStoryboard(s.width, s.height, s.glyphs, legend);
    } catch (const Error& e) {
      fail(args->file, ": ", e.what());
    }
    writePngAtomic(args->out, image);
    std::printf("%s: %dx%d pixels, %zu agents\n", args->out.c_str(), s.width, s.height, s.glyphs.size());
  });
}

void addExample(CLI::App& parent) {
  auto* command = parent.add_subcommand("example", "Write a random valid storyboard");
  struct Args {
    std::string out, size = "90x90";
    sb::ExampleOptions example;
    LegendOptions legend;
  };
  auto args = std::make_shared<Args>();
  command->add_option("--out", args->out, "Output PNG")->required();
  command->add_option("--seed", args->example.seed, "Random seed");
  command->add_option("--size", args->size, "WxH in pixels (default 90x90)");
  command->add_option("--density", args->example.density, "Agents per 1000 px^2 (default 10)");
  command->add_option("--groups", args->example.groups, "Number of groups (default 4)");
  args->legend.add(command);
  command->callback([args] {
    const Size size = parseSize(args->size, "--size");
    args->example.width = size.width;
    args->example.height = size.height;
    const std::vector<sb::Glyph> glyphs = sb::generateExampleGlyphs(args->example);
    writePngAtomic(args->out, sb::encodeStoryboard(size.width, size.height, glyphs, args->legend.load()));
    std::printf("%s: %dx%d pixels, %zu agents\n", args->out.c_str(), size.width, size.height, glyphs.size());
  });
}

void addQuilt(CLI::App& parent) {
  auto* command = parent.add_subcommand("quilt", "Enlarge a storyboard by glyph-preserving image quilting");
  struct Args {
    std::string file, out, size, mask;
    sb::QuiltOptions quilt;
    LegendOptions legend;
  };
  auto args = std::make_shared<Args>();
  command->add_option("file", args->file, "Small storyboard PNG (the sample)")->required();
  command->add_option("--size", args->size, "Output WxH in pixels")->required();
  command->add_option("--out", args->out, "Output PNG")->required();
  command->add_option("--block", args->quilt.block, "Block side in pixels (default: sample/3 in 8..48)");
  command->add_option("--overlap", args->quilt.overlap, "Overlap in pixels (default: block/5, >= 3)");
  command->add_option("--seed", args->quilt.seed, "Random seed");
  command->add_option("--tolerance", args->quilt.tolerance, "Blocks within (1+T) x best error are eligible (0.1)");
  command->add_flag("--no-wrap", [args](int64_t) { args->quilt.wrap = false; },
                    "Take blocks only from inside the sample (plain Efros-Freeman; edges get rarer)");
  command->add_option("--mask", args->mask, "Walkable mask PNG: white walkable, black not; scaled to the output");
  args->legend.add(command);
  command->callback([args] {
    const Size size = parseSize(args->size, "--size");
    args->quilt.width = size.width;
    args->quilt.height = size.height;
    if (!args->mask.empty()) args->quilt.walkable = readPng(args->mask);
    const ImageRgba8 sample = readPng(args->file);
    const sb::Legend legend = args->legend.load();
    sb::QuiltResult result;
    try {
      result = sb::quiltStoryboard(sample, legend, args->quilt);
    } catch (const Error& e) {
      fail(args->file, ": ", e.what());
    }
    writePngAtomic(args->out, result.image);
    const sb::QuiltReport& r = result.report;
    std::printf("%s: %dx%d pixels from %s in %.2f s (block %d, overlap %d, %d blocks, %ld candidates each)\n",
                args->out.c_str(), size.width, size.height, args->file.c_str(), r.seconds, r.block, r.overlap,
                r.blocks, r.candidatesPerBlock);
    std::printf("sample:\n%s", sb::formatStats(r.sample).c_str());
    std::printf("output (sample in parentheses):\n%s", sb::formatStats(r.output, &r.sample).c_str());
    std::printf("dropped: %d touching, %d outside the image, %d on non-walkable pixels; %d invalid sample components ignored\n",
                r.droppedTouching, r.droppedOutside, r.droppedMask, r.ignoredSampleInvalid);
  });
}

void addStoryboardCommands(CLI::App& app) {
  auto* storyboard = app.add_subcommand("storyboard", "Glyph storyboards: decode, encode, example, quilt");
  storyboard->require_subcommand(1);
  addDecode(*storyboard);
  addEncode(*storyboard);
  addExample(*storyboard);
  addQuilt(*storyboard);
}

const CommandRegistration kRegistration("storyboard", addStoryboardCommands);
}  // namespace
}  // namespace throng::tools
