#pragma once
// The .tsg/.tsc container (engine/core/binary_io.h) ends with a CRC-32 of everything
// before it and records its total size in the header; random mutations would almost never
// get past those checks. The harnesses rewrite both (and the "TEND" end marker) so the
// fuzzer reaches the chunk table and the readers behind it.
#include <cstdint>
#include <span>
#include <vector>

namespace throng::fuzz {

// A copy of `input` with the header's total size, the trailer's CRC and its end marker made
// consistent; inputs shorter than a header and trailer are returned unchanged.
std::vector<uint8_t> withValidChunkTrailer(std::span<const uint8_t> input);

}  // namespace throng::fuzz
