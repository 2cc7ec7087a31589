// The skeleton and clip pair a cape is made for: identities of prepared pairs, recorded in the
// .tsg and .tsc, and playback's check that names both pairs when the crowd plays other clips.
#include <doctest/doctest.h>

#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

#include "chunk_patch.h"
#include "cli_support.h"
#include "cloth_fixtures.h"
#include "core/error.h"
#include "secondary/clip_identity.h"
#include "secondary/cloth_database.h"
#include "secondary/offline/explore_file.h"
#include "test_support.h"

using namespace throng;
using namespace throng::secondary;

namespace {
const char* kRun = "bvh/bandai_namco/dataset-1_run_normal_001.bvh";
const char* kDash = "bvh/bandai_namco/dataset-1_dash_normal_001.bvh";

anim::ClipPair bandaiPair() {
  return anim::loadClipPair(test::sharedDataDir() / kRun, test::sharedDataDir() / kDash);
}

ClothDatabase smallDatabase() {
  PlaybackPrimary primary = test::syntheticPrimary(0.5f, {5, 4, 3});
  return test::randomDatabase(primary, test::syntheticGraph(primary, 2), test::gridMesh(6, 5), 3,
                              5);
}
}  // namespace

TEST_CASE("clip identity: the same pair gives the same identity, another skeleton another one") {
  const ClipPairIdentity builtIn = clipPairIdentity(anim::defaultRunPair());
  CHECK(builtIn.recorded());
  CHECK(builtIn.skeletonHash == builtInRunIdentity().skeletonHash);
  CHECK(builtIn.clipsHash == builtInRunIdentity().clipsHash);
  // Same skeleton, other clips (the built-in walk): the skeleton matches, the clips do not.
  const ClipPairIdentity walk = clipPairIdentity(anim::defaultWalkPair());
  CHECK(walk.skeletonHash == builtIn.skeletonHash);
  CHECK(walk.clipsHash != builtIn.clipsHash);
  CHECK_NOTHROW(checkClipsMatch(builtIn, "cape.tsc", anim::defaultRunPair()));
  CHECK_NOTHROW(checkClipsMatch({}, "old.tsc", anim::defaultRunPair()));  // not recorded: built-in
  CHECK_THROWS_WITH_AS(checkClipsMatch(builtIn, "cape.tsc", anim::defaultWalkPair()),
                       doctest::Contains("cape.tsc: the capes were made for other clips"), Error);
  if (!test::haveSharedData(kRun)) return;
  const ClipPairIdentity bandai = clipPairIdentity(bandaiPair());
  CHECK(bandai.jointCount == 22);
  CHECK(bandai.skeletonHash == clipPairIdentity(bandaiPair()).skeletonHash);
  CHECK(bandai.clipsHash == clipPairIdentity(bandaiPair()).clipsHash);
  // A database made for the built-in run on a Bandai crowd, and the other way round: both named.
  for (const auto& [made, crowd] :
       {std::pair{builtIn, bandaiPair()}, std::pair{bandai, anim::defaultRunPair()}}) {
    try {
      checkClipsMatch(made, "cape.tsc", crowd);
      FAIL("no error for a database made for another skeleton");
    } catch (const Error& e) {
      const std::string what = e.what();
      CHECK(what.find("cape.tsc: the capes were made for another skeleton") != std::string::npos);
      CHECK(what.find(made.describe()) != std::string::npos);
      CHECK(what.find(clipPairIdentity(crowd).describe()) != std::string::npos);
    }
  }
}

TEST_CASE(".tsc: the clip identity round trips; a version 2 file is read as the built-in run") {
  ClothDatabase db = smallDatabase();
  db.clips = clipPairIdentity(anim::defaultWalkPair());
  const std::vector<uint8_t> bytes = encodeClothDatabase(db);
  const ClothDatabase back = decodeClothDatabase(bytes, "walk.tsc");
  CHECK(back.clips.name == db.clips.name);
  CHECK(back.clips.jointCount == db.clips.jointCount);
  CHECK(back.clips.skeletonHash == db.clips.skeletonHash);
  CHECK(back.clips.clipsHash == db.clips.clipsHash);
  CHECK_NOTHROW(checkClothClips(back, "walk.tsc", anim::defaultWalkPair()));
  CHECK_THROWS_WITH_AS(checkClothClips(back, "walk.tsc", anim::defaultRunPair()),
                       doctest::Contains("made for other clips"), Error);
  // Version 2 had no identity: read, and taken for the built-in run.
  std::vector<uint8_t> version2 = encodeClothDatabase(smallDatabase());
  version2[8] = 2;
  version2 = test::patchChunk(version2, "VERT", [](test::RawChunk&) {});  // new checksum
  const ClothDatabase old = decodeClothDatabase(version2, "old.tsc");
  CHECK_FALSE(old.clips.recorded());
  CHECK_NOTHROW(checkClothClips(old, "old.tsc", anim::defaultRunPair()));
  CHECK_THROWS_WITH_AS(checkClothClips(old, "old.tsc", anim::defaultWalkPair()),
                       doctest::Contains("old.tsc: the capes were made for other clips"), Error);
}

TEST_CASE(
    "cloth explore --slow/--fast: the cape on the Bandai run+dash, recorded in .tsg and .tsc") {
  if (!test::haveSharedData(kRun)) return;
  const auto dir = test::freshDirectory("cloth_explore_clips");
  const auto tsg = dir / "bandai.tsg", tsc = dir / "bandai.tsc";
  const std::string clips = " --slow " + (test::sharedDataDir() / kRun).string() + " --fast " +
                            (test::sharedDataDir() / kDash).string();
  test::CommandResult r = test::runThrong(
      "cloth explore --garment-config '{\"cape\": {\"columns\": 8, \"rows\": 12}}' "
      "--budget-expansions 3 --quiet --json" +
      clips + " --out " + tsg.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const ExploreFile file = loadExploreFile(tsg);
  const ClipPairIdentity bandai = clipPairIdentity(bandaiPair());
  CHECK(file.clips.skeletonHash == bandai.skeletonHash);
  CHECK(file.clips.clipsHash == bandai.clipsHash);
  CHECK(file.primary.jointCount == 22);
  // Pinned to the Bandai skeleton's neck and shoulders.
  for (uint32_t joint : file.mesh.pinJoints) {
    const std::string& name = file.primary.jointNames[joint];
    CHECK((name == "Neck" || name.rfind("Shoulder", 0) == 0));
  }
  r = test::runThrong("cloth compress " + tsg.string() + " --out " + tsc.string() + " --quiet");
  REQUIRE(r.exitCode == 0);
  const ClothDatabase db = readClothDatabase(tsc);
  CHECK(db.clips.clipsHash == bandai.clipsHash);
  CHECK_NOTHROW(checkClothClips(db, tsc.string(), bandaiPair()));
  CHECK_THROWS_WITH_AS(checkClothClips(db, tsc.string(), anim::defaultRunPair()),
                       doctest::Contains("made for another skeleton"), Error);
  r = test::runThrong("cloth info " + tsc.string() + " --json");
  REQUIRE(r.exitCode == 0);
  CHECK(nlohmann::json::parse(r.output)["clips"] == bandai.name);
  // A resumed run keeps its clips; --slow alone is refused.
  r = test::runThrong("cloth explore --resume --quiet" + clips + " --out " + tsg.string());
  CHECK(r.exitCode != 0);
  CHECK(r.output.find("cannot change a resumed exploration") != std::string::npos);
  r = test::runThrong("cloth explore --quiet --slow " + (test::sharedDataDir() / kRun).string() +
                      " --out " + (dir / "x.tsg").string());
  CHECK(r.exitCode != 0);
  CHECK(r.output.find("--slow and --fast must be given together") != std::string::npos);
}

TEST_CASE(".tsg: a cloth vertex pinned to a joint the skeleton lacks is refused on load") {
  const auto dir = test::freshDirectory("tsg_pin_joints");
  const auto path = dir / "toy.tsg", bad = dir / "bad.tsg";
  REQUIRE(test::runThrong("cloth explore --garment toy --budget-expansions 2 --quiet --out " +
                          path.string())
              .exitCode == 0);
  std::ifstream in(path, std::ios::binary);
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                   std::istreambuf_iterator<char>()};
  const uint32_t joint = 999;
  std::vector<uint8_t> patched = test::patchChunk(bytes, "MPJT", [&](test::RawChunk& c) {
    REQUIRE(c.payload.size() >= 4);
    std::memcpy(c.payload.data(), &joint, 4);
  });
  std::ofstream(bad, std::ios::binary)
      .write(reinterpret_cast<const char*>(patched.data()), std::streamsize(patched.size()));
  CHECK_NOTHROW(loadExploreFile(path));
  CHECK_THROWS_WITH_AS(loadExploreFile(bad),
                       doctest::Contains("a cloth vertex is pinned to joint 999"), Error);
}
