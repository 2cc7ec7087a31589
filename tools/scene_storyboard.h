#pragma once
// The scenes of `throng render`, `throng view`, `throng export` and the bench from their
// options: the plain scenario's crowd, the steered circle or the storyboard crowd (--storyboard
// FILE --trajectories FILE), each built by engine/scene's builders (scene/scene_builders.h).
#include <memory>
#include <string>
#include <string_view>

#include "gpu/context.h"
#include "scene/scene.h"
#include "scene/scene_builders.h"
#include "scene_options.h"

namespace throng::tools {

// Checks the storyboard options and reads the storyboard's size (sets options.story.extent);
// throws Error naming the option or file.
void validateStoryboardScene(SceneOptions& options);
// Reads the Menge scenario (its errors name file and line; its warnings are logged) and sets
// where it lies (options.mengeCentre, mengeExtent). Throws Error.
void validateMengeScene(SceneOptions& options);
// --policy NAME (the one vocabulary: crowd::parseSteerPolicy); throws Error on another name.
crowd::SteerPolicy scenePolicy(const std::string& name);
std::string_view policyName(crowd::SteerPolicy policy);

// The storyboard scene's description; `userClips`: the --slow/--fast pair for every action
// (null: the built-in pair per action).
scene::StoryboardSceneDescription storyboardDescription(const SceneOptions& options,
                                                        const anim::ClipPair* userClips);
// Whether the circle scene is steered along its lanes (not with --speed-period, whose speed
// changes the waypoints cannot follow: those runs keep re-aiming at the tangent).
bool steersCircle(const SceneOptions& options);

// The scene the options describe, animated by `clips` (the storyboard: by its built-in pair
// per action unless --slow/--fast were given). Throws Error naming the option or file.
scene::SceneSetup makeSceneSetup(const SceneOptions& options, const anim::ClipPair& clips);
std::unique_ptr<scene::Scene> makeScene(const gpu::Context& context, const SceneOptions& options,
                                        const anim::ClipPair& clips);

}  // namespace throng::tools
