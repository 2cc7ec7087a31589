#pragma once
// What `throng view` animates: a scene (scene::Scene) that the panel can re-spawn (count,
// scenario, seed, speed range, motion cache, coverage LOD), with its capes, speed changes and
// live LOD thresholds.
#include <memory>
#include <optional>
#include <string>

#include "gpu/context.h"
#include "scene/scene.h"
#include "scene_options.h"
#include "secondary/cloth_gpu_layer.h"
#include "synth/crowd_synth.h"

namespace throng::tools {

struct ViewScene {
  anim::ClipPair clips;     // what every respawn animates (the storyboard: with --slow/--fast)
  anim::Skeleton skeleton;  // the slow clip's: the coverage LOD finds the body parts in it
  std::string clipDescription;
  SceneOptions options;                 // the scene as last spawned
  std::unique_ptr<scene::Scene> crowd;  // the plain scenario's, the circle's or the storyboard's
  float groundExtent = 0.0f;
  double simulatedSeconds = 0.0;
  // --cloth: the database, and the capes of the current crowd (rebuilt with it).
  std::unique_ptr<secondary::ClothDatabase> clothDb;
  std::unique_ptr<secondary::ClothLayer> cloth;
  VkFormat colorFormat = VK_FORMAT_UNDEFINED;  // the target the capes are drawn into
};

// What the frame synthesizes and draws.
inline const synth::CrowdSynth& frameSynth(const ViewScene& s) {
  return s.crowd->synth();
}
inline uint32_t characterCount(const ViewScene& s) {
  return s.crowd->count();
}

std::unique_ptr<ViewScene> makeViewScene(const gpu::Context& context, const SceneOptions& options,
                                         anim::ClipPair clips, VkFormat colorFormat);

// Replaces the crowd by a new one for `options` (waits for the GPU first). Throws Error for
// impossible options and then leaves the scene as it was; when the new crowd fails part way
// (gpu::LimitError past a device limit) the old one is rebuilt as it was spawned.
void respawnCrowd(const gpu::Context& context, ViewScene& scene, const SceneOptions& options);

// New coverage-LOD thresholds (pixels: the torso's for mid, the limbs' for near) for the running
// crowd, and for later respawns. The thresholds live in a host-visible buffer that frames in
// flight read, so this waits for the GPU first when the crowd has the LOD on.
void setLodThresholds(const gpu::Context& context, ViewScene& scene, float midPixels,
                      float nearPixels);

}  // namespace throng::tools
