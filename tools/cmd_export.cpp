// `throng export`: chosen agents' synthesized animation as glTF 2.0 (.glb) or BVH.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "anim/animation_export.h"
#include "anim/bvh.h"
#include "anim/gltf_export.h"
#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "crowd/circle_paths.h"
#include "crowd/trajectory_writer.h"
#include "progress.h"
#include "scene_options.h"
#include "scene_storyboard.h"

namespace throng::tools {
namespace {

constexpr size_t kMaxExportSamples = 50'000'000;  // joint × frame × agent: ≈ 1.4 GB of glTF at most

struct ExportOptions {
  SceneOptions scene;
  int frames = 90;
  std::string agents = "all";
  std::string out;
};

std::vector<uint32_t> parseAgents(const std::string& text, size_t crowdSize) {
  std::vector<uint32_t> agents;
  if (text == "all") {
    for (size_t i = 0; i < crowdSize; ++i) agents.push_back(uint32_t(i));
    return agents;
  }
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    char* end = nullptr;
    long long value = std::strtoll(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || value < 0 || size_t(value) >= crowdSize)
      fail("--agents: expected 'all' or indices 0..", crowdSize - 1, " separated by commas, got '",
           item, "'");
    agents.push_back(uint32_t(value));
  }
  return agents;
}

// Options that change what is drawn, not what moves, do nothing here.
void rejectRenderOnlyOptions(const CLI::App& command) {
  for (const char* name :
       {"--camera", "--eye", "--target", "--fov", "--size", "--device", "--lod", "--lod-tint",
        "--lod-mid-pixels", "--lod-near-pixels", "--lod-update-lag", "--cloth", "--cloth-tint",
        "--cloth-full", "--cache-budget"}) {
    bool known = false;
    for (const CLI::Option* option : command.get_options())
      for (const std::string& l : option->get_lnames()) known = known || "--" + l == name;
    if (known && command.count(name) > 0)
      fail(name, " does nothing in export (it changes the picture, not the motion)");
  }
}

std::filesystem::path agentPath(const std::filesystem::path& out, uint32_t agent, bool several) {
  if (!several) return out;
  std::filesystem::path path = out;
  char suffix[32];
  std::snprintf(suffix, sizeof(suffix), "_%06u.bvh", agent);
  return path.replace_extension().string() + suffix;
}

void runExport(ExportOptions& o, const CLI::App& command) {
  rejectRenderOnlyOptions(command);
  validateSceneOptions(o.scene);
  if (o.scene.storyboard() || o.scene.mengeScene() || o.scene.corridor())
    fail("export: ", o.scene.scenario.name,
         " scenes are steered on the GPU (goals, walls); export random or circle scenes");
  if (o.scene.groups.size() > 1)
    fail("export: a scene of ", o.scene.groups.size(),
         " groups has as many clip sets; export a scene of one group");
  if (o.frames < 1 || o.frames > 100000) fail("--frames: expected 1..100000, got ", o.frames);
  const std::filesystem::path out = o.out;
  const std::string extension = out.extension().string();
  if (extension != ".glb" && extension != ".bvh")
    fail("--out: expected a file name ending in .glb or .bvh, got ", o.out);
  ensureWritableDirectory(out.parent_path().empty() ? "." : out.parent_path());

  anim::ClipPair clips = loadSceneClips(o.scene);
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  crowd::Crowd crowd = makeSceneCrowd(o.scene);
  std::vector<uint32_t> agents = parseAgents(o.agents, crowd.size());
  if (agents.size() * size_t(o.frames) * size_t(pair.jointCount()) > kMaxExportSamples)
    fail("export: ", agents.size(), " agents × ", o.frames, " frames × ", pair.jointCount(),
         " joints is more than ", kMaxExportSamples,
         " samples; choose fewer with --agents or --frames");

  // The whole crowd moves (the steered circle scene avoids its neighbours); the chosen agents
  // are recorded as it does.
  crowd::AgentPaths paths;
  crowd::AvoidanceParams avoidance;
  const bool steered = steersCircle(o.scene);
  if (steered) {
    paths =
        crowd::circlePaths(crowd, anim::clipRootSpeed(pair.slow), anim::clipRootSpeed(pair.fast));
    crowd.steering = anim::Steering::KeepHeading;
    avoidance.policy = scenePolicy(o.scene.story.policy);
    avoidance.radius = o.scene.story.radius;
    avoidance.seed = uint32_t(o.scene.scenario.seed);
  }
  crowd::SteeredCrowdCpu run(pair, std::move(crowd), steered ? &paths : nullptr, avoidance);
  std::vector<anim::JointAnimation> animations;
  for (uint32_t agent : agents)
    animations.push_back(anim::beginAnimation(pair, clips.slow.skeleton, o.scene.dt,
                                              "agent_" + std::to_string(agent)));
  synth::SpeedSchedule speeds = sceneSpeedSchedule(o.scene);
  std::unique_ptr<crowd::TrajectoryWriter> trajectories;
  if (!o.scene.trajectoriesOut.empty()) {
    crowd::checkTrajectoryOutput(o.scene.trajectoriesOut, run.crowd().size(), uint64_t(o.frames));
    trajectories = std::make_unique<crowd::TrajectoryWriter>(
        o.scene.trajectoriesOut, 1.0 / double(o.scene.dt), std::vector<uint32_t>{});
  }
  Progress progress("export", o.frames);
  for (int f = 0; f < o.frames; ++f) {
    for (size_t k = 0; k < agents.size(); ++k)
      anim::appendPose(pair, run.crowd().placement[agents[k]], run.crowd().motion[agents[k]],
                       animations[k]);
    if (trajectories) trajectories->addFrame(run.crowd().placement);
    run.step(o.scene.dt, speeds.advance(o.scene.dt));
    progress.update(f + 1);
  }
  progress.finish();
  if (trajectories) trajectories->finish();
  if (extension == ".glb") {
    anim::writeGlb(out, animations);
  } else {
    for (const anim::JointAnimation& a : animations)
      writeTextFileAtomic(agentPath(out, std::stoul(a.name.substr(6)), animations.size() > 1),
                          anim::formatBvh(anim::toBvhClip(a)));
  }
  std::printf("exported %zu agent(s) × %d frames (%d joints, %.0f fps) to %s\n", animations.size(),
              o.frames, pair.jointCount(), 1.0 / o.scene.dt, out.string().c_str());
}

void addExportCommand(CLI::App& app) {
  auto options = std::make_shared<ExportOptions>();
  options->scene.characters = 10;
  CLI::App* cmd =
      app.add_subcommand("export", "Write agents' synthesized animation as glTF 2.0 (.glb) or BVH");
  addSceneOptions(*cmd, options->scene);
  cmd->add_option("--frames", options->frames, "Number of frames (at --dt seconds each)")
      ->capture_default_str();
  cmd->add_option("--agents", options->agents, "Which agents: 'all' or indices such as 0,4,17")
      ->capture_default_str();
  cmd->add_option("--out,-o", options->out,
                  "Output file: NAME.glb (every agent) or NAME.bvh (several: NAME_000004.bvh ...)")
      ->required();
  cmd->callback([options, cmd] { runExport(*options, *cmd); });
}

const CommandRegistration kRegistration("export", addExportCommand);

}  // namespace
}  // namespace throng::tools
