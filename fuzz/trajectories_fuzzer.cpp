// Trajectory text (every format, chosen by the first byte, as the file name, the column count or
// the framerate comment would) → tracks → path vectors, speeds, source assignment, a replay and its
// goals.
#include <array>

#include "crowd/path_vectors.h"
#include "crowd/trajectories.h"
#include "fuzz_support.h"

using namespace throng;

namespace {
struct Variant {
  const char* name;
  crowd::TrajectoryFormat format;
};
// The first byte's digit (byte % 6) picks one: '0' auto, '1' biwi_eth, '2' obsmat.txt by name,
// '3' frame-ped-x-y, '4' obsmat, '5' PedPy.
constexpr std::array<Variant, 6> kVariants = {{
    {"fuzz.txt", crowd::TrajectoryFormat::Auto},
    {"biwi_eth.txt", crowd::TrajectoryFormat::Auto},
    {"obsmat.txt", crowd::TrajectoryFormat::Auto},
    {"fuzz.txt", crowd::TrajectoryFormat::FramePedXY},
    {"fuzz.txt", crowd::TrajectoryFormat::EthObsmat},
    {"fuzz.txt", crowd::TrajectoryFormat::PedPy},
}};

void usePaths(const std::vector<crowd::PathSource>& sources) {
  crowd::pathSpeeds(sources);
  if (sources.empty()) return;
  const std::vector<crowd::SpeedRange> ranges = {{0.5f, 1.2f}, {1.2f, 2.5f}, {0.0f, 0.1f}};
  crowd::assignSources(sources, ranges, 7);
  const crowd::AgentPaths paths = crowd::replaySources(sources, {0.0f, 0.0f}, 2.0f);
  std::vector<glm::vec4> goals(paths.size());
  for (uint32_t second = 0; second < 4; ++second) crowd::writeGoals(paths, second, goals);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const Variant& variant = kVariants[data[0] % kVariants.size()];
  fuzz::expectParseOrError([&] {
    crowd::TrajectoryOptions options;
    options.format = variant.format;
    const crowd::Trajectories tracks =
        crowd::parseTrajectories(fuzz::asText(data + 1, size - 1), variant.name, options);
    usePaths(crowd::resamplePathVectors(tracks));
  });
  return 0;
}
