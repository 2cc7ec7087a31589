#pragma once
// Built-in scenarios, deterministic from a seed.
#include <cstdint>
#include <string>

#include "crowd/crowd.h"

namespace throng::crowd {

struct ScenarioOptions {
  std::string name = "random";  // "random" or "circle"
  uint32_t characters = 2000;
  uint64_t seed = 1;
  float density = 0.5f;         // characters per square metre (random)
  float minSpeedWeight = 0.0f;  // w range
  float maxSpeedWeight = 1.0f;
  float minScale = 0.92f;       // body-size variation
  float maxScale = 1.08f;
};

// Throws Error for an unknown scenario name or impossible options.
Crowd makeScenario(const ScenarioOptions& options);

// Half the side of the square (random) or the outer radius (circle) the crowd occupies.
float scenarioExtent(const ScenarioOptions& options);

}  // namespace throng::crowd
