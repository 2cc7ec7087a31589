#pragma once
// H.264 video in an MP4 file, encoded by the `ffmpeg` program (Debian's package) fed raw RGBA
// frames through a pipe. A separate process rather than libavcodec: the encoder runs on its own
// core(s) without touching the engine's threads, an encoder crash cannot take the engine down,
// and there is no ABI to follow across FFmpeg versions. The file is written under a temporary
// name and renamed only when ffmpeg has finished it, so a killed run never leaves a
// half-written video under the final name.
#include <sys/types.h>

#include <filesystem>

#include "core/image.h"

namespace throng {

struct VideoOptions {
  int width = 0;
  int height = 0;
  double fps = 30.0;
  int crf = 20;  // x264 constant rate factor: 0 lossless .. 51 worst; 18-23 looks clean
};

// Throws Error naming `path` or the option when the size or rate is impossible, when the
// output folder is not writable, or when the ffmpeg program is missing.
void checkVideoOptions(const std::filesystem::path& path, const VideoOptions& options);

class VideoWriter {
 public:
  VideoWriter(std::filesystem::path path, const VideoOptions& options);
  ~VideoWriter();  // unfinished: stops ffmpeg and removes the temporary file
  VideoWriter(VideoWriter&& other) noexcept;
  VideoWriter& operator=(VideoWriter&&) = delete;
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // The image must have the size given at construction.
  void write(const ImageRgba8& frame);
  // Closes the stream, waits for ffmpeg, checks its exit status and renames the file into place.
  void finish();
  int framesWritten() const { return frames_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  void abandon() noexcept;
  std::filesystem::path path_, tmp_, log_;
  VideoOptions options_;
  pid_t pid_ = -1;
  int pipe_ = -1;
  int frames_ = 0;
};

}  // namespace throng
