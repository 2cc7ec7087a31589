// Explored secondary motion graphs (.tsg): the whole load (run config JSON, primary graph,
// cloth mesh, secondary graph with its consistency checks) and `cloth info`'s summary.
#include "chunk_fixup.h"
#include "fuzz_support.h"
#include "secondary/offline/explore_file.h"

using namespace throng;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<uint8_t> bytes = fuzz::withValidChunkTrailer({data, size});
  const fuzz::MemoryFile file(bytes);
  fuzz::expectParseOrError([&] { secondary::loadExploreFile(file.path()); });
  fuzz::expectParseOrError([&] { secondary::exploreFileInfo(file.path(), true); });
  return 0;
}
