// `throng clip info FILE.bvh [--json] [--loop]`: what the importer sees in a capture
// (joints, channel orders, frames, units) and, with --loop, the best cycle in it, so a clip
// can be checked before it is baked.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "anim/bvh.h"
#include "anim/bvh_channels.h"
#include "anim/clip_prep.h"
#include "command.h"
#include "core/error.h"

namespace throng::tools {
namespace {

constexpr float kLoopFrameTime = 1.0f / 30.0f;

struct ClipInfoOptions {
  std::string file;
  bool json = false;
  bool loop = false;
  int minFrames = 15;  // 0.5 s at 30 fps: shorter than any walk or run cycle
  int maxFrames = 45;  // 1.5 s: longer than a slow walk cycle
};

// A float as JSON with its shortest decimal form (0.0083333, not 0.008333300240337849).
double tidy(float value) {
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (ec != std::errc()) return value;
  return std::strtod(std::string(buffer, end).c_str(), nullptr);
}

std::string channelList(const anim::Joint& joint) {
  std::string out;
  for (anim::Channel c : joint.channels) {
    if (!out.empty()) out += ' ';
    out += anim::channelName(c);
  }
  return out;
}

anim::LoopCut findLoop(const anim::RawClip& raw, const anim::UnitsGuess& units,
                       const ClipInfoOptions& options) {
  anim::Clip clip;
  try {
    clip =
        anim::resample(anim::scaleToMetres(anim::toClip(raw), units.metresPerUnit), kLoopFrameTime);
  } catch (const Error& e) {
    fail(options.file, ": ", e.what());  // the resampler names the clip, not the file it came from
  }
  // A cycle needs its end frame too, so at most frameCount - 1 frames long.
  int maxFrames = std::min(options.maxFrames, clip.frameCount - 1);
  int minFrames = std::min(options.minFrames, maxFrames);
  if (minFrames < 2) {
    fail(options.file, ": ", clip.frameCount,
         " frames at 30 fps is too short to search for a loop");
  }
  return anim::findBestLoop(clip, minFrames, maxFrames);
}

nlohmann::json toJson(const anim::RawClip& raw, const anim::UnitsGuess& units,
                      const std::optional<anim::LoopCut>& loop, const ClipInfoOptions& options) {
  nlohmann::json joints = nlohmann::json::array();
  for (const anim::Joint& joint : raw.skeleton.joints) {
    nlohmann::json channels = nlohmann::json::array();
    for (anim::Channel c : joint.channels) channels.push_back(std::string(anim::channelName(c)));
    joints.push_back({{"name", joint.name}, {"parent", joint.parent}, {"channels", channels}});
  }
  nlohmann::json out = {
      {"schema", "throng.clip_info"},
      {"version", 1},
      {"file", options.file},
      {"joints", joints},
      {"joint_count", raw.skeleton.jointCount()},
      {"frames", raw.frameCount},
      {"frame_time", tidy(raw.frameTime)},
      {"units",
       {{"label", units.label},
        {"metres_per_unit", tidy(units.metresPerUnit)},
        {"height_m", tidy(units.heightInUnits * units.metresPerUnit)},
        {"height_in_units", tidy(units.heightInUnits)}}},
  };
  if (loop) {
    out["loop"] = {{"start", loop->start},
                   {"end", loop->end},
                   {"length", loop->length()},
                   {"error", tidy(loop->error)},
                   {"frame_time", tidy(kLoopFrameTime)}};
  }
  return out;
}

void printText(const anim::RawClip& raw, const anim::UnitsGuess& units,
               const std::optional<anim::LoopCut>& loop, const ClipInfoOptions& options) {
  std::printf("file: %s\n", options.file.c_str());
  std::printf("joints: %d\n", raw.skeleton.jointCount());
  for (int j = 0; j < raw.skeleton.jointCount(); ++j) {
    const anim::Joint& joint = raw.skeleton.joints[size_t(j)];
    std::printf("  %3d %-24s parent %3d  %s%s\n", j, joint.name.c_str(), joint.parent,
                channelList(joint).c_str(), joint.endSite ? "  (end site)" : "");
  }
  std::printf("frames: %d\n", raw.frameCount);
  std::printf("frame time: %g s (%.1f fps, %.2f s)\n", raw.frameTime, 1.0 / raw.frameTime,
              raw.frameCount * double(raw.frameTime));
  std::printf("units: %s (%.4g m per unit), standing height %.2f m (%.1f units)\n",
              units.label.c_str(), units.metresPerUnit, units.heightInUnits * units.metresPerUnit,
              units.heightInUnits);
  if (loop) {
    std::printf("loop (at 30 fps): frames %d..%d, length %d (%.2f s), error %.4f\n", loop->start,
                loop->end, loop->length(), loop->length() * kLoopFrameTime, loop->error);
  }
}

void runClipInfo(const ClipInfoOptions& options) {
  anim::RawClip raw = anim::loadBvh(options.file);
  anim::UnitsGuess units = anim::detectUnits(raw.skeleton);
  std::optional<anim::LoopCut> loop;
  if (options.loop) loop = findLoop(raw, units, options);
  if (options.json) {
    // Joint names are bytes from the file: replace invalid UTF-8 rather than throw.
    std::cout << toJson(raw, units, loop, options)
                     .dump(2, ' ', false, nlohmann::json::error_handler_t::replace)
              << '\n';
  } else {
    printText(raw, units, loop, options);
  }
}

void addClipCommands(CLI::App& app) {
  CLI::App* clip = app.add_subcommand("clip", "Inspect motion-capture clips");
  clip->require_subcommand(1);
  CLI::App* info =
      clip->add_subcommand("info", "Joints, frames, units and best loop of a BVH file");
  auto options = std::make_shared<ClipInfoOptions>();
  info->add_option("file", options->file, "BVH file")->required();
  info->add_flag("--json", options->json, "Print one JSON object");
  info->add_flag("--loop", options->loop, "Find the best loop (in metres, resampled to 30 fps)");
  info->add_option("--min-frames", options->minFrames, "Shortest loop searched, frames at 30 fps")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  info->add_option("--max-frames", options->maxFrames, "Longest loop searched, frames at 30 fps")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  info->callback([options] { runClipInfo(*options); });
}

const CommandRegistration kRegistration("clip", addClipCommands);

}  // namespace
}  // namespace throng::tools
