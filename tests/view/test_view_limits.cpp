// `throng view` past the device's limits: the crowd it starts with and script resizes fail
// naming the option or script line and the limit; a respawn past them is refused with that
// message and the viewer goes on with the crowd it had.
#include <doctest/doctest.h>

#include <cmath>

#include "gpu_fixture.h"
#include "synth/gpu_types.h"
#include "test_support.h"
#include "view_run.h"

using namespace throng;
namespace fs = std::filesystem;

namespace {
constexpr const char* kScene = "-n 200 --size 320x180 --seed 7 --camera wide --no-panel";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The largest buffer this device creates (its heap when it does not say).
uint64_t largestBuffer(const gpu::DeviceInfo& info) {
  return info.maxBufferSize > 0 ? std::min(info.maxBufferSize, info.deviceLocalBytes)
                                : info.deviceLocalBytes;
}
}  // namespace

TEST_CASE("view: a respawn past the device's limits is refused by name and the crowd stays") {
  const gpu::DeviceInfo& info = test::gpuContext().info();
  // 4M characters' joint points (25 joints of 16 bytes) in one buffer.
  if (uint64_t(4000000) * 25 * sizeof(throng::gpu_types::JointPoint) <= largestBuffer(info)) {
    MESSAGE("4M characters fit ", info.name, ": nothing to refuse");
    return;
  }
  fs::path out = test::freshDirectory("view_respawn_limit");
  test::writeText(out / "big.txt", "wait 2\nrespawn 4000000\nwait 3\n");
  test::ViewRun run =
      test::runView(std::string(kScene) + " --frames 8 --validation --input-script " +
                    (out / "big.txt").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  CHECK(contains(run.result.output,
                 "respawn failed: " + (out / "big.txt").string() + ":2: respawn 4000000: "));
  CHECK(contains(run.result.output, info.name));
  CHECK_FALSE(contains(run.result.output, "is invalid"));  // no job left without its inputs
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["frames"] == 8);
  CHECK(run.stats["characters"] == 200);
  CHECK(run.stats["respawns"] == 0);
  CHECK(run.stats["validation_messages"] == 0);
}

// A crowd that is made but outgrows a binding when its first frame is recorded: the viewer
// brings back the previous crowd and re-records the frame.
TEST_CASE(
    "view: a respawned crowd that meets a limit while recording gives way to the previous one") {
  fs::path out = test::freshDirectory("view_respawn_record_limit");
  test::writeText(out / "big.txt", "wait 2\nrespawn 1350000\nwait 2\n");
  test::ViewRun run =
      test::runView(std::string(kScene) + " --frames 5 --validation --input-script " +
                    (out / "big.txt").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["frames"] == 5);
  CHECK(run.stats["validation_messages"] == 0);
  if (contains(run.result.output, "respawn failed")) {
    MESSAGE("1350000 characters are past a limit of ", test::gpuContext().info().name);
    CHECK(contains(run.result.output, "big.txt:2: respawn 1350000: "));
    CHECK(run.stats["characters"] == 200);
    CHECK(run.stats["respawns"] == 0);
  } else {
    CHECK(run.stats["characters"] == 1350000);
    CHECK(run.stats["respawns"] == 1);
  }
}

TEST_CASE("view: the starting crowd and a script resize past the limits name -n and the line") {
  const gpu::DeviceInfo& info = test::gpuContext().info();
  fs::path out = test::freshDirectory("view_limits");
  if (uint64_t(4000000) * 25 * sizeof(throng::gpu_types::JointPoint) > largestBuffer(info)) {
    test::ViewRun run = test::runView("-n 4000000 --size 320x180 --frames 2");
    INFO(run.result.output);
    CHECK(run.result.exitCode == 1);
    CHECK(contains(run.result.output, "error: -n 4000000: "));
  }
  // The joint splat keeps 8 bytes a pixel in one storage binding.
  if (info.int64Atomics && 16384.0 * 16384.0 * 8.0 > double(info.maxStorageBufferRange)) {
    test::writeText(out / "resize.txt", "wait 2\nresize 16384 16384\nwait 2\n");
    test::ViewRun run =
        test::runView(std::string(kScene) + " --frames 6 --validation --input-script " +
                      (out / "resize.txt").string());
    INFO(run.result.output);
    CHECK(run.result.exitCode == 1);
    CHECK(contains(run.result.output, "resize.txt:2: resize 16384 16384: "));
    CHECK(contains(run.result.output, "maxStorageBufferRange"));
    CHECK_FALSE(contains(run.result.output, "vulkan validation"));
  }
}
