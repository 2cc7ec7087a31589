#pragma once
// What `throng view` animates: one motion pair, its compiled passes and a crowd that the panel
// can re-spawn (count, scenario, seed, speed range, motion cache, coverage LOD), with its speed
// changes and live LOD thresholds.
#include <memory>
#include <optional>
#include <string>

#include "gpu/context.h"
#include "render/steered_crowd.h"
#include "scene_options.h"
#include "secondary/cloth_gpu_layer.h"
#include "synth/crowd_synth.h"

namespace throng::tools {

struct ViewScene {
  anim::MotionPair pair;  // CrowdSynth points at it: ViewScene never moves (held by unique_ptr)
  anim::Skeleton skeleton;  // the slow clip's: the coverage LOD finds the body parts in it
  std::optional<anim::ClipPair> userClips;  // --slow/--fast, for the storyboard scene
  std::string clipDescription;
  SceneOptions options;  // the scene as last spawned
  std::unique_ptr<synth::SynthPrograms> programs;
  synth::CrowdSynth synth;  // the plain scenarios' crowd
  std::unique_ptr<render::SteeredCrowd> steered;  // the storyboard scene's, instead of `synth`
  synth::SpeedSchedule speeds;  // its period and range may be changed live
  float groundExtent = 0.0f;
  double simulatedSeconds = 0.0;
  // --cloth: the database, and the capes of the current crowd (rebuilt with it).
  std::unique_ptr<secondary::ClothDatabase> clothDb;
  std::unique_ptr<secondary::ClothLayer> cloth;
  VkFormat colorFormat = VK_FORMAT_UNDEFINED;  // the target the capes are drawn into
};

// What the frame synthesizes and draws, for either kind of scene.
inline const synth::CrowdSynth& frameSynth(const ViewScene& s) { return s.steered ? s.steered->synth() : s.synth; }
inline const synth::SynthPrograms& framePrograms(const ViewScene& s) {
  return s.steered ? s.steered->programs() : *s.programs;
}
inline uint32_t characterCount(const ViewScene& s) { return s.steered ? s.steered->count() : s.synth.crowd.count; }


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
