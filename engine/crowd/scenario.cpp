#include "crowd/scenario.h"

#include <cmath>

#include "core/error.h"
#include "core/math.h"
#include "core/rng.h"

namespace throng::crowd {
namespace {

void validate(const ScenarioOptions& o) {
  if (o.name != "random" && o.name != "circle")
    fail("unknown scene '", o.name, "': expected 'random' or 'circle'");
  if (o.characters == 0) fail("the crowd needs at least one character (--characters)");
  if (!(o.density > 0.0f)) fail("density must be positive, got ", o.density);
  if (!(o.minSpeedWeight >= 0.0f && o.maxSpeedWeight <= 1.0f && o.minSpeedWeight <= o.maxSpeedWeight))
    fail("speed weight range [", o.minSpeedWeight, ", ", o.maxSpeedWeight, "] must lie within [0, 1]");
  if (!(o.minScale > 0.0f && o.minScale <= o.maxScale)) fail("scale range must be positive and ordered");
}

void randomMotion(Crowd& crowd, size_t i, Rng& rng, const ScenarioOptions& o) {
  float w = rng.uniform(o.minSpeedWeight, o.maxSpeedWeight);
  crowd.motion[i] = glm::vec4(rng.uniform(), w, w, rng.uniform(o.minScale, o.maxScale));
}

}  // namespace

float scenarioExtent(const ScenarioOptions& o) {
  float area = float(o.characters) / o.density;
  if (o.name == "circle") {
    // Concentric lanes 1.4 m apart whose total length holds every runner 2.5 m apart.
    float inner = 8.0f;
    float lanes = std::max(1.0f, std::ceil(std::sqrt(area) / 10.0f));
    return inner + lanes * 1.4f + std::sqrt(area) * 0.1f;
  }
  return 0.5f * std::sqrt(area);
}

Crowd makeScenario(const ScenarioOptions& o) {
  validate(o);
  Crowd crowd;
  crowd.resize(o.characters);
  Rng rng(o.seed);
  if (o.name == "random") {
    float half = scenarioExtent(o);
    for (size_t i = 0; i < crowd.size(); ++i) {
      crowd.placement[i] = glm::vec4(rng.uniform(-half, half), 0.0f, rng.uniform(-half, half), rng.uniform(-kPi, kPi));
      randomMotion(crowd, i, rng, o);
    }
    return crowd;
  }
  // circle (paper Fig. 9): runners on concentric lanes around the origin, headings re-aimed
  // at the tangent every frame by the root-motion pass.
  crowd.steering = anim::Steering::Circle;
  const float inner = 8.0f, laneGap = 1.4f, spacing = 2.2f;
  size_t placed = 0;
  for (int lane = 0; placed < crowd.size(); ++lane) {
    float radius = inner + lane * laneGap;
    size_t perLane = static_cast<size_t>(2.0f * kPi * radius / spacing);
    for (size_t k = 0; k < perLane && placed < crowd.size(); ++k, ++placed) {
      float angle = 2.0f * kPi * (float(k) + 0.5f * (lane % 2)) / float(perLane) + rng.uniform(-0.05f, 0.05f);
      glm::vec2 p(radius * std::cos(angle), radius * std::sin(angle));
      crowd.placement[placed] = glm::vec4(p.x, 0.0f, p.y, anim::circleHeading(p));
      randomMotion(crowd, placed, rng, o);
    }
  }
  return crowd;
}

}  // namespace throng::crowd
