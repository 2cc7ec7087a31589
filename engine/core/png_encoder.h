#pragma once
// PNG writing (ISA-L's igzip), for frame loops: an encoder keeps its compressor's work buffer
// and its file buffers from one image to the next, so encoding frame after frame allocates nothing.
// Fresh multi-megabyte buffers would be zero-filled and page-faulted in on every frame, on the
// cores that render.
#include <cstdint>
#include <span>
#include <vector>

#include "core/image.h"

namespace throng {

class PngEncoder {
 public:
  // The image's PNG file: 8-bit RGB when every pixel is opaque, RGBA otherwise, igzip level 1
  // and no row filter (fast rather than small). The bytes stay valid until the next call.
  std::span<const uint8_t> encode(const ImageRgba8& image);

 private:
  std::vector<uint8_t> levelBuffer_;  // igzip's hash table and token buffer at level 1
  std::vector<uint8_t> rows_;         // the filtered rows the compressor reads
  std::vector<uint8_t> file_;         // signature, IHDR, IDAT (compressed in place), IEND
};

}  // namespace throng
