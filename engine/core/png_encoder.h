#pragma once
// PNG writing (libdeflate), for frame loops: an encoder keeps its compressor and its buffers from
// one image to the next, so encoding frame after frame allocates nothing. Fresh multi-megabyte
// buffers would be zero-filled and page-faulted in on every frame, on the cores that render.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/image.h"

struct libdeflate_compressor;

namespace throng {

class PngEncoder {
 public:
  PngEncoder();
  ~PngEncoder();
  PngEncoder(PngEncoder&&) noexcept;
  PngEncoder& operator=(PngEncoder&&) noexcept;

  // The image's PNG file: 8-bit RGB when every pixel is opaque, RGBA otherwise, deflate level 1
  // and no row filter (fast rather than small). The bytes stay valid until the next call.
  std::span<const uint8_t> encode(const ImageRgba8& image);

 private:
  struct FreeCompressor {
    void operator()(libdeflate_compressor* compressor) const;
  };
  std::unique_ptr<libdeflate_compressor, FreeCompressor> compressor_;  // made by the first encode
  std::vector<uint8_t> rows_;  // the filtered rows the compressor reads
  std::vector<uint8_t> file_;  // signature, IHDR, IDAT (compressed in place), IEND
};

}  // namespace throng
