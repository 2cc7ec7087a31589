#pragma once
// The kinds of scene the engine builds (each as a SceneSetup for scene::Scene):
//  * plain: a crowd walking with its own heading and speed (speed changes every period);
//  * circle: runners following waypoints on their lane circles, with avoidance;
//  * storyboard: a storyboard's glyphs placed as agents (ordered by clip set), each following
//    the path vectors of a tracked person from real video, with avoidance, animated by the clip
//    pair of its action (walk, run, idle/talk, hop) and tinted by its group.
// A new kind of scene is a new builder here; what it needs from files is read here too.
#include <optional>
#include <span>
#include <string>

#include "anim/default_clips.h"
#include "scene/scene.h"
#include "storyboard/codec.h"

namespace throng::scene {

SceneSetup plainScene(crowd::Crowd crowd, anim::MotionPair pair,
                      const synth::SpeedSchedule& speeds);
// The scene's characters numbered in space (crowd::spatialOrder), their tints and labels with
// them: the update-rate LOD's chunks are runs of consecutive characters, so numbered in space a
// chunk is a patch of ground, near or far as a whole. A scene of one group; throws Error else.
void numberInSpace(SceneSetup& setup);

// A group of characters animated by one clip set.
struct GroupDescription {
  uint32_t count = 1000;
  std::string clips = "run";               // built-in set: run, walk, talk or hop (slow/fast empty)
  std::string slow, fast;                  // or a BVH pair
  std::string placement = "random";        // random (a square at `density`) or circle (lanes)
  glm::vec2 centre{0.0f};                  // (x, z) metres
  float density = 0.5f;                    // characters per square metre (random)
  float speedMin = 0.0f, speedMax = 1.0f;  // speed weight range
  float scaleMin = 0.92f, scaleMax = 1.08f;
};

// The group's clip set: its BVH pair, or the built-in set it names.
anim::ClipPair groupClips(const GroupDescription& group);
// The group's characters: its placement around its centre, speeds (on bucket speeds when
// bucketWidth > 0) and sizes, deterministic from the seed and the group's index.
crowd::Crowd groupCrowd(const GroupDescription& group, uint64_t seed, size_t index,
                        float bucketWidth);
// A plain scene of several groups (at most kMaxClipSets), each animated by its clip set.
SceneSetup groupsScene(std::span<const GroupDescription> groups, uint64_t seed, float bucketWidth,
                       const synth::SpeedSchedule& speeds);

// The circle's runners (crowd from crowd::makeScenario's "circle") on their lanes.
SceneSetup circleScene(crowd::Crowd crowd, anim::MotionPair pair,
                       const crowd::AvoidanceParams& avoidance);

struct StoryboardSceneDescription {
  std::string storyboard, trajectories, legend;  // files (legend optional)
  float cell = 0.5f;                             // metres per storyboard pixel
  float jitter = 0.1f;                           // ± metres
  float stepTime = 0.0f;                         // seconds per annotation step; 0: by dataset
  uint64_t seed = 1;
  crowd::AvoidanceParams avoidance;
  std::optional<anim::ClipPair> clips;  // one pair for every action (absent: one per action)
};

// The storyboard file read with its legend; throws Error naming the file when it holds no
// valid glyph.
storyboard::Storyboard readSceneStoryboard(const StoryboardSceneDescription& description);
// Reads the storyboard and the trajectories and builds the agents, their paths and groups.
SceneSetup storyboardScene(const StoryboardSceneDescription& description);

}  // namespace throng::scene
