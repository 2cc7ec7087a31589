// `throng view` end to end under a private Xvfb: the window's last frame against the headless
// render of the same scene, scripted input moving the camera, resize and close, and the errors
// without a display or with bad options.
#include <doctest/doctest.h>

#include <cmath>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "crowd/scenario.h"
#include "crowd/trajectories.h"
#include "render/camera.h"
#include "render/camera_control.h"
#include "test_support.h"
#include "view_run.h"

using namespace throng;
namespace fs = std::filesystem;

namespace {

constexpr const char* kScene = "-n 200 --size 800x450 --seed 7 --camera wide";
constexpr int kFrames = 30;

using test::firstNonSnakeKey;
using test::runView;
using test::ViewRun;
using test::writeText;

glm::vec3 vec3Of(const nlohmann::json& j) {
  return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

render::Camera defaultCamera(const std::string& preset = "wide") {
  crowd::ScenarioOptions scenario;
  scenario.characters = 200;
  scenario.seed = 7;
  return render::cameraPreset(preset, crowd::scenarioExtent(scenario));
}

// The headless frame `kFrames` of the same scene, rendered once for the whole suite.
const ImageRgba8& headlessFrame() {
  static ImageRgba8 image = [] {
    fs::path out = test::freshDirectory("view_headless");
    test::CommandResult run = test::runThrong(std::string("render ") + kScene + " --frames " +
                                              std::to_string(kFrames) + " --out " + out.string());
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04d.png", kFrames - 1);
    return readPng(out / name);
  }();
  return image;
}

double meanAbsErrorIn(const ImageRgba8& a, const ImageRgba8& b, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  long n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x, ++n)
      sum += std::abs(a.at(x, y).r - b.at(x, y).r) + std::abs(a.at(x, y).g - b.at(x, y).g) +
             std::abs(a.at(x, y).b - b.at(x, y).b);
  return n ? sum / (3.0 * n) : 0.0;
}

}  // namespace

TEST_CASE("view: the last frame without the panel is the headless render of the same scene") {
  fs::path out = test::freshDirectory("view_screenshot_plain");
  ViewRun run =
      runView(std::string(kScene) + " --frames " + std::to_string(kFrames) +
              " --no-panel --validation" + " --screenshot " + (out / "view.png").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  CHECK(run.result.output.find("vulkan validation") == std::string::npos);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["validation_messages"] == 0);
  CHECK(run.stats["frames"] == kFrames);
  CHECK(run.stats["width"] == 800);
  CHECK(run.stats["height"] == 450);
  CHECK(run.stats["clock"] == "fixed");
  CHECK(run.stats["characters"] == 200);
  CHECK(run.stats["gpu_ms"]["render"].get<double>() > 0.0);
  // The method's defaults: the coverage LOD and the motion cache, as in `throng render`.
  CHECK(run.stats["lod"]["enabled"] == true);
  CHECK(run.stats["schema"] == "throng.view_stats");
  CHECK(run.stats["version"] == 1);
  CHECK(firstNonSnakeKey(run.stats) == "");
  CHECK(run.stats["cache"].is_object());

  ImageRgba8 actual = readPng(out / "view.png");
  const ImageRgba8& expected = headlessFrame();
  REQUIRE(actual.width == expected.width);
  REQUIRE(actual.height == expected.height);
  ImageDiff diff = compareImages(actual, expected, 24);
  MESSAGE("view vs render: mean ", diff.meanAbsError, ", pixels over threshold ",
          diff.fractionDifferent * 100.0, "%");
  if (diff.meanAbsError >= 1.0) writePngAtomic(out / "diff.png", diff.diffImage);
  CHECK(diff.meanAbsError < 1.0);
  CHECK(diff.fractionDifferent < 0.005);
}

TEST_CASE(
    "view: with the panel, the frame outside it is the headless render and the panel is drawn") {
  fs::path out = test::freshDirectory("view_screenshot_panel");
  ViewRun run = runView(std::string(kScene) + " --frames " + std::to_string(kFrames) +
                        " --validation --screenshot " + (out / "view.png").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["validation_messages"] == 0);
  const nlohmann::json& panel = run.stats["panel"];
  REQUIRE(panel["visible"] == true);
  int x0 = int(std::floor(panel["x"].get<double>())) - 2,
      y0 = int(std::floor(panel["y"].get<double>())) - 2;
  int x1 = int(std::ceil(panel["x"].get<double>() + panel["width"].get<double>())) + 2;
  int y1 = int(std::ceil(panel["y"].get<double>() + panel["height"].get<double>())) + 2;
  REQUIRE(x1 - x0 > 100);
  REQUIRE(x1 < 600);  // the panel leaves most of the window to the crowd

  ImageRgba8 actual = readPng(out / "view.png");
  const ImageRgba8& expected = headlessFrame();
  REQUIRE(actual.width == expected.width);
  REQUIRE(actual.height == expected.height);
  x0 = std::max(0, x0), y0 = std::max(0, y0), x1 = std::min(actual.width, x1),
  y1 = std::min(actual.height, y1);
  double inside = meanAbsErrorIn(actual, expected, x0, y0, x1, y1);
  MESSAGE("panel area differs from the crowd alone by ", inside, " on average");
  CHECK(inside > 10.0);
  ImageRgba8 masked = actual;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) masked.at(x, y) = expected.at(x, y);
  ImageDiff diff = compareImages(masked, expected, 24);
  MESSAGE("outside the panel: mean ", diff.meanAbsError, ", over threshold ",
          diff.fractionDifferent * 100.0, "%");
  CHECK(diff.meanAbsError < 1.0);
  CHECK(diff.fractionDifferent < 0.005);
}

TEST_CASE("view: a scripted drag orbits the camera about its target") {
  fs::path out = test::freshDirectory("view_orbit");
  writeText(out / "orbit.txt",
            "# 100 pixels to the right over 10 frames\ndrag 600 200 700 200 10\nwait 2\n");
  ViewRun run = runView(std::string(kScene) + " --frames 20 --no-lod --input-script " +
                        (out / "orbit.txt").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  render::Camera before = defaultCamera();
  render::Camera after = before;
  after.eye = vec3Of(run.stats["camera"]["eye"]);
  after.target = vec3Of(run.stats["camera"]["target"]);
  CHECK(glm::length(after.eye - before.eye) > 1.0f);
  CHECK(glm::length(after.target - before.target) < 1e-3f);
  CHECK(render::cameraDistance(after) ==
        doctest::Approx(render::cameraDistance(before)).epsilon(1e-4));
  CHECK(render::cameraPitchDegrees(after) ==
        doctest::Approx(render::cameraPitchDegrees(before)).epsilon(1e-3));
  float yawChange = render::cameraYawDegrees(after) - render::cameraYawDegrees(before);
  yawChange = std::remainder(yawChange, 360.0f);
  CHECK(yawChange == doctest::Approx(-100.0f * render::kOrbitDegreesPerPixel).epsilon(1e-3));
  // Without the coverage LOD every joint stays active whatever the camera.
  CHECK(run.stats["active_joints"] == 200 * run.stats["joints_per_character"].get<int>());
  CHECK(run.stats["lod"]["enabled"] == false);
  CHECK(run.stats["lod"]["levels"] == nlohmann::json::array({0, 0, 200}));
}

TEST_CASE("view: number keys pick presets and the wheel zooms toward the target") {
  fs::path out = test::freshDirectory("view_keys");
  writeText(out / "keys.txt", "key 2\nwait 1\nscroll 3\nwait 1\n");
  ViewRun run =
      runView(std::string(kScene) + " --frames 8 --input-script " + (out / "keys.txt").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  render::Camera top = defaultCamera("top");
  glm::vec3 eye = vec3Of(run.stats["camera"]["eye"]),
            target = vec3Of(run.stats["camera"]["target"]);
  CHECK(glm::length(target - top.target) < 1e-3f);
  float expected = render::cameraDistance(top) * std::pow(render::kZoomPerStep, 3.0f);
  CHECK(glm::length(eye - target) == doctest::Approx(expected).epsilon(1e-4));
  CHECK(glm::dot(glm::normalize(eye - target), glm::normalize(top.eye - top.target)) > 0.99999f);
}

TEST_CASE("view: Space pauses and N steps one frame") {
  fs::path out = test::freshDirectory("view_pause");
  writeText(out / "pause.txt", "key SPACE\nwait 5\nkey N\nwait 2\n");
  ViewRun run = runView(std::string(kScene) + " --frames 10 --no-panel --input-script " +
                        (out / "pause.txt").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["frames"] == 10);
  CHECK(run.stats["paused"] == true);
  CHECK(run.stats["simulated_seconds"].get<double>() == doctest::Approx(1.0 / 30.0).epsilon(1e-4));
}

TEST_CASE(
    "view: a respawn and periodic speed changes rebuild the crowd while frames are in flight") {
  fs::path out = test::freshDirectory("view_respawn");
  writeText(out / "respawn.txt", "wait 3\nrespawn 300 circle\nwait 3\n");
  ViewRun run = runView(std::string(kScene) +
                        " --frames 12 --no-lod --validation --speed-period 0.1 --input-script " +
                        (out / "respawn.txt").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["validation_messages"] == 0);
  CHECK(run.stats["respawns"] == 1);
  CHECK(run.stats["characters"] == 300);
  CHECK(run.stats["active_joints"] == 300 * run.stats["joints_per_character"].get<int>());
  CHECK(run.stats["speed_changes"].get<int>() >= 2);
}

TEST_CASE("view: the motion cache counts what `throng render --cache` counts for the same frames") {
  const std::string scene = std::string(kScene) + " --cache --speed-period 0.2 --frames 12";
  fs::path out = test::freshDirectory("view_cache");
  ViewRun run = runView(scene + " --validation");
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["validation_messages"] == 0);
  const nlohmann::json& cache = run.stats["cache"];
  REQUIRE(cache.is_object());
  CHECK(cache["misses"].get<int>() > 0);
  CHECK(cache["hits"].get<int>() > 0);
  CHECK(cache["entries"].get<int>() > 0);
  CHECK(cache["bytes_used"].get<uint64_t>() <= cache["budget_bytes"].get<uint64_t>());

  test::CommandResult render = test::runThrong("render " + scene + " --out " + out.string());
  INFO(render.output);
  REQUIRE(render.exitCode == 0);
  unsigned hits = 0, misses = 0, evictions = 0, entries = 0;
  size_t at = render.output.find("motion cache: ");
  REQUIRE(at != std::string::npos);
  REQUIRE(std::sscanf(render.output.c_str() + at,
                      "motion cache: %u hits, %u misses, %u evictions, %u entries", &hits, &misses,
                      &evictions, &entries) == 4);
  CHECK(cache["hits"] == hits);
  CHECK(cache["misses"] == misses);
  CHECK(cache["evictions"] == evictions);
  CHECK(cache["entries"] == entries);
}

TEST_CASE("view: resize, F12 and close are handled") {
  fs::path out = test::freshDirectory("view_resize");
  writeText(out / "resize.txt", "resize 400 300\nwait 10\nkey F12\nwait 2\nclose\n");
  fs::path previous = fs::current_path();
  fs::current_path(out);  // F12 writes into the working directory
  ViewRun run =
      runView(std::string(kScene) + " --frames 500 --validation --input-script resize.txt");
  fs::current_path(previous);
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  REQUIRE(run.stats.is_object());
  CHECK(run.stats["validation_messages"] == 0);
  CHECK(run.stats["frames"].get<int>() < 500);  // closed by the script
  CHECK(run.stats["width"] == 400);
  CHECK(run.stats["height"] == 300);
  CHECK(run.stats["swapchain_rebuilds"].get<int>() >= 1);
  REQUIRE(fs::exists(out / "throng_view_0001.png"));
  ImageRgba8 shot = readPng(out / "throng_view_0001.png");
  CHECK(shot.width == 400);
  CHECK(shot.height == 300);
}

TEST_CASE("view: without a display it fails clearly and points at throng render") {
  test::useDisplay("");
  test::CommandResult run = test::runThrong(std::string("view ") + kScene + " --frames 2");
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(run.output.find(
            "error: no display: set DISPLAY or use `throng render` for headless frames") !=
        std::string::npos);

  test::useDisplay(":1234");  // no server there
  run = test::runThrong(std::string("view ") + kScene + " --frames 2");
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(run.output.find("no display: cannot open display ':1234'") != std::string::npos);
  CHECK(run.output.find("throng render") != std::string::npos);
}

// Bad choices and out-of-range numbers are usage errors (exit 2): tests/tools/test_cli.cpp.
TEST_CASE("view: bad options fail like throng render, before any window opens") {
  test::useDisplay("");  // the option errors come first, display or not
  fs::path out = test::freshDirectory("view_bad_options");
  writeText(out / "bad.txt", "wait 2\njump 3\n");
  writeText(out / "huge.txt", "wait 2\ndrag 1e308 2 3 4\n");
  struct Case {
    std::string args;
    std::string message;
  };
  const Case cases[] = {
      {"--size 12x", "--size: expected WxH"},
      {"--slow /nonexistent/slow.bvh --fast /nonexistent/fast.bvh",
       "/nonexistent/slow.bvh: cannot open"},
      {"--eye 1,2", "--eye: expected three numbers"},
      {"--screenshot " + (out / "x.png").string(), "--screenshot needs --frames"},
      {"--frames 3 --screenshot " + (out / "x.jpg").string(), "--screenshot: expected a .png path"},
      {"--clock sometimes", "--clock: expected real or fixed"},
      {"--input-script " + (out / "missing.txt").string(), "missing.txt"},
      {"--input-script " + (out / "bad.txt").string(), "bad.txt:2: unknown command 'jump'"},
      // A drag this far made the camera NaN and the run exit 0.
      {"--input-script " + (out / "huge.txt").string(),
       "huge.txt:2: expected X0 in -100000..100000, got '1e308'"},
      {"--cache --bucket-width 1e-9", "at most 4096 speed buckets"},
  };
  for (const Case& c : cases) {
    test::CommandResult run = test::runThrong("view " + c.args);
    INFO(c.args, " → ", run.output);
    CHECK(run.exitCode == 1);
    CHECK(run.output.find(c.message) != std::string::npos);
    CHECK(run.output.find("no display") == std::string::npos);
  }
  CHECK_FALSE(fs::exists(out / "x.png"));
}

TEST_CASE("view: --trajectories-out records the crowd of every presented frame as PedPy text") {
  fs::path out = test::freshDirectory("view_trajectories");
  ViewRun run = runView(std::string(kScene) + " --frames 6 --no-panel --trajectories-out " +
                        (out / "t.txt").string());
  INFO(run.result.output);
  REQUIRE(run.result.exitCode == 0);
  const crowd::Trajectories t = crowd::loadTrajectories(out / "t.txt");
  CHECK(t.format == crowd::TrajectoryFormat::PedPy);
  CHECK(t.sampleCount == 200 * 6);
  CHECK(t.tracks.size() == 200);
  CHECK(t.secondsPerFrame == doctest::Approx(1.0 / 30.0).epsilon(1e-5));
}
