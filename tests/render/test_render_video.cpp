// `throng render --video`: an H.264 MP4 that ffprobe reads, written off the frame loop, never
// half-written under its name; output folders of earlier runs are not mixed into.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "cli_support.h"

using namespace throng;
namespace fs = std::filesystem;

namespace {

std::string shell(const std::string& command) {
  std::string out;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[512];
  while (std::fgets(buffer, sizeof(buffer), pipe)) out += buffer;
  pclose(pipe);
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

bool haveFfmpeg() {
  return std::system("ffmpeg -version >/dev/null 2>&1 && ffprobe -version >/dev/null 2>&1") == 0;
}

std::string probe(const fs::path& video) {
  return shell(
      "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
      "stream=codec_name,width,height,nb_read_frames -of csv=p=0 '" +
      video.string() + "'");
}

constexpr const char* kSmallScene = "render -n 200 --size 320x240 --seed 3 --validation";

}  // namespace

TEST_CASE("render video: H.264 MP4 with the right size and frame count, no PNGs unless --out") {
  if (!haveFfmpeg()) {
    MESSAGE("skipped: ffmpeg/ffprobe not installed (scripts/install_deps.sh installs them)");
    return;
  }
  fs::path dir = test::freshDirectory("render_video");
  fs::path video = dir / "crowd.mp4";
  auto run = test::runThrong(std::string(kSmallScene) + " --frames 12 --video " + video.string() +
                             " --out " + (dir / "frames").string());
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  CHECK(probe(video) == "h264,320,240,12");
  CHECK(fs::exists(dir / "frames" / "frame_0011.png"));
  CHECK(run.output.find("wall time per frame") != std::string::npos);
  CHECK(run.output.find("prepared in") != std::string::npos);

  fs::path only = dir / "only.mp4";
  auto seconds = test::runThrong(std::string(kSmallScene) + " --seconds 0.5 --fps 24 --video " +
                                 only.string());
  INFO(seconds.output);
  REQUIRE(seconds.exitCode == 0);
  CHECK(probe(only) == "h264,320,240,15");  // 0.5 s at the default 1/30 s step
  CHECK(shell("ffprobe -v error -show_entries stream=r_frame_rate -of csv=p=0 '" + only.string() +
              "'") == "24/1");
  CHECK_FALSE(
      fs::exists(fs::current_path() / "frames" / "frame_0014.png"));  // no PNGs without --out
}

TEST_CASE("render video: a run killed midway leaves no file under the final name") {
  if (!haveFfmpeg()) {
    MESSAGE("skipped: ffmpeg not installed");
    return;
  }
  fs::path dir = test::freshDirectory("render_video_killed");
  fs::path video = dir / "killed.mp4";
  std::string command = "LP_NUM_THREADS=2 " + test::throngBinary() + " " + kSmallScene +
                        " --frames 5000 --video " + video.string();
  // Killed once the encoder has started (its temporary file exists), long before the end.
  shell("(" + command + " >/dev/null 2>&1 & pid=$!; for i in $(seq 100); do ls '" + dir.string() +
        "' | grep -q tmp && break; sleep 0.1; done; sleep 1; kill -9 $pid; wait $pid)");
  CHECK_FALSE(fs::exists(video));
}

TEST_CASE("render: an output folder with an earlier run's frames is refused unless --overwrite") {
  fs::path dir = test::freshDirectory("render_overwrite");
  std::string args = std::string(kSmallScene) + " --frames 2 --out " + dir.string();
  REQUIRE(test::runThrong(args).exitCode == 0);
  auto again = test::runThrong(args);
  CHECK(again.exitCode == 1);
  CHECK(again.output.find("earlier run") != std::string::npos);
  CHECK(test::runThrong(args + " --overwrite").exitCode == 0);

  auto bad =
      test::runThrong(std::string(kSmallScene) + " --frames 2 --video " + (dir / "x.avi").string());
  CHECK(bad.exitCode == 1);
  CHECK(bad.output.find(".mp4") != std::string::npos);
  auto both =
      test::runThrong(std::string(kSmallScene) + " --frames 2 --seconds 1 --out " + dir.string());
  CHECK(both.exitCode == 2);
}
