#pragma once
// The storyboard scene of `throng render` and `throng view` (--storyboard FILE --trajectories
// FILE): the storyboard's glyphs placed as agents (ordered by clip set), each following the
// path vectors of a tracked person from real video, with GPU collision avoidance, animated by
// the clip pair of its action (built-in walk, run, idle/talk and hop pairs; --slow/--fast give
// one pair to every action) and tinted by its group. The frame work is render::SteeredCrowd.
#include <memory>
#include <vector>

#include "gpu/context.h"
#include "render/steered_crowd.h"
#include "scene_options.h"

namespace throng::tools {

// Checks the storyboard options and reads the storyboard's size (sets options.story.extent);
// throws Error naming the option or file.
void validateStoryboardScene(SceneOptions& options);
// The one vocabulary of avoidance policies: anticipatory (time to collision), published (the
// rule) and none; ttc and rule are accepted as aliases.
crowd::SteerPolicy scenePolicy(const std::string& name);
std::string_view policyName(crowd::SteerPolicy policy);

// Loads the storyboard and the trajectories and builds the agents, their paths and the pairs.
// `userClips`: the --slow/--fast pair for every action (null: the built-in pair per action).
render::SteeredCrowdSetup makeStoryboardSetup(const SceneOptions& options,
                                              const anim::ClipPair* userClips);

// The circle scene as a steered crowd: runners follow waypoints on their lane circles
// (crowd/circle_paths.h) with the --policy avoidance at --radius, animated by `pair`.
render::SteeredCrowdSetup makeCircleSetup(const SceneOptions& options, anim::MotionPair pair);
// Whether the circle scene is steered that way (not with --speed-period, whose speed changes
// the waypoints cannot follow: those runs keep re-aiming at the tangent).
bool steersCircle(const SceneOptions& options);

// What a frame animates: the plain scenario's crowd (one CrowdSynth), a storyboard crowd or
// the steered circle scene.
class SceneCrowd {
 public:
  SceneCrowd(const gpu::Context& context, const SceneOptions& options, const anim::ClipPair& clips);
  const synth::CrowdSynth& synth() const;  // what recordCrowdFrame synthesizes
  const synth::SynthPrograms& programs() const;
  const crowd::CrowdBuffers& crowd() const;  // every character's placement and motion
  uint32_t count() const;
  uint32_t jointCount() const { return synth().jointCount(); }
  const render::SteeredCrowd* steered() const { return steered_.get(); }
  // The storyboard's work of this frame (nothing for a plain scene); once per frame.
  void addHooks(render::FrameHooks& hooks, float dt);
  // Per agent: the storyboard group (empty for other scenes).
  const std::vector<uint32_t>& groups() const { return groups_; }
  // Per agent: whether it is on the scene at `seconds` (steered scenes follow their paths'
  // first and last seconds; everyone else always is).
  std::vector<uint8_t> activeAt(double seconds) const;

 private:
  std::unique_ptr<anim::MotionPair> pair_;
  std::unique_ptr<synth::SynthPrograms> programs_;
  synth::CrowdSynth synth_;
  std::unique_ptr<render::SteeredCrowd> steered_;
  std::vector<uint32_t> groups_;
  crowd::AgentPaths paths_;  // steered scenes
};

}  // namespace throng::tools
