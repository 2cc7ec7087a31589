// Compressed cloth databases (.tsc): decode with its validation, then what playback does with
// a database it accepted: dequantize and reconstruct states (all bases and an LOD subset).
#include <algorithm>
#include <numeric>

#include "chunk_fixup.h"
#include "fuzz_support.h"
#include "secondary/cloth_database.h"
#include "secondary/cloth_decoder.h"

using namespace throng;

namespace {
void reconstructSomeStates(const secondary::ClothDatabase& db) {
  const secondary::DecodedBases decoded = secondary::dequantize(db);
  std::vector<glm::vec3> positions(decoded.vertexCount);
  std::vector<uint32_t> order(decoded.vertexCount);
  std::iota(order.begin(), order.end(), 0u);
  const uint32_t states = std::min<uint32_t>(decoded.stateCount, 4);
  for (uint32_t state = 0; state < states; ++state) {
    secondary::decodeState(decoded, state, positions);
    const std::span<glm::vec3> half(positions.data(), positions.size() / 2);
    secondary::decodeStateSubset(decoded, state, order, decoded.basisCount / 2, half);
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<uint8_t> bytes = fuzz::withValidChunkTrailer({data, size});
  fuzz::expectParseOrError(
      [&] { reconstructSomeStates(secondary::decodeClothDatabase(bytes, "fuzz.tsc")); });
  return 0;
}
