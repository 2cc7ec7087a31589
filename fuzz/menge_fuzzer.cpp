// Menge scene and behaviour XML (the first byte picks: even scene, odd behaviour) → profiles,
// groups expanded into agents, obstacle sets; goal sets, states, transitions resolved by name.
#include "fuzz_support.h"
#include "menge/menge.h"

using namespace throng;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string_view xml = fuzz::asText(data + 1, size - 1);
  fuzz::expectParseOrError([&] {
    if (data[0] % 2 == 0) {
      (void)menge::parseMengeScene(xml, "fuzz/fuzzS.xml");
    } else {
      (void)menge::parseMengeBehavior(xml, "fuzz/fuzzB.xml");
    }
  });
  return 0;
}
