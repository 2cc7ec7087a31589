// Menge scenarios as scenes (scene/menge_scene.h): the five shared scenes load; run on the GPU
// (steering with goals and walls, then synthesis, as a frame records them without the draw), no
// agent ever crosses a wall or comes within its radius of one (GPU readback, every step), and
// the small scenes reach their end state: every agent at its final goal.
#include <doctest/doctest.h>

#include "anim/default_clips.h"
#include "crowd/crowd_sim.h"
#include "crowd/obstacles.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "menge/menge.h"
#include "scene/frame_stages.h"
#include "scene/menge_scene.h"
#include "test_support.h"

using namespace throng;

namespace {

struct RunResult {
  double seconds = 0.0;
  bool done = false;
  uint32_t atGoal = 0;
  crowd::WallViolations walls;
};

// Steps the scene (steer and synthesis stages) for at most `seconds`, updating the goals every
// half second and counting wall violations between consecutive steps on read-back positions.
RunResult runScene(scene::Scene& s, const crowd::WallGrid* walls, float radius, double seconds) {
  gpu::Context& ctx = test::gpuContext();
  const float dt = 1.0f / 30.0f;
  RunResult r;
  std::vector<glm::vec4> previous = gpu::readback<glm::vec4>(ctx, s.crowd().placement, s.count());
  const synth::CoverageCamera camera =
      synth::coverageCamera(glm::mat4(1.0f), 45.0f, 64, 64, 0.1f);
  for (int frame = 1; r.seconds < seconds; ++frame) {
    const scene::SceneStep step = s.advance(dt);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      scene::SteerStage{&s, &step}.record(cmd);
      scene::SynthesisStage{&s, &step, camera, ctx.info().maxStorageBufferRange}.record(cmd);
    });
    r.seconds += dt;
    const std::vector<glm::vec4> now = gpu::readback<glm::vec4>(ctx, s.crowd().placement, s.count());
    if (walls) {
      const crowd::WallViolations v =
          crowd::countWallViolations(*walls, previous, now, radius - 0.001f);
      r.walls.crossings += v.crossings;
      r.walls.tooClose += v.tooClose;
      r.walls.closest = std::min(r.walls.closest, v.closest);
    }
    previous = now;
    if (frame % 15 == 0) {
      s.updateGoals(ctx);
      if (s.goalsDone()) break;
    }
  }
  r.done = s.goalsDone();
  r.atGoal = s.agentsAtGoal();
  return r;
}

}  // namespace

TEST_CASE("Menge scenes run with goals and walls: no wall crossed, small scenes reach their end") {
  if (!test::haveSharedData("scenes/menge")) return;
  struct Case {
    const char* name;
    double seconds;  // simulated
    bool mustFinish;
  };
  const Case cases[] = {{"4square", 60.0, true},   {"circle", 60.0, true},
                        {"bottleneck", 60.0, true}, {"stadium", 10.0, false},
                        {"tradeshow", 5.0, false}};
  for (const Case& c : cases) {
    const std::string name = c.name;
    CAPTURE(name);
    const menge::MengeScenario scenario =
        menge::readMengeProject(test::sharedDataDir() / "scenes/menge" / (std::string(c.name) + ".xml"));
    scene::MengeSceneResult m = scene::mengeScene(scenario, anim::defaultWalkPair(), 1, 0.05f);
    const size_t agents = m.setup.crowd.size();
    const crowd::AvoidanceParams avoidance = m.setup.steering->avoidance;
    const crowd::WallGrid walls = crowd::binWallsFor(m.setup.walls, avoidance);
    const bool hasWalls = !m.setup.walls.empty();
    scene::Scene s(test::gpuContext(), std::move(m.setup), {true, 0.05f, 20ull << 20}, {});
    const RunResult r = runScene(s, hasWalls ? &walls : nullptr, avoidance.radius, c.seconds);
    MESSAGE(std::string(c.name), ": ", agents, " agents, ", walls.segments.size(), " wall segments; after ",
            r.seconds, " s ", r.atGoal, " at their final goal", std::string(r.done ? " (all)" : ""),
            "; wall crossings ", r.walls.crossings, ", closer than the radius ", r.walls.tooClose);
    CHECK(r.walls.crossings == 0);
    CHECK(r.walls.tooClose == 0);
    if (c.mustFinish) CHECK(r.done);
  }
  CHECK(test::gpuContext().validationMessageCount() == 0);
}
