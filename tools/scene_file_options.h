#pragma once
// A scene file as the commands' scene options (scene/scene_file.h): `throng render SCENE.json`,
// `throng view SCENE.json`, and `--save-scene FILE`, which writes the file of a scene given by
// flags, so that every flag scene is expressible as a file.
#include "scene/scene_file.h"
#include "scene_options.h"

namespace throng::tools {

// Reads options.sceneFile (when set) into the options. A flag that describes the scene too is
// an error naming it; output flags (--out, --video, --frames, --seconds, --size, --device, ...)
// stay and override the file's output. Throws Error.
void applySceneFile(SceneOptions& options);
// The scene of these (validated) options as a scene file; `seconds` of output at 1 / dt fps.
scene::SceneFile sceneFileOf(const SceneOptions& options, float seconds);

}  // namespace throng::tools
