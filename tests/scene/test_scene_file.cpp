// The scene file: every problem named by file, line and key path; a written file reads back the
// same; relative files resolve against the file's folder. No GPU.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include "core/error.h"
#include "render/camera_path.h"

#include "scene/example_scenes.h"
#include "scene/json_lines.h"
#include "scene/scene_file.h"

using namespace throng;

namespace {

const char* kGood = R"({
  "schema": "throng.scene",
  "version": 1,
  "seed": 7,
  "groups": [
    {"count": 500, "clips": "walk", "centre": [-20, 0], "speed": [0.2, 0.6]},
    {"count": 300, "slow": "clips/a.bvh", "fast": "clips/b.bvh", "density": 0.8}
  ],
  "speed_period": 5,
  "motion": {"lod": false, "cache": true, "bucket_width": 0.1},
  "camera": {"preset": "top", "path": [
    {"time": 0, "eye": [0, 30, -40], "target": [0, 0, 0]},
    {"time": 4, "eye": [40, 30, 0], "target": [0, 0, 0], "fov": 60}
  ]},
  "output": {"size": "640x360", "fps": 25, "seconds": 4}
})";

// The text with `from` replaced by `to` (once), parsed; returns the error message.
std::string errorOf(const std::string& text) {
  try {
    scene::parseSceneFile(text, "s.json", "/scenes");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string edited(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("scene file: a good file reads into groups, camera path and output") {
  const scene::SceneFile f = scene::parseSceneFile(kGood, "s.json", "/scenes");
  CHECK(f.seed == 7);
  CHECK(f.behaviour == "plain");
  REQUIRE(f.groups.size() == 2);
  CHECK(f.groups[0].count == 500);
  CHECK(f.groups[0].clips == "walk");
  CHECK(f.groups[0].centre.x == -20.0f);
  CHECK(f.groups[0].speedMax == doctest::Approx(0.6));
  CHECK(f.groups[1].slow == "/scenes/clips/a.bvh");  // relative to the file's folder
  CHECK(f.groups[1].density == doctest::Approx(0.8));
  CHECK(f.speedPeriod == 5.0f);
  CHECK_FALSE(f.lod);
  CHECK(f.bucketWidth == doctest::Approx(0.1));
  CHECK(f.cameraPreset == "top");
  REQUIRE(f.cameraPath.size() == 2);
  CHECK(f.cameraPath[1].fovYDegrees == 60.0f);
  CHECK(f.size == "640x360");
  CHECK(f.fps == 25.0f);
}

TEST_CASE("scene file: what is written reads back the same") {
  const scene::SceneFile f = scene::parseSceneFile(kGood, "s.json", "/scenes");
  const std::string text = scene::writeSceneFile(f);
  CHECK(text.find("0.6000000") == std::string::npos);  // floats written as typed
  const scene::SceneFile g = scene::parseSceneFile(text, "t.json", "/elsewhere");
  REQUIRE(g.groups.size() == 2);
  CHECK(g.groups[1].slow == f.groups[1].slow);  // absolute once written
  CHECK(g.groups[0].speedMin == f.groups[0].speedMin);
  CHECK(g.groups[0].centre == f.groups[0].centre);
  CHECK(g.cameraPath.size() == 2);
  CHECK(g.cameraPath[1].eye == f.cameraPath[1].eye);
  CHECK(g.speedPeriod == f.speedPeriod);
  CHECK(g.size == f.size);
  CHECK(g.seconds == f.seconds);
  CHECK(scene::writeSceneFile(g) == text);
}

TEST_CASE("scene file: problems name the line and the key path") {
  struct Case {
    std::string text, expected;
  };
  const std::string good = kGood;
  const Case cases[] = {
      {edited(good, "\"count\": 500", "\"count\": 0"),
       "s.json:6: groups[0].count: expected 1..4000000"},
      {edited(good, "\"count\": 300", "\"count\": \"many\""),
       "s.json:7: groups[1].count: expected a number"},
      {edited(good, "\"density\": 0.8", "\"dense\": 0.8"),
       "s.json:7: groups[1].dense: unknown key"},
      {edited(good, "\"walk\"", "\"swim\""),
       "s.json:6: groups[0].clips: 'swim' is not one of run, walk"},
      {edited(good, "\"time\": 4", "\"time\": 0"),
       "s.json:13: camera.path[1].time: keyframe times must increase"},
      {edited(good, "\"640x360\"", "\"640 by 360\""), "s.json:15: output.size: expected WxH"},
      {edited(good, "throng.scene", "throng.storyboard"),
       "s.json:2: schema: expected \"throng.scene\""},
      {edited(good, "\"speed\": [0.2, 0.6]", "\"speed\": [0.7, 0.6]"),
       "s.json:6: groups[0].speed: expected [low, high]"},
      {edited(good, "\"slow\": \"clips/a.bvh\", ", ""),
       "s.json:7: groups[1]: slow and fast name a BVH pair"},
      {edited(good, "\"seed\": 7", "\"seed\": 7, \"seed\": 8"), "s.json"},  // duplicate key
      {edited(good, "\"speed_period\": 5", "\"avoidance\": {\"policy\": \"none\"}"),
       "s.json:9: avoidance: the plain behaviour does not steer"},
      {edited(good, "\"seed\": 7", "\"seed\": 7, \"behaviour\": \"storyboard\""),
       "storyboard behaviour needs a storyboard"},
      {"{\"schema\": \"throng.scene\", \"version\": 1}",
       "s.json:1: scene: a plain or circle scene needs groups"},
      {"{\"schema\": \"throng.scene\", ", "s.json"},  // truncated
  };
  for (const Case& c : cases) {
    CAPTURE(c.expected);
    const std::string message = errorOf(c.text);
    CAPTURE(message);
    CHECK(message.find(c.expected) != std::string::npos);
  }
}

TEST_CASE("scene file: JSON lines and key paths") {
  const scene::JsonLines lines(kGood);
  CHECK(lines.line("/groups/1/count") == 7);
  CHECK(lines.line("/camera/path/1/eye/2") == 13);
  CHECK(lines.line("/output/missing") == 15);  // its parent's line
  CHECK(scene::keyPath("/camera/path/1/time") == "camera.path[1].time");
}

TEST_CASE("camera path: linear between keyframes, held outside them") {
  const render::CameraKey path[] = {{0.0f, {0, 10, 0}, {0, 0, 0}, 40.0f},
                                    {2.0f, {20, 10, 0}, {0, 0, 10}, 60.0f}};
  render::Camera base;
  base.nearPlane = 0.5f;
  const render::Camera mid = render::cameraAt(path, 1.0f, base);
  CHECK(mid.eye.x == doctest::Approx(10.0f));
  CHECK(mid.target.z == doctest::Approx(5.0f));
  CHECK(mid.fovYDegrees == doctest::Approx(50.0f));
  CHECK(mid.nearPlane == 0.5f);  // the rest of the camera kept
  CHECK(render::cameraAt(path, -1.0f, base).eye.x == 0.0f);
  CHECK(render::cameraAt(path, 9.0f, base).eye.x == 20.0f);
  CHECK(render::cameraAt({}, 1.0f, base).eye == base.eye);
}

TEST_CASE("the committed example scenes are what `throng assets generate` writes, and read back") {
  for (const auto& [name, scene] : scene::exampleScenes()) {
    CAPTURE(name);
    const std::filesystem::path path =
        std::filesystem::path(THRONG_SOURCE_DIR) / "assets/scenes" / name;
    REQUIRE_MESSAGE(std::filesystem::exists(path), "run `throng assets generate --out assets`");
    std::ifstream in(path);
    const std::string committed((std::istreambuf_iterator<char>(in)), {});
    CHECK_MESSAGE(committed == scene::writeSceneFile(scene),
                  "out of date: run `throng assets generate --out assets`");
    CHECK_NOTHROW(scene::readSceneFile(path));
  }
}

TEST_CASE("scene file: the corridor's tracked set is a file beside the scene, checked to exist") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "throng_corridor_set";
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "people.txt") << "0 1 0.0 0.0\n"; }
  const std::string text = R"({"schema": "throng.scene", "version": 1, "behaviour": "corridor",
  "corridor": {"length": 80, "trajectories": "people.txt"}})";
  const scene::SceneFile f = scene::parseSceneFile(text, "c.json", dir);
  CHECK(f.corridorLength == 80.0f);
  CHECK(std::filesystem::path(f.corridorTrajectories) == (dir / "people.txt").lexically_normal());
  const scene::SceneFile back =
      scene::parseSceneFile(scene::writeSceneFile(f), "c2.json", "/elsewhere");
  CHECK(back.corridorTrajectories == f.corridorTrajectories);

  try {
    scene::parseSceneFile(edited(text, "people.txt", "nobody.txt"), "c.json", dir);
    FAIL("a missing tracked set was accepted");
  } catch (const Error& e) {
    const std::string what = e.what();
    CHECK(what.find("c.json:2") != std::string::npos);
    CHECK_MESSAGE(what.find("corridor.trajectories") != std::string::npos, what);
    CHECK(what.find("nobody.txt") != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}
