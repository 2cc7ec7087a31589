// BVH import: the real captures in ../shared/data, the project's assets, every malformed
// file in tests/anim/data/bad, line endings, and robustness against truncation and edits.
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "anim/bvh.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/rng.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace throng::anim;

namespace {

const fs::path kBadDir = fs::path(THRONG_ANIM_TEST_DATA) / "bad";

std::string errorOf(const fs::path& path) {
  try {
    loadBvh(path);
  } catch (const throng::Error& e) {
    return e.what();
  }
  return "(no error)";
}

std::string errorOfText(const std::string& text) {
  try {
    parseBvh(text, "text.bvh");
  } catch (const throng::Error& e) {
    return e.what();
  }
  return "(no error)";
}

int countEndSites(const Skeleton& s) {
  int n = 0;
  for (const Joint& j : s.joints) n += j.endSite ? 1 : 0;
  return n;
}

void checkParentsFirst(const Skeleton& s) {
  REQUIRE(s.jointCount() > 0);
  CHECK(s.joints[0].parent == -1);
  for (int j = 1; j < s.jointCount(); ++j) {
    CHECK(s.joints[size_t(j)].parent >= 0);
    CHECK(s.joints[size_t(j)].parent < j);
  }
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  std::string out;
  size_t pos = 0;
  for (size_t hit; (hit = text.find(from, pos)) != std::string::npos; pos = hit + from.size()) {
    out += text.substr(pos, hit - pos) + to;
  }
  return out + text.substr(pos);
}

void checkSameClip(const RawClip& a, const RawClip& b) {
  REQUIRE(a.skeleton.jointCount() == b.skeleton.jointCount());
  for (int j = 0; j < a.skeleton.jointCount(); ++j) {
    const Joint& x = a.skeleton.joints[size_t(j)];
    const Joint& y = b.skeleton.joints[size_t(j)];
    CHECK(x.name == y.name);
    CHECK(x.parent == y.parent);
    CHECK(x.offset == y.offset);
    CHECK(x.channels == y.channels);
    CHECK(x.endSite == y.endSite);
  }
  CHECK(a.frameCount == b.frameCount);
  CHECK(a.frameTime == b.frameTime);
  CHECK(a.channelCount == b.channelCount);
  CHECK(a.values == b.values);
}

}  // namespace

TEST_CASE("CMU captures: 31 joints, 7 End Sites, 96 channels, T-pose frame counted") {
  const std::vector<std::pair<std::string, int>> files = {
      {"cmu_09_01_run.bvh", 149}, {"cmu_35_17_runjog.bvh", 168}, {"cmu_12_01_walk.bvh", 524}};
  for (const auto& file : files) {
    const std::string& name = file.first;  // a plain reference: CAPTURE keeps it in a lambda
    const int frames = file.second;
    if (!throng::test::haveSharedData("bvh/cmu/" + name)) continue;
    CAPTURE(name);
    RawClip clip = loadBvh(throng::test::sharedDataDir() / "bvh/cmu" / name);
    CHECK(clip.skeleton.jointCount() == 31);
    CHECK(countEndSites(clip.skeleton) == 7);
    CHECK(clip.channelCount == 96);
    CHECK(clip.frameCount == frames);
    CHECK(clip.frameTime == doctest::Approx(0.0083333f));
    CHECK(clip.values.size() == size_t(frames) * 96);
    checkParentsFirst(clip.skeleton);
    const Joint& root = clip.skeleton.joints[0];
    CHECK(root.name == "Hips");
    CHECK(root.channels == std::vector<Channel>{Channel::Xposition, Channel::Yposition,
                                                Channel::Zposition, Channel::Zrotation,
                                                Channel::Yrotation, Channel::Xrotation});
    for (int j = 1; j < 31; ++j) {
      CHECK(clip.skeleton.joints[size_t(j)].channels ==
            std::vector<Channel>{Channel::Zrotation, Channel::Yrotation, Channel::Xrotation});
    }
    CHECK(clip.skeleton.joints[1].name == "LHipJoint");
    CHECK(clip.skeleton.joints[2].name == "LeftUpLeg");
    CHECK(clip.skeleton.joints[2].parent == 1);
    CHECK(clip.sourceName.find(name) != std::string::npos);
  }
}

TEST_CASE("CMU 09_01: first values, End Site stored on its joint") {
  if (!throng::test::haveSharedData("bvh/cmu/cmu_09_01_run.bvh")) return;
  RawClip clip = loadBvh(throng::test::sharedDataDir() / "bvh/cmu/cmu_09_01_run.bvh");
  CHECK(clip.values[0] == doctest::Approx(-0.3071f));
  CHECK(clip.values[1] == doctest::Approx(17.6356f));
  CHECK(clip.values[2] == doctest::Approx(-28.2214f));
  CHECK(clip.values[9] == -21.0f);
  CHECK(clip.skeleton.joints[2].offset ==
        glm::vec3(1.57314f, -1.85774f, 0.63783f));  // LeftUpLeg Zrotation in the integer T-pose
  int toe = clip.skeleton.findJoint("LeftToeBase");
  REQUIRE(toe >= 0);
  REQUIRE(clip.skeleton.joints[size_t(toe)].endSite.has_value());
  CHECK(clip.skeleton.joints[size_t(toe)].endSite->z == doctest::Approx(1.09718f));
  CHECK(clip.skeleton.findJoint("End Site") == -1);
  CHECK(clip.skeleton.findJoint("Site") == -1);
}

TEST_CASE("Bandai Namco captures: 22 joints, 132 channels, Z X Y order") {
  const std::vector<std::pair<std::string, int>> files = {{"dataset-1_run_normal_001.bvh", 24},
                                                          {"dataset-1_dash_normal_001.bvh", 20},
                                                          {"dataset-1_walk_normal_002.bvh", 31}};
  for (const auto& file : files) {
    const std::string& name = file.first;  // a plain reference: CAPTURE keeps it in a lambda
    const int frames = file.second;
    if (!throng::test::haveSharedData("bvh/bandai_namco/" + name)) continue;
    CAPTURE(name);
    RawClip clip = loadBvh(throng::test::sharedDataDir() / "bvh/bandai_namco" / name);
    CHECK(clip.skeleton.jointCount() == 22);
    CHECK(countEndSites(clip.skeleton) == 5);
    CHECK(clip.channelCount == 132);
    CHECK(clip.frameCount == frames);
    CHECK(clip.frameTime == doctest::Approx(1.0f / 30.0f).epsilon(1e-5));
    CHECK(clip.values.size() == size_t(frames) * 132);
    checkParentsFirst(clip.skeleton);
    CHECK(clip.skeleton.joints[0].name == "joint_Root");
    for (const Joint& j : clip.skeleton.joints) {
      CHECK(j.channels == std::vector<Channel>{Channel::Xposition, Channel::Yposition,
                                               Channel::Zposition, Channel::Zrotation,
                                               Channel::Xrotation, Channel::Yrotation});
    }
  }
  if (throng::test::haveSharedData("bvh/bandai_namco/dataset-1_run_normal_001.bvh")) {
    RawClip run =
        loadBvh(throng::test::sharedDataDir() / "bvh/bandai_namco/dataset-1_run_normal_001.bvh");
    CHECK(run.values[8] == doctest::Approx(8.33909e-14f));  // scientific notation
    CHECK(run.values[5] == 0.0f);                           // "-0"
    CHECK(run.skeleton.joints[1].offset.y == doctest::Approx(93.9915f));
  }
}

TEST_CASE("the project's own assets load") {
  fs::path assets = throng::test::sourceDir() / "assets";
  int loaded = 0;
  if (fs::is_directory(assets)) {
    for (const auto& entry : fs::directory_iterator(assets)) {
      if (entry.path().extension() != ".bvh") continue;
      CAPTURE(entry.path().string());
      RawClip clip = loadBvh(entry.path());
      CHECK(clip.frameCount > 0);
      CHECK(clip.frameTime > 0.0f);
      CHECK(clip.values.size() == size_t(clip.frameCount) * size_t(clip.channelCount));
      checkParentsFirst(clip.skeleton);
      ++loaded;
    }
  }
  if (loaded == 0) MESSAGE("SKIPPED: no assets/*.bvh yet (generated by the asset tool)");
}

TEST_CASE("each malformed file gives its own error with file, line and what was expected") {
  struct Case {
    const char* file;
    int line;
    const char* phrase;
  };
  const Case cases[] = {
      {"truncated_frames", 20,
       "the motion data ends after 2 of the 4 frames that Frames: on line 17 declares"},
      {"huge_frames", 20, "the motion data ends after 2 of the 999999999 frames"},
      {"truncated_hierarchy", 12, "unexpected end of file, expected '}' closing the End Site"},
      {"missing_brace", 15,
       "unknown token 'MOTION', expected JOINT, End Site or '}' closing joint 'Hips'"},
      {"wrong_value_count", 20, "expected 9 values on frame 2 of 2, found 8"},
      {"unknown_token", 10, "unknown token 'EndSite'"},
      {"nan_value", 19, "expected a finite number on frame 1, found 'nan'"},
      {"inf_value", 20, "expected a finite number on frame 2, found '-inf'"},
      {"overflow_offset", 8, "expected a finite number for OFFSET, found '1e999'"},
      {"bad_number", 8, "expected a number for OFFSET, found '1.0.0'"},
      {"bad_channel_count", 9, "expected a channel count of 3 or 6, found '4'"},
      {"unknown_channel", 9, "unknown channel 'Wrotation'"},
      {"duplicate_channel", 9, "channel 'Zrotation' listed twice"},
      {"position_only_joint", 9,
       "expected Xrotation, Yrotation and Zrotation on a 3-channel joint"},
      {"missing_channels", 9, "expected CHANNELS, found 'End'"},
      {"missing_motion", 15, "expected a MOTION section, found end of file"},
      {"negative_frame_time", 18, "expected a positive frame time in seconds, found '-0.0333333'"},
      {"zero_frame_time", 18, "expected a positive frame time in seconds, found '0'"},
      {"missing_frame_time", 18, "expected 'Frame Time:', found '0'"},
      {"zero_frames", 17, "expected a frame count of at least 1, found '0'"},
      {"joint_without_name", 6, "expected a joint name"},
      {"second_root", 16, "only one ROOT is supported"},
      {"empty", 1, "unexpected end of file, expected HIERARCHY"},
  };
  int checked = 0;
  for (const Case& c : cases) {
    fs::path path = kBadDir / (std::string(c.file) + ".bvh");
    CAPTURE(path.string());
    REQUIRE(fs::exists(path));
    std::string message = errorOf(path);
    CAPTURE(message);
    CHECK(message.rfind(path.string() + ":" + std::to_string(c.line) + ": ", 0) == 0);
    CHECK(message.find(c.phrase) != std::string::npos);
    ++checked;
  }
  // Every file in the folder has a case above.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kBadDir))
    files += entry.path().extension() == ".bvh";
  CHECK(files == checked);
}

TEST_CASE("more motion lines than Frames: declares load the declared frames with a warning") {
  // As assimp's Boxing_Toes.bvh (3,070 lines under Frames: 3069), which assimp loads.
  const fs::path path = kBadDir.parent_path() / "extra_frames.bvh";
  std::vector<std::string> warnings;
  RawClip clip = parseBvh(throng::readTextFile(path), path.string(), &warnings);
  CHECK(clip.frameCount == 1);
  REQUIRE(clip.values.size() == size_t(clip.channelCount));
  CHECK(clip.values[0] == 0.0f);
  CHECK(clip.values[1] == 90.0f);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].rfind(
            path.string() + ":20: 1 motion line after the 1 frames that Frames: on line 17", 0) ==
        0);
  CHECK(loadBvh(path).frameCount == 1);  // the warning goes to the log instead
}

TEST_CASE("more than 1024 joints is refused at the joint that exceeds it") {
  auto chain = [](int joints) {
    std::string text =
        "HIERARCHY\nROOT j0\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
    for (int j = 1; j < joints; ++j) {
      text += "JOINT j" + std::to_string(j) +
              "\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
    }
    for (int j = 0; j < joints; ++j) text += "} ";
    text += "\nMOTION\nFrames: 1\nFrame Time: 0.1\n";
    for (int j = 0; j < joints * 3; ++j) text += "0 ";
    return text + "\n";
  };
  RawClip ok = parseBvh(chain(1024), "chain.bvh");  // deepest nesting allowed: no recursion
  CHECK(ok.skeleton.jointCount() == 1024);
  CHECK(ok.skeleton.joints[1023].parent == 1022);
  std::string message = errorOfText(chain(1025));
  // Joint 1024 (the 1025th) starts on line 2 + 4 * 1024.
  CHECK(message.find("text.bvh:" + std::to_string(2 + 4 * 1024) + ": more than 1024 joints") == 0);
}

TEST_CASE("CRLF, LF, lone CR and mixed endings parse identically; line numbers agree") {
  for (const char* rel :
       {"bvh/bandai_namco/dataset-1_run_normal_001.bvh", "bvh/cmu/cmu_09_01_run.bvh"}) {
    if (!throng::test::haveSharedData(rel)) continue;
    CAPTURE(rel);
    std::string original = throng::readTextFile(throng::test::sharedDataDir() / rel);
    std::string lf = replaceAll(original, "\r\n", "\n");
    REQUIRE(lf.find('\r') == std::string::npos);
    std::string crlf = replaceAll(lf, "\n", "\r\n");
    std::string cr = replaceAll(lf, "\n", "\r");
    std::string mixed;
    int n = 0;
    for (char c : lf)
      mixed += (c == '\n' && (n++ % 3 == 0)) ? std::string("\r\n") : std::string(1, c);
    RawClip reference = parseBvh(lf, "lf.bvh");
    checkSameClip(reference, parseBvh(original, "original.bvh"));
    checkSameClip(reference, parseBvh(crlf, "crlf.bvh"));
    checkSameClip(reference, parseBvh(cr, "cr.bvh"));
    checkSameClip(reference, parseBvh(mixed, "mixed.bvh"));
    // An error late in the file names the same line whatever the endings.
    auto breakLast = [](const std::string& s) {
      size_t end = s.find_last_of("0123456789") + 1;
      std::string broken = s.substr(0, end);
      broken += 'x';
      broken.append(s, end);
      return broken;
    };
    std::string lfError = errorOfText(breakLast(lf));
    CHECK(lfError.find("expected a number on frame") != std::string::npos);
    CHECK(errorOfText(breakLast(crlf)) == lfError);
    CHECK(errorOfText(breakLast(mixed)) == lfError);
  }
}

TEST_CASE("tabs, trailing spaces, '+' signs and 'Frames :' spacing are accepted") {
  std::string text =
      "HIERARCHY  \n\tROOT\tHips \t\n{\n\tOFFSET\t+1.5 -0 2e1   \n"
      "\tCHANNELS 6 Xposition Yposition Zposition Yrotation Xrotation Zrotation\t\n}\n\n"
      "MOTION\nFrames : 2\nFrame Time:\t.0083333  \n"
      "\t1 2 3 4 5 6  \n\n  -1E2 .5 -.5 0 0 8.33909e-14\n\n\n";
  RawClip clip = parseBvh(text, "spaces.bvh");
  CHECK(clip.skeleton.joints[0].offset == glm::vec3(1.5f, 0.0f, 20.0f));
  CHECK(clip.frameCount == 2);
  CHECK(clip.frameTime == doctest::Approx(0.0083333f));
  CHECK(clip.values == std::vector<float>{1, 2, 3, 4, 5, 6, -100, 0.5f, -0.5f, 0, 0, 8.33909e-14f});
}

TEST_CASE("any truncation of a real file is an Error or a complete parse, never a crash") {
  const char* rel = "bvh/bandai_namco/dataset-1_dash_normal_001.bvh";
  if (!throng::test::haveSharedData(rel)) return;
  std::string text = throng::readTextFile(throng::test::sharedDataDir() / rel);
  size_t motion = text.find("MOTION");
  int errors = 0;
  for (size_t cut = 0; cut < text.size(); cut += 37) {
    std::string message = errorOfText(text.substr(0, cut));
    if (message == "(no error)") {
      CHECK(cut > motion);  // only a cut inside the very last value can still parse
    } else {
      CHECK(message.rfind("text.bvh:", 0) == 0);
      ++errors;
    }
  }
  CHECK(errors > 700);
}

TEST_CASE("random byte edits of a small file are an Error or a parse, never a crash") {
  // extra_frames.bvh declares 1 frame of its 2; declaring both makes it exact.
  std::string base = throng::readTextFile(kBadDir.parent_path() / "extra_frames.bvh");
  base.replace(base.find("Frames: 1"), 9, "Frames: 2");
  REQUIRE(parseBvh(base, "base.bvh").frameCount == 2);
  const std::string alphabet = "0123456789.-+eE \t\r\n{}:#xnaif";
  throng::Rng rng(7);
  int parsed = 0, errors = 0;
  for (int i = 0; i < 3000; ++i) {
    std::string text = base;
    for (int e = 1 + int(rng.next() % 4); e > 0; --e) {
      size_t at = rng.next() % text.size();
      char c = alphabet[rng.next() % alphabet.size()];
      switch (rng.next() % 3) {
        case 0:
          text[at] = c;
          break;
        case 1:
          text.insert(text.begin() + long(at), c);
          break;
        default:
          text.erase(at, 1);
          break;
      }
    }
    try {
      RawClip clip = parseBvh(text, "fuzz.bvh");
      REQUIRE(clip.values.size() == size_t(clip.frameCount) * size_t(clip.channelCount));
      ++parsed;
    } catch (const throng::Error& e) {
      REQUIRE(std::string(e.what()).rfind("fuzz.bvh:", 0) == 0);
      ++errors;
    }
  }
  CHECK(errors > 1000);  // most edits break something...
  CHECK(parsed > 10);    // ...and some (a changed digit) do not
}
