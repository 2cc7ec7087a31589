#pragma once
// Where rendered frames go: numbered PNG files and/or an MP4 video, encoded on worker threads
// so that encoding never sits on the frame loop's timing path. The queue between the frame loop
// and the workers holds at most `queueDepth` frames: a loop that outruns the encoders waits for
// a free slot (bounded memory) and the time it waits is reported. PNG files are independent, so
// several workers encode them at once; a video takes its frames in order, from one worker.
// Frames are handed over by value and their buffers come back for the next ones (spareImage):
// a long run allocates a few frames' worth of memory once, not a frame's worth every frame.
#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/image.h"
#include "core/png_encoder.h"
#include "core/video_writer.h"

namespace throng {

struct FrameOutputOptions {
  std::optional<std::filesystem::path> pngFolder;  // frame_0000.png, frame_0001.png, ...
  std::optional<std::filesystem::path> video;      // an .mp4 file
  int width = 0, height = 0;
  double fps = 30.0;
  int queueDepth = 3;
  // PNG encoders (1 with a video); 0: one per hardware thread at the lowest priority, half the
  // hardware threads otherwise, 1 to 8.
  int workers = 0;
  // Workers at the lowest scheduling priority (nice 19): on a CPU device the frame loop's threads
  // are the device, and an encoder sharing their cores would stretch every pass it preempts.
  // Encoding then takes the cores' idle time; the bounded queue makes the loop wait when it
  // falls behind.
  bool lowPriority = true;
};

struct FrameOutputStats {
  int frames = 0;
  double encodeMs = 0.0;  // the workers' time, all frames (summed over workers)
  int workers = 1;
  double waitedMs = 0.0;  // the frame loop's time waiting for a free queue slot
  int workerNice = 0;     // the scheduling priority the workers ran at (Linux nice value)
};

class FrameOutput {
 public:
  explicit FrameOutput(const FrameOutputOptions& options);
  ~FrameOutput();  // unfinished: stops the worker; an unfinished video is removed
  FrameOutput(const FrameOutput&) = delete;
  FrameOutput& operator=(const FrameOutput&) = delete;

  // A frame buffer the workers are done with, to fill and push (its pixels are stale), or an
  // empty image when none is free.
  ImageRgba8 spareImage();
  // Queues a frame (its index names the PNG). Rethrows the worker's error, if any.
  void push(ImageRgba8 frame, int index);
  // Drains the queue, closes the video, rethrows the worker's error.
  void finish();
  FrameOutputStats stats() const;

 private:
  struct Job {
    ImageRgba8 image;
    int index = 0;
  };
  void run();
  void encode(const Job& job, PngEncoder& png);
  void rethrow();
  void joinWorkers();

  FrameOutputOptions options_;
  std::optional<VideoWriter> video_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;
  std::vector<ImageRgba8> spares_;  // encoded frames' buffers, for spareImage
  int inFlight_ = 0;                // frames taken by a worker and not yet encoded
  bool closing_ = false;
  std::exception_ptr error_;
  FrameOutputStats stats_;
  std::vector<std::thread> workers_;
};

}  // namespace throng
