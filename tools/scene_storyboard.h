#pragma once
// The storyboard scene of `throng render` and `throng view` (--storyboard FILE --trajectories
// FILE): the storyboard's glyphs placed as agents (ordered by clip set), each following the
// path vectors of a tracked person from real video, with GPU collision avoidance, animated by
// the clip pair of its action (built-in walk, run, idle/talk and hop pairs; --slow/--fast give
// one pair to every action) and tinted by its group. Every scene of the tools (plain scenario,
// steered circle, storyboard) is built here as a scene::SceneSetup.
#include <memory>
#include <vector>

#include "gpu/context.h"
#include "scene/scene.h"
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
scene::SceneSetup makeStoryboardSetup(const SceneOptions& options,
                                              const anim::ClipPair* userClips);

// The circle scene as a steered crowd: runners follow waypoints on their lane circles
// (crowd/circle_paths.h) with the --policy avoidance at --radius, animated by `pair`.
scene::SceneSetup makeCircleSetup(const SceneOptions& options, anim::MotionPair pair);
// Whether the circle scene is steered that way (not with --speed-period, whose speed changes
// the waypoints cannot follow: those runs keep re-aiming at the tangent).
bool steersCircle(const SceneOptions& options);

// The scene the options describe: the plain scenario's crowd, the steered circle or the
// storyboard crowd, animated by `clips` (the storyboard: by its built-in pair per action unless
// --slow/--fast were given). Throws Error naming the option or file.
scene::SceneSetup makeSceneSetup(const SceneOptions& options, const anim::ClipPair& clips);
std::unique_ptr<scene::Scene> makeScene(const gpu::Context& context, const SceneOptions& options,
                                        const anim::ClipPair& clips);

}  // namespace throng::tools
