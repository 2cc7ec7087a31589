// `throng render` end to end: a golden image of a small fixed scene, and bad options that must
// fail clearly without leaving files behind.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.h"
#include "core/file_io.h"
#include "core/image.h"
#include "crowd/trajectories.h"
#include "gpu_fixture.h"
#include "synth/gpu_types.h"
#include "test_support.h"

using namespace throng;
namespace fs = std::filesystem;

namespace {
constexpr const char* kGoldenArgs =
    "render --characters 50 --size 320x180 --seed 7 --frames 4 --camera closeup --eye 6,3.5,-9 "
    "--validation --no-lod --no-cache";

size_t fileCount(const fs::path& dir) {
  size_t n = 0;
  for (const auto& entry : fs::directory_iterator(dir)) n += entry.is_regular_file() ? 1 : 0;
  return n;
}
}  // namespace

TEST_CASE("render: a small fixed scene matches the stored golden image") {
  fs::path out = test::freshDirectory("golden_render");
  test::CommandResult run = test::runThrong(std::string(kGoldenArgs) + " --out " + out.string());
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  CHECK(run.output.find("validation message") == std::string::npos);
  CHECK(fileCount(out) == 4);
  ImageRgba8 actual = readPng(out / "frame_0003.png");
  fs::path goldenPath = fs::path(THRONG_GOLDEN_DIR) / "small_scene.png";
  REQUIRE_MESSAGE(fs::exists(goldenPath), "missing golden image; run scripts/update_goldens.sh");
  ImageRgba8 golden = readPng(goldenPath);
  ImageDiff diff = compareImages(actual, golden, 24);
  MESSAGE("golden diff: mean ", diff.meanAbsError, ", pixels over threshold ",
          diff.fractionDifferent * 100.0, "%");
  bool ok = diff.meanAbsError < 1.5 && diff.fractionDifferent < 0.01;
  if (!ok) {
    writePngAtomic(out / "actual.png", actual);
    writePngAtomic(out / "diff.png", diff.diffImage);
    MESSAGE("wrote ", (out / "actual.png").string(), " and ", (out / "diff.png").string());
  }
  CHECK(ok);
  // Not a blank frame: characters cover a real part of the picture.
  size_t coloured = 0;
  for (const Rgba8& p : actual.pixels)
    coloured += (std::max({p.r, p.g, p.b}) - std::min({p.r, p.g, p.b}) > 60) ? 1 : 0;
  CHECK(coloured > actual.pixels.size() / 50);
}

TEST_CASE("render: bad options fail clearly and write nothing") {
  fs::path out = test::freshDirectory("bad_options");
  struct Case {
    std::string args;
    std::string message;
  };
  const Case cases[] = {
      {"--characters -5", "--characters: expected 1..4000000, got -5"},
      {"--scene stadium", "unknown scene 'stadium'"},
      {"--size 12x", "--size: expected WxH"},
      {"--camera orbit", "unknown camera preset 'orbit'"},
      {"--slow /nonexistent/slow.bvh --fast /nonexistent/fast.bvh",
       "/nonexistent/slow.bvh: cannot open"},
      {"--slow only.bvh", "--slow and --fast must be given together"},
      {"--frames 0", "--frames: Value 0 not in range 1 to 100000"},
      {"--eye 1,2", "--eye: expected three numbers"},
      // 1e9 speed buckets made 4 GB per-bucket buffers (a crash); the count is bounded.
      {"--cache --bucket-width 1e-9",
       "--bucket-width: expected a speed-weight width in 1/4095..1 (at most 4096"},
      {"--cache --bucket-width 0.0002", "at most 4096 speed buckets"},
      // --fov 0 meant "the preset's" although the message says 1..170.
      {"--fov 0", "--fov: expected 1..170 degrees, got 0"},
      {"--fov 170.5", "--fov: expected 1..170 degrees"},
      {"--fov nan", "--fov: expected 1..170 degrees"},
      // Options that do nothing in the chosen scene.
      {"--policy none", "--policy: steers the storyboard and circle scenes"},
      {"--radius 0.5", "--radius: steers the storyboard and circle scenes"},
      {"--scene circle --speed-period 1 --policy none", "not 'circle'"},
      {"--scene circle --density 2", "--density: spaces the random scene, not 'circle'"},
      {"--cell 2", "--cell: belongs to the storyboard scene"},
      {"--no-cache --cache-budget 10", "--cache-budget: needs the motion cache"},
      {"--no-lod --lod-mid-pixels 3", "--lod-mid-pixels: needs the coverage LOD"},
      {"--no-lod --lod-tint", "--lod-tint: needs the coverage LOD"},
      // The update-rate LOD needs every character's own step where others read them.
      {"--no-lod --lod-update-lag 2", "--lod-update-lag: needs the coverage LOD"},
      {"--scene circle --lod-update-lag 2", "--lod-update-lag: only for the random crowd"},
      {"--menge /nonexistent.xml --lod-update-lag 2", "--lod-update-lag: only for the random"},
      {"--lod-update-lag 2 --trajectories-out t.txt", "without --trajectories-out"},
      {"--lod-update-lag -1", "--lod-update-lag"},
      {"--policy boids", "--policy"},
  };
  for (const Case& c : cases) {
    test::CommandResult run = test::runThrong("render " + c.args + " --out " + out.string());
    INFO(c.args, " → ", run.output);
    CHECK(run.exitCode != 0);
    CHECK(run.output.find(c.message) != std::string::npos);
    CHECK(fileCount(out) == 0);
  }
  // An output path that is a file, not a directory.
  fs::path file = out / "not_a_dir";
  {
    std::FILE* f = std::fopen(file.c_str(), "w");
    std::fclose(f);
  }
  test::CommandResult run = test::runThrong("render --frames 1 --out " + file.string());
  CHECK(run.exitCode != 0);
  CHECK(run.output.find("not a directory") != std::string::npos);
}

// Past a device limit the run stops before the first frame with the option and the limit named,
// instead of binding more than the device allows (undefined behaviour without validation).
TEST_CASE("render: options past the device's limits name the option and the limit") {
  const gpu::DeviceInfo& info = test::gpuContext().info();
  fs::path out = test::freshDirectory("device_limits");
  struct Case {
    std::string args, option, limit;
  };
  std::vector<Case> cases;
  // The joint splat keeps 8 bytes a pixel in one storage binding.
  const auto side = static_cast<uint32_t>(std::sqrt(double(info.maxStorageBufferRange) / 8.0)) + 2;
  if (info.int64Atomics && side <= 16384) {
    const std::string size = std::to_string(side) + "x" + std::to_string(side);
    cases.push_back({"-n 10 --size " + size, "--size " + size + ": ", "maxStorageBufferRange"});
  }
  // The cache's data is one storage binding of the budget.
  const double budgetMb = double(info.maxStorageBufferRange) / 1048576.0 + 8.0;
  if (budgetMb <= 65536.0) {
    const std::string budget = std::to_string(int(budgetMb));
    cases.push_back({"-n 10 --cache --cache-budget " + budget, "--cache-budget " + budget + ": ",
                     "maxStorageBufferRange"});
  }
  // 4M characters' joint points (25 joints of 16 bytes) outgrow one buffer or heap here, or
  // the list of their joints (4 bytes each) one storage binding.
  const uint64_t largestBuffer = info.maxBufferSize > 0
                                     ? std::min(info.maxBufferSize, info.deviceLocalBytes)
                                     : info.deviceLocalBytes;
  if (uint64_t(4000000) * 25 * sizeof(throng::gpu_types::JointPoint) > largestBuffer ||
      uint64_t(4000000) * 25 * sizeof(uint32_t) > info.maxStorageBufferRange)
    cases.push_back({"-n 4000000", "-n 4000000: ", ""});
  for (const Case& c : cases) {
    test::CommandResult run =
        test::runThrong("render " + c.args + " --frames 1 --validation --out " + out.string());
    INFO(c.args, " → ", run.output);
    CHECK(run.exitCode == 1);
    CHECK(run.output.find("error: " + c.option) != std::string::npos);
    CHECK(run.output.find(c.limit) != std::string::npos);
    CHECK(run.output.find(info.name) != std::string::npos);
    CHECK(run.output.find("vulkan validation") == std::string::npos);
    CHECK(fileCount(out) == 0);
  }
}

// --trajectories-out: the PedPy text and the CSV of one run hold the same positions, and
// `crowd metrics` reads the PedPy text back.
TEST_CASE("render: --trajectories-out writes PedPy text and CSV that crowd metrics reads") {
  fs::path out = test::freshDirectory("trajectories_out");
  const std::string scene =
      "render --scene circle -n 30 --frames 40 --size 96x64 --overwrite --out " +
      (out / "frames").string();
  for (const char* name : {"t.txt", "t.csv"}) {
    test::CommandResult run =
        test::runThrong(scene + " --trajectories-out " + (out / name).string());
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    CHECK(run.output.find("trajectories of 30 agents over 40 frames") != std::string::npos);
  }
  const crowd::Trajectories text = crowd::loadTrajectories(out / "t.txt");
  REQUIRE(text.tracks.size() == 30);
  CHECK(text.secondsPerFrame == doctest::Approx(1.0 / 30.0).epsilon(1e-5));
  // CSV rows: id,frame,time,x,y,z,... in engine coordinates; PedPy (x, y) = engine (x, z).
  std::istringstream csv(readTextFile(out / "t.csv"));
  std::string line;
  std::getline(csv, line);
  CHECK(line == "id,frame,time,x,y,z,heading,speed,group,state");
  size_t rows = 0;
  double worst = 0.0;
  while (std::getline(csv, line)) {
    int id = 0, frame = 0;
    double time = 0, x = 0, y = 0, z = 0;
    REQUIRE(std::sscanf(line.c_str(), "%d,%d,%lf,%lf,%lf,%lf", &id, &frame, &time, &x, &y, &z) ==
            6);
    REQUIRE(id < 30);
    const glm::vec2 p = text.tracks[size_t(id)].points.at(size_t(frame)).position;
    worst = std::max({worst, std::abs(p.x - x), std::abs(p.y - z)});
    ++rows;
  }
  CHECK(rows == 30 * 40);
  CHECK(worst <= 1e-4);
  test::CommandResult metrics = test::runThrong(
      "crowd metrics --cpu --policy none --trajectories " + (out / "t.txt").string());
  INFO(metrics.output);
  CHECK(metrics.exitCode == 0);
  CHECK(metrics.output.find("30 people") != std::string::npos);
  test::CommandResult bad =
      test::runThrong(scene + " --trajectories-out " + (out / "t.json").string());
  CHECK(bad.exitCode != 0);
  CHECK(bad.output.find("--trajectories-out") != std::string::npos);
  CHECK(!fs::exists(out / "t.json"));
}
