#include "scene/scene_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>

#include "core/error.h"
#include "core/file_io.h"
#include "crowd/avoidance_types.h"
#include "scene/json_lines.h"
#include "storyboard/json_document.h"

namespace throng::scene {

namespace {

using Json = storyboard::JsonDocument;
constexpr const char* kSchema = "throng.scene";
constexpr uint32_t kMaxCharacters = 4000000;

// 4000000 (not 4e+06), 0.05, 1e-06.
std::string numberText(double x) {
  char text[32];
  if (std::abs(x) < 1e15 && x == std::floor(x))
    std::snprintf(text, sizeof(text), "%.0f", x);
  else
    std::snprintf(text, sizeof(text), "%.6g", x);
  return text;
}

// Reads values out of the parsed document, naming the file, line and key path on any problem.
class Reader {
 public:
  Reader(std::string source, std::string_view text) : source_(std::move(source)), lines_(text) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw Error(concat(source_, ":", lines_.line(pointer), ": ",
                       pointer.empty() ? std::string("scene") : keyPath(pointer), ": ", what));
  }

  void onlyKeys(const Json& object, const std::string& pointer,
                std::initializer_list<const char*> allowed) const {
    if (!object.is_object()) fail(pointer, "expected an object");
    for (auto it = object.begin(); it != object.end(); ++it)
      if (std::none_of(allowed.begin(), allowed.end(),
                       [&](const char* key) { return it.key() == key; })) {
        std::string list;
        for (const char* key : allowed) list += (list.empty() ? "" : ", ") + std::string(key);
        fail(pointer + "/" + it.key(), concat("unknown key (expected one of: ", list, ")"));
      }
  }

  double number(const Json& object, const std::string& pointer, const char* key, double lo,
                double hi, double fallback) const {
    if (!object.contains(key)) return fallback;
    const Json& v = object.at(key);
    const std::string at = pointer + "/" + key;
    if (!v.is_number()) fail(at, "expected a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi)
      fail(at, concat("expected ", numberText(lo), "..", numberText(hi), ", got ", numberText(x)));
    return x;
  }

  std::string text(const Json& object, const std::string& pointer, const char* key,
                   const std::string& fallback,
                   std::initializer_list<const char*> choices = {}) const {
    if (!object.contains(key)) return fallback;
    const Json& v = object.at(key);
    const std::string at = pointer + "/" + key;
    if (!v.is_string()) fail(at, "expected a string");
    const std::string s = v.get<std::string>();
    if (choices.size() > 0 &&
        std::none_of(choices.begin(), choices.end(), [&](const char* c) { return s == c; })) {
      std::string list;
      for (const char* c : choices) list += (list.empty() ? "" : ", ") + std::string(c);
      fail(at, concat("'", s, "' is not one of ", list));
    }
    return s;
  }

  bool flag(const Json& object, const std::string& pointer, const char* key, bool fallback) const {
    if (!object.contains(key)) return fallback;
    if (!object.at(key).is_boolean()) fail(pointer + "/" + key, "expected true or false");
    return object.at(key).get<bool>();
  }

  template <int N>
  glm::vec<N, float> vector(const Json& object, const std::string& pointer, const char* key) const {
    const Json& v = object.at(key);
    const std::string at = pointer + "/" + key;
    if (!v.is_array() || v.size() != N) fail(at, concat("expected an array of ", N, " numbers"));
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>()) ||
          std::abs(v[i].get<double>()) > 1e6)
        fail(concat(at, "/", i), "expected a number within ±1e6");
      out[i] = v[i].get<float>();
    }
    return out;
  }

  // [lo, hi] within [min, max] with lo <= hi.
  void range(const Json& object, const std::string& pointer, const char* key, float min, float max,
             float& lo, float& hi) const {
    if (!object.contains(key)) return;
    const glm::vec2 r = vector<2>(object, pointer, key);
    if (!(r.x >= min && r.y <= max && r.x <= r.y))
      fail(pointer + "/" + key,
           concat("expected [low, high] with ", min, " <= low <= high <= ", max));
    lo = r.x;
    hi = r.y;
  }

  std::string file(const Json& object, const std::string& pointer, const char* key,
                   const std::filesystem::path& base) const {
    const std::string name = text(object, pointer, key, "");
    if (name.empty()) return name;
    const std::filesystem::path p(name);
    return (p.is_absolute() ? p : base / p).lexically_normal().string();
  }

 private:
  std::string source_;
  JsonLines lines_;
};

GroupDescription readGroup(const Reader& r, const Json& g, const std::string& at,
                           const std::filesystem::path& base) {
  r.onlyKeys(
      g, at,
      {"count", "clips", "slow", "fast", "placement", "centre", "density", "speed", "scale"});
  GroupDescription group;
  if (!g.contains("count")) r.fail(at, "a group needs a count");
  group.count = uint32_t(r.number(g, at, "count", 1, kMaxCharacters, 1));
  group.clips = r.text(g, at, "clips", "run", {"run", "walk", "talk", "hop"});
  group.slow = r.file(g, at, "slow", base);
  group.fast = r.file(g, at, "fast", base);
  if (group.slow.empty() != group.fast.empty())
    r.fail(at, "slow and fast name a BVH pair: give both or neither");
  if (!group.slow.empty() && g.contains("clips"))
    r.fail(at + "/clips", "a group has a built-in clip set or a slow/fast pair, not both");
  group.placement = r.text(g, at, "placement", "random", {"random", "circle"});
  if (g.contains("centre")) group.centre = r.vector<2>(g, at, "centre");
  group.density = float(r.number(g, at, "density", 0.01, 10.0, group.density));
  r.range(g, at, "speed", 0.0f, 1.0f, group.speedMin, group.speedMax);
  r.range(g, at, "scale", 0.1f, 10.0f, group.scaleMin, group.scaleMax);
  return group;
}

void readStoryboard(const Reader& r, const Json& s, const std::string& at,
                    const std::filesystem::path& base, SceneFile& scene) {
  r.onlyKeys(s, at, {"file", "trajectories", "legend", "cell", "jitter", "step_time"});
  StoryboardSceneDescription& d = scene.storyboard;
  d.storyboard = r.file(s, at, "file", base);
  d.trajectories = r.file(s, at, "trajectories", base);
  d.legend = r.file(s, at, "legend", base);
  if (d.storyboard.empty() || d.trajectories.empty())
    r.fail(at, "a storyboard needs a file and trajectories");
  d.cell = float(r.number(s, at, "cell", 1e-3, 100.0, d.cell));
  d.jitter = float(r.number(s, at, "jitter", 0.0, 10.0, d.jitter));
  d.stepTime = float(r.number(s, at, "step_time", 0.0, 60.0, d.stepTime));
}

void readCamera(const Reader& r, const Json& c, const std::string& at, SceneFile& scene) {
  r.onlyKeys(c, at, {"preset", "eye", "target", "fov", "path"});
  scene.cameraPreset =
      r.text(c, at, "preset", scene.cameraPreset, {"wide", "street", "top", "closeup"});
  if (c.contains("eye")) scene.eye = r.vector<3>(c, at, "eye");
  if (c.contains("target")) scene.target = r.vector<3>(c, at, "target");
  if (c.contains("fov")) scene.fovYDegrees = float(r.number(c, at, "fov", 1.0, 170.0, 45.0));
  if (!c.contains("path")) return;
  const Json& path = c.at("path");
  if (!path.is_array() || path.empty() || path.size() > 10000)
    r.fail(at + "/path", "expected an array of 1..10000 keyframes");
  for (size_t k = 0; k < path.size(); ++k) {
    const std::string key = concat(at, "/path/", k);
    r.onlyKeys(path[k], key, {"time", "eye", "target", "fov"});
    if (!path[k].contains("time") || !path[k].contains("eye") || !path[k].contains("target"))
      r.fail(key, "a keyframe needs time, eye and target");
    render::CameraKey f;
    f.seconds = float(r.number(path[k], key, "time", 0.0, 1e6, 0.0));
    f.eye = r.vector<3>(path[k], key, "eye");
    f.target = r.vector<3>(path[k], key, "target");
    f.fovYDegrees =
        float(r.number(path[k], key, "fov", 1.0, 170.0, scene.fovYDegrees.value_or(45.0f)));
    if (!scene.cameraPath.empty() && !(f.seconds > scene.cameraPath.back().seconds))
      r.fail(key + "/time", "keyframe times must increase");
    scene.cameraPath.push_back(f);
  }
}

void readMotion(const Reader& r, const Json& m, const std::string& at, SceneFile& scene) {
  r.onlyKeys(m, at, {"lod", "cache", "cache_budget_mb", "bucket_width"});
  scene.lod = r.flag(m, at, "lod", scene.lod);
  scene.cache = r.flag(m, at, "cache", scene.cache);
  scene.cacheBudgetMb =
      float(r.number(m, at, "cache_budget_mb", 0.0, 65536.0, scene.cacheBudgetMb));
  scene.bucketWidth = float(r.number(m, at, "bucket_width", 1.0 / 4095.0, 1.0, scene.bucketWidth));
}

void readOutput(const Reader& r, const Json& o, const std::string& at, SceneFile& scene) {
  r.onlyKeys(o, at, {"size", "fps", "seconds"});
  scene.size = r.text(o, at, "size", scene.size);
  unsigned w = 0, h = 0;
  char extra = 0;
  if (std::sscanf(scene.size.c_str(), "%ux%u%c", &w, &h, &extra) != 2 || w < 1 || h < 1 ||
      w > 16384 || h > 16384)
    r.fail(at + "/size", concat("expected WxH within 1..16384, got '", scene.size, "'"));
  scene.fps = float(r.number(o, at, "fps", 1.0, 240.0, scene.fps));
  scene.seconds = float(r.number(o, at, "seconds", 1e-3, 3600.0, scene.seconds));
}

// The corridor behaviour's object: its length and the tracked set its walkers follow.
void readCorridor(const Reader& r, const Json& c, const std::filesystem::path& base,
                  SceneFile& scene) {
  r.onlyKeys(c, "/corridor", {"length", "trajectories"});
  scene.corridorLength = float(r.number(c, "/corridor", "length", 10.0, 2000.0, 60.0));
  scene.corridorTrajectories = r.file(c, "/corridor", "trajectories", base);
  if (!scene.corridorTrajectories.empty() && !std::filesystem::exists(scene.corridorTrajectories))
    r.fail("/corridor/trajectories", concat("no such file: ", scene.corridorTrajectories));
}

void readGroups(const Reader& r, const Json& doc, const std::filesystem::path& base,
                SceneFile& scene) {
  const Json& groups = doc.at("groups");
  if (!groups.is_array() || groups.empty() || groups.size() > gpu_types::kMaxClipSets)
    r.fail("/groups", concat("expected an array of 1..", gpu_types::kMaxClipSets, " groups"));
  uint64_t total = 0;
  for (size_t k = 0; k < groups.size(); ++k) {
    scene.groups.push_back(readGroup(r, groups[k], concat("/groups/", k), base));
    total += scene.groups.back().count;
  }
  if (total > kMaxCharacters)
    r.fail("/groups", concat(total, " characters in all; at most ", kMaxCharacters));
  if (scene.behaviour == "circle" &&
      (scene.groups.size() != 1 || scene.groups[0].placement != "circle"))
    r.fail("/behaviour", "the circle behaviour needs one group placed on circle lanes");
}

}  // namespace

SceneFile parseSceneFile(std::string_view text, const std::string& source,
                         const std::filesystem::path& baseDir) {
  const Json doc = storyboard::parseJsonDocument(text, source);
  const Reader r(source, text);
  r.onlyKeys(doc, "",
             {"schema", "version", "seed", "behaviour", "groups", "storyboard", "menge", "corridor",
              "walls", "avoidance", "speed_period", "motion", "capes", "camera", "output"});
  if (r.text(doc, "", "schema", "") != kSchema)
    r.fail("/schema", concat("expected \"", kSchema, "\""));
  if (r.number(doc, "", "version", 1, 1, 0) != 1) r.fail("/version", "expected 1");
  SceneFile scene;
  scene.seed = uint64_t(r.number(doc, "", "seed", 0, 4294967295.0, 1));
  scene.behaviour =
      r.text(doc, "", "behaviour", "plain", {"plain", "circle", "storyboard", "menge", "corridor"});
  if (doc.contains("corridor") && scene.behaviour != "corridor")
    r.fail("/corridor", "only the corridor behaviour has one");
  if (doc.contains("menge") && scene.behaviour != "menge")
    r.fail("/menge", "only the menge behaviour reads a Menge scenario");
  if (scene.behaviour == "corridor") {
    if (doc.contains("groups") || doc.contains("storyboard"))
      r.fail(doc.contains("groups") ? "/groups" : "/storyboard",
             "the corridor's agents come from its own quilted storyboard");
    if (doc.contains("corridor")) readCorridor(r, doc.at("corridor"), baseDir, scene);
  } else if (scene.behaviour == "menge") {
    scene.menge = r.file(doc, "", "menge", baseDir);
    if (scene.menge.empty()) r.fail("/behaviour", "the menge behaviour needs a menge project file");
    if (doc.contains("groups") || doc.contains("storyboard"))
      r.fail(doc.contains("groups") ? "/groups" : "/storyboard",
             "a Menge scenario's agents come from its own file");
  } else if (scene.behaviour == "storyboard") {
    if (!doc.contains("storyboard"))
      r.fail("/behaviour", "the storyboard behaviour needs a storyboard");
    if (doc.contains("groups"))
      r.fail("/groups", "a storyboard scene's agents come from its glyphs");
    readStoryboard(r, doc.at("storyboard"), "/storyboard", baseDir, scene);
  } else {
    if (doc.contains("storyboard")) r.fail("/storyboard", "only the storyboard behaviour has one");
    if (!doc.contains("groups")) r.fail("", "a plain or circle scene needs groups");
    readGroups(r, doc, baseDir, scene);
  }
  if (doc.contains("avoidance") && scene.behaviour == "plain")
    r.fail("/avoidance",
           "the plain behaviour does not steer (avoidance is for circle and storyboard)");
  if (doc.contains("avoidance")) {
    r.onlyKeys(doc.at("avoidance"), "/avoidance", {"policy", "radius"});
    scene.policy = r.text(doc.at("avoidance"), "/avoidance", "policy", scene.policy,
                          {"anticipatory", "published", "none", "ttc", "rule"});
    scene.radius = float(r.number(doc.at("avoidance"), "/avoidance", "radius", 0.01, 10.0, 0.3));
    if (scene.behaviour == "menge" && doc.at("avoidance").contains("radius"))
      r.fail("/avoidance/radius", "a Menge scenario gives each agent profile its radius");
  }
  scene.speedPeriod = float(r.number(doc, "", "speed_period", 0.0, 1e6, 0.0));
  if (scene.speedPeriod > 0.0f && scene.behaviour != "plain")
    r.fail("/speed_period", "speed changes apply to the plain behaviour only");
  if (doc.contains("motion")) readMotion(r, doc.at("motion"), "/motion", scene);
  scene.capes = r.file(doc, "", "capes", baseDir);
  scene.walls = r.file(doc, "", "walls", baseDir);
  if (!scene.walls.empty() && scene.behaviour == "plain")
    r.fail("/walls", "walls need a steered behaviour (circle, storyboard, menge or corridor)");
  if (doc.contains("camera")) readCamera(r, doc.at("camera"), "/camera", scene);
  if (doc.contains("output")) readOutput(r, doc.at("output"), "/output", scene);
  return scene;
}

SceneFile readSceneFile(const std::filesystem::path& path) {
  const std::string text = readTextFile(path.string());
  return parseSceneFile(text, path.string(), path.parent_path());
}

namespace {

// A float as the shortest decimal that reads back to it (0.05f → 0.05, not 0.0500000007).
double tidy(float x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof(buffer), x).ptr;
  return std::strtod(std::string(buffer, end).c_str(), nullptr);
}

std::string absolute(const std::string& file) {
  return file.empty() ? file : std::filesystem::absolute(file).lexically_normal().string();
}

Json groupJson(const GroupDescription& g) {
  Json j;
  j["count"] = g.count;
  if (g.slow.empty()) {
    j["clips"] = g.clips;
  } else {
    j["slow"] = absolute(g.slow);
    j["fast"] = absolute(g.fast);
  }
  j["placement"] = g.placement;
  j["centre"] = {tidy(g.centre.x), tidy(g.centre.y)};
  j["density"] = tidy(g.density);
  j["speed"] = {tidy(g.speedMin), tidy(g.speedMax)};
  j["scale"] = {tidy(g.scaleMin), tidy(g.scaleMax)};
  return j;
}

Json cameraJson(const SceneFile& s) {
  Json c;
  c["preset"] = s.cameraPreset;
  if (s.eye) c["eye"] = {tidy(s.eye->x), tidy(s.eye->y), tidy(s.eye->z)};
  if (s.target) c["target"] = {tidy(s.target->x), tidy(s.target->y), tidy(s.target->z)};
  if (s.fovYDegrees) c["fov"] = tidy(*s.fovYDegrees);
  for (const render::CameraKey& f : s.cameraPath)
    c["path"].push_back({{"time", tidy(f.seconds)},
                         {"eye", {tidy(f.eye.x), tidy(f.eye.y), tidy(f.eye.z)}},
                         {"target", {tidy(f.target.x), tidy(f.target.y), tidy(f.target.z)}},
                         {"fov", tidy(f.fovYDegrees)}});
  return c;
}

}  // namespace

std::string writeSceneFile(const SceneFile& s) {
  Json doc;
  doc["schema"] = kSchema;
  doc["version"] = 1;
  doc["seed"] = s.seed;
  doc["behaviour"] = s.behaviour;
  if (s.behaviour == "corridor") {
    doc["corridor"] = {{"length", tidy(s.corridorLength)}};
    if (!s.corridorTrajectories.empty())
      doc["corridor"]["trajectories"] = absolute(s.corridorTrajectories);
  } else if (s.behaviour == "menge") {
    doc["menge"] = absolute(s.menge);
  } else if (s.behaviour == "storyboard") {
    const StoryboardSceneDescription& d = s.storyboard;
    Json b = {{"file", absolute(d.storyboard)}, {"trajectories", absolute(d.trajectories)}};
    if (!d.legend.empty()) b["legend"] = absolute(d.legend);
    b["cell"] = tidy(d.cell);
    b["jitter"] = tidy(d.jitter);
    b["step_time"] = tidy(d.stepTime);
    doc["storyboard"] = b;
  } else {
    for (const GroupDescription& g : s.groups) doc["groups"].push_back(groupJson(g));
  }
  if (s.behaviour == "menge") doc["avoidance"] = {{"policy", s.policy}};
  if (s.behaviour == "circle" || s.behaviour == "storyboard" || s.behaviour == "corridor")
    doc["avoidance"] = {{"policy", s.policy}, {"radius", tidy(s.radius)}};
  if (s.behaviour == "plain") doc["speed_period"] = tidy(s.speedPeriod);
  doc["motion"] = {{"lod", s.lod},
                   {"cache", s.cache},
                   {"cache_budget_mb", tidy(s.cacheBudgetMb)},
                   {"bucket_width", tidy(s.bucketWidth)}};
  if (!s.capes.empty()) doc["capes"] = absolute(s.capes);
  if (!s.walls.empty()) doc["walls"] = absolute(s.walls);
  doc["camera"] = cameraJson(s);
  doc["output"] = {{"size", s.size}, {"fps", tidy(s.fps)}, {"seconds", tidy(s.seconds)}};
  return doc.dump(2) + "\n";
}

}  // namespace throng::scene
