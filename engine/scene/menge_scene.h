#pragma once
// A Menge scenario (engine/menge) as a Throng scene: Menge's agents (generated positions,
// profiles) become one crowd animated by a clip pair (each agent's preferred speed → its speed
// weight), Menge's obstacles (explicit sets and nav-mesh obstacles) become walls, its goal sets
// and BFSM become per-group goal state machines with nav-mesh or road-map navigation, and the
// agents avoid each other and the walls on the GPU. Menge's (x, y) is Throng's (x, z).
// Anything of the BFSM without an equivalent is a warning naming the element and its line.
#include <string>
#include <vector>

#include "anim/default_clips.h"
#include "menge/menge.h"
#include "scene/scene.h"

namespace throng::scene {

struct MengeSceneResult {
  SceneSetup setup;
  std::vector<std::string> warnings;           // the scenario's own, then the conversion's
  glm::vec2 boundsMin{0.0f}, boundsMax{0.0f};  // agents, walls and goals (x, z)
};

// Throws Error for a scenario that cannot become a scene (no agent, bad goals).
MengeSceneResult mengeScene(const menge::MengeScenario& scenario, const anim::ClipPair& clips,
                            uint64_t seed, float bucketWidth);

}  // namespace throng::scene
