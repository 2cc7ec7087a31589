// Animation out: synthesized motion exported as BVH (round trip through the importer) and as
// glTF 2.0 (checked by the Khronos glTF-Validator when it is installed).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "anim/animation_export.h"
#include "anim/bvh.h"
#include "anim/default_clips.h"
#include "anim/euler.h"
#include "anim/gltf_export.h"
#include "anim/reference_synth.h"
#include "cli_support.h"
#include "core/error.h"
#include "core/math.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace throng;
using namespace throng::anim;

namespace {

// World joint positions of an imported clip's frame.
std::vector<glm::vec3> clipWorldPositions(const Clip& clip, int frame) {
  std::vector<glm::vec3> position(size_t(clip.jointCount()));
  std::vector<glm::vec4> rotation(size_t(clip.jointCount()));
  for (int j = 0; j < clip.jointCount(); ++j) {
    int p = clip.skeleton.joints[size_t(j)].parent;
    glm::vec4 q = clip.rotation(frame, j);
    if (p < 0) {
      position[size_t(j)] = clip.offset(frame, j);
      rotation[size_t(j)] = q;
    } else {
      position[size_t(j)] =
          position[size_t(p)] + quatRotate(rotation[size_t(p)], clip.offset(frame, j));
      rotation[size_t(j)] = quatMul(rotation[size_t(p)], q);
    }
  }
  return position;
}

// World joint positions from the joint points the renderer gets (the GPU passes' twin).
std::vector<glm::vec3> synthesizedPositions(const MotionPair& pair, const glm::vec4& placement,
                                            const glm::vec4& motion) {
  std::vector<glm::vec4> points(size_t(pair.jointCount()));
  poseCharacter(pair, placement, motion, points);
  std::vector<glm::vec3> position;
  for (const glm::vec4& point : points) position.push_back(glm::vec3(point));
  return position;
}

struct PairCase {
  const char* name;
  ClipPair clips;
};

std::vector<PairCase> pairCases() {
  std::vector<PairCase> cases;
  cases.push_back({"built-in run", defaultRunPair()});
  const fs::path data = THRONG_SHARED_DATA_DIR;
  const fs::path bandai = data / "bvh/bandai_namco", cmu = data / "bvh/cmu";
  if (fs::exists(bandai) && fs::exists(cmu)) {
    cases.push_back({"Bandai run+dash", loadClipPair(bandai / "dataset-1_run_normal_001.bvh",
                                                     bandai / "dataset-1_dash_normal_001.bvh")});
    cases.push_back(
        {"CMU 35_17+09_01", loadClipPair(cmu / "cmu_35_17_runjog.bvh", cmu / "cmu_09_01_run.bvh")});
  } else {
    MESSAGE("skipped the Bandai and CMU pairs: ../shared/data/bvh is absent");
  }
  return cases;
}

throng::test::CommandResult runShell(const std::string& command) {
  throng::test::CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
  int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

bool haveValidator() {
  return fs::exists(fs::path(THRONG_SOURCE_DIR) /
                    "build-tools/gltf-validator/node_modules/gltf-validator") &&
         std::system("node --version >/dev/null 2>&1") == 0;
}

}  // namespace

TEST_CASE("export: Euler ZXY degrees turn back into the same rotation") {
  std::mt19937 rng(7);
  std::normal_distribution<float> n;
  const std::vector<Channel> zxy = {Channel::Zrotation, Channel::Xrotation, Channel::Yrotation};
  for (int i = 0; i < 2000; ++i) {
    glm::quat q = glm::normalize(glm::quat(n(rng), n(rng), n(rng), n(rng)));
    glm::vec3 e = eulerZxyDegrees(q);
    glm::vec4 back = channelsToQuat(zxy, std::vector<float>{e.x, e.y, e.z});
    CHECK(std::abs(back.x * q.x + back.y * q.y + back.z * q.z + back.w * q.w) ==
          doctest::Approx(1.0).epsilon(1e-5));
  }
}

TEST_CASE("export: invalid requests are errors") {
  ClipPair clips = defaultRunPair();
  MotionPair pair = makeMotionPair(clips.slow, clips.fast);
  Skeleton other = clips.slow.skeleton;
  other.joints.pop_back();
  CHECK_THROWS_AS(recordCharacter(pair, other, glm::vec4(0), glm::vec4(0, 0.5f, 0.5f, 1), {}),
                  Error);
  RecordOptions none;
  none.frames = 0;
  CHECK_THROWS_AS(
      recordCharacter(pair, clips.slow.skeleton, glm::vec4(0), glm::vec4(0, 0.5f, 0.5f, 1), none),
      Error);
  CHECK_THROWS_AS(formatGlb({}), Error);
}

TEST_CASE("export: the exported BVH re-imported equals the synthesized poses (<= 1e-4 m)") {
  for (PairCase& c : pairCases()) {
    CAPTURE(c.name);
    MotionPair pair = makeMotionPair(c.clips.slow, c.clips.fast);
    for (float w : {0.0f, 0.5f, 1.0f}) {
      CAPTURE(w);
      glm::vec4 placement(3.0f, 0.0f, -2.0f, 0.7f), motion(0.3f, w, w, 1.1f);
      RecordOptions options;
      options.frames = 45;
      JointAnimation animation =
          recordCharacter(pair, c.clips.slow.skeleton, placement, motion, options);
      Clip imported = toClip(parseBvh(formatBvh(toBvhClip(animation)), "export.bvh"));
      REQUIRE(imported.frameCount == options.frames);
      REQUIRE(imported.jointCount() == pair.jointCount());
      float worst = 0.0f;
      for (int f = 0; f < options.frames; ++f) {
        std::vector<glm::vec3> expected = synthesizedPositions(pair, placement, motion);
        std::vector<glm::vec3> fromFile = clipWorldPositions(imported, f);
        std::vector<glm::vec3> fromAnimation = worldPositions(animation, f);
        for (int j = 0; j < pair.jointCount(); ++j) {
          worst = std::max(worst, glm::length(fromFile[size_t(j)] - expected[size_t(j)]));
          worst = std::max(worst, glm::length(fromAnimation[size_t(j)] - expected[size_t(j)]));
        }
        stepCharacter(pair, placement, motion, options.dt, Steering::KeepHeading);
      }
      CHECK(worst <= 1e-4f);
    }
  }
}

TEST_CASE("export: throng export writes glTF that the Khronos validator passes, and BVH") {
  using throng::test::runThrong;
  fs::path dir = throng::test::freshDirectory("export_cli");
  auto bad = runThrong("export --out " + (dir / "a.txt").string());
  CHECK(bad.exitCode == 1);
  CHECK(bad.output.find(".glb or .bvh") != std::string::npos);
  CHECK(runThrong("export -n 3 --agents 3 --out " + (dir / "a.glb").string()).exitCode == 1);
  CHECK(runThrong("export --lod --out " + (dir / "a.glb").string()).output.find("does nothing") !=
        std::string::npos);

  auto bvh = runThrong("export -n 4 --agents 1,3 --frames 20 --out " + (dir / "two.bvh").string());
  REQUIRE(bvh.exitCode == 0);
  CHECK(loadBvh(dir / "two_000001.bvh").frameCount == 20);
  CHECK(loadBvh(dir / "two_000003.bvh").frameCount == 20);

  const fs::path data = THRONG_SHARED_DATA_DIR;
  std::vector<std::string> pairs = {""};
  if (fs::exists(data / "bvh")) {
    pairs.push_back(" --slow " + (data / "bvh/bandai_namco/dataset-1_run_normal_001.bvh").string() +
                    " --fast " +
                    (data / "bvh/bandai_namco/dataset-1_dash_normal_001.bvh").string());
    pairs.push_back(" --slow " + (data / "bvh/cmu/cmu_35_17_runjog.bvh").string() + " --fast " +
                    (data / "bvh/cmu/cmu_09_01_run.bvh").string());
  }
  for (size_t i = 0; i < pairs.size(); ++i) {
    fs::path glb = dir / ("pair" + std::to_string(i) + ".glb");
    auto r =
        runThrong("export --scene circle -n 3 --frames 30" + pairs[i] + " --out " + glb.string());
    CAPTURE(r.output);
    REQUIRE(r.exitCode == 0);
    REQUIRE(fs::file_size(glb) > 1000);
    if (!haveValidator()) {
      MESSAGE(
          "glTF-Validator not installed (scripts/install_deps.sh installs it): only the export "
          "ran");
      continue;
    }
    auto v =
        runShell("node " + (fs::path(THRONG_SOURCE_DIR) / "scripts/validate_gltf.js").string() +
                 " " + glb.string());
    CAPTURE(v.output);
    CHECK(v.exitCode == 0);
    CHECK(v.output.find("errors 0 ") != std::string::npos);
  }
}
