// Characters numbered in space (crowd/spatial_order.h): a permutation that keeps each
// character's state together and puts neighbours next to each other, so a run of 64
// consecutive characters (an update-rate chunk) covers a small patch of the crowd's ground.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>

#include "core/error.h"
#include "crowd/scenario.h"
#include "crowd/spatial_order.h"

using namespace throng;

namespace {

// The mean side of the smallest box around each run of 64 consecutive characters.
float meanChunkSpan(const crowd::Crowd& crowd) {
  double sum = 0.0;
  size_t chunks = 0;
  for (size_t first = 0; first + 64 <= crowd.size(); first += 64, ++chunks) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (size_t i = first; i < first + 64; ++i) {
      lo = glm::min(lo, glm::vec2(crowd.placement[i].x, crowd.placement[i].z));
      hi = glm::max(hi, glm::vec2(crowd.placement[i].x, crowd.placement[i].z));
    }
    sum += 0.5 * double((hi.x - lo.x) + (hi.y - lo.y));
  }
  return float(sum / double(chunks));
}

}  // namespace

TEST_CASE("spatial order: a permutation that keeps each character whole and neighbours close") {
  crowd::ScenarioOptions options;
  options.characters = 20000;
  const crowd::Crowd crowd = crowd::makeScenario(options);
  const std::vector<uint32_t> order = crowd::spatialOrder(crowd);
  std::vector<uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<uint32_t> identity(crowd.size());
  std::iota(identity.begin(), identity.end(), 0u);
  CHECK(sorted == identity);
  const crowd::Crowd numbered = crowd::permuted(crowd, order);
  for (size_t k = 0; k < crowd.size(); k += 997) {
    CHECK(numbered.placement[k] == crowd.placement[order[k]]);
    CHECK(numbered.motion[k] == crowd.motion[order[k]]);
  }
  const float before = meanChunkSpan(crowd), after = meanChunkSpan(numbered);
  const float side = 2.0f * crowd::scenarioExtent(options);
  MESSAGE("20,000 characters on a ", side, " m square: a chunk of 64 spans ", before,
          " m as made, ", after, " m numbered in space");
  CHECK(before > 0.9f * side);
  CHECK(after < 0.15f * side);
  const std::vector<uint32_t> labels =
      crowd::permuted(std::vector<uint32_t>{7, 8, 9}, std::vector<uint32_t>{2, 0, 1});
  CHECK(labels == std::vector<uint32_t>{9, 7, 8});
  CHECK(crowd::permuted(std::span<const uint32_t>{}, order).empty());
  CHECK_THROWS_AS(crowd::permuted(std::vector<uint32_t>{1, 2}, std::vector<uint32_t>{0, 2}), Error);
  CHECK_THROWS_AS(crowd::permuted(crowd, std::vector<uint32_t>{0}), Error);
}
