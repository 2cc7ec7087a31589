// Frames out: PNG files (read back pixel for pixel) and H.264/MP4 video written off the frame
// loop, checked with ffprobe.
#include <doctest/doctest.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <thread>

#include "core/binary_io.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/frame_output.h"
#include "core/png_encoder.h"
#include "core/video_writer.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace throng;

namespace {

ImageRgba8 gradientFrame(int w, int h, int t) {
  ImageRgba8 image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      image.at(x, y) = {uint8_t((x * 4 + t * 8) & 255), uint8_t(y * 4), uint8_t(t * 16 & 255), 255};
  return image;
}

std::string run(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[512];
  while (std::fgets(buffer, sizeof(buffer), pipe)) out += buffer;
  ::pclose(pipe);
  return out;
}

// "codec_name,width,height,nb_read_frames" of the first video stream.
std::string probe(const fs::path& video) {
  std::string out =
      run("ffprobe -v error -select_streams v:0 -count_frames -show_entries "
          "stream=codec_name,width,height,nb_read_frames -of csv=p=0 '" +
          video.string() + "' 2>&1");
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

bool haveFfmpeg() {
  return std::system("ffmpeg -version >/dev/null 2>&1") == 0;
}

// PNG frames of w×h into `folder` by `workers` workers with a queue `depth` frames deep.
FrameOutputOptions pngOptions(const fs::path& folder, int w, int h, int workers, int depth) {
  return {.pngFolder = folder, .width = w, .height = h, .queueDepth = depth, .workers = workers};
}

fs::path freshFolder(const char* name) {
  fs::path dir = fs::temp_directory_path() / concat("throng_", name, "_", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("video: impossible options are errors naming the file or option") {
  fs::path dir = freshFolder("video_opts");
  CHECK_THROWS_WITH_AS(checkVideoOptions(dir / "a.avi", {64, 48, 30.0}), doctest::Contains(".mp4"),
                       Error);
  CHECK_THROWS_WITH_AS(checkVideoOptions(dir / "a.mp4", {1, 48, 30.0}),
                       doctest::Contains("outside 2..8192"), Error);
  CHECK_THROWS_WITH_AS(checkVideoOptions(dir / "a.mp4", {64, 48, 0.0}), doctest::Contains("--fps"),
                       Error);
  CHECK_THROWS_WITH_AS(checkVideoOptions(dir / "a.mp4", {64, 48, 30.0, 99}),
                       doctest::Contains("crf"), Error);
  fs::create_directories(dir / "d.mp4");
  CHECK_THROWS_WITH_AS(checkVideoOptions(dir / "d.mp4", {64, 48, 30.0}),
                       doctest::Contains("is a directory"), Error);
  fs::remove_all(dir);
}

TEST_CASE("video: frames become an H.264 MP4 that ffprobe reads, with the right size and count") {
  if (!haveFfmpeg()) {
    MESSAGE("skipped: the ffmpeg program is not installed");
    return;
  }
  fs::path dir = freshFolder("video_ok");
  fs::path video = dir / "out.mp4";
  {
    VideoWriter writer(video, {64, 48, 30.0});
    for (int t = 0; t < 12; ++t) writer.write(gradientFrame(64, 48, t));
    CHECK_FALSE(fs::exists(video));  // nothing under the final name before it is complete
    writer.finish();
  }
  CHECK(probe(video) == "h264,64,48,12");
  int others = 0;
  for (const auto& entry : fs::directory_iterator(dir)) others += entry.path() != video;
  CHECK(others == 0);  // no temporary or log file left behind
  CHECK_THROWS_WITH_AS(VideoWriter(video, {64, 48, 30.0}).write(gradientFrame(32, 48, 0)),
                       doctest::Contains("frame of 32x48"), Error);
  fs::remove_all(dir);
}

TEST_CASE("video: an odd frame size is padded to even sides") {
  if (!haveFfmpeg()) {
    MESSAGE("skipped: the ffmpeg program is not installed");
    return;
  }
  fs::path dir = freshFolder("video_odd");
  VideoWriter writer(dir / "odd.mp4", {33, 21, 24.0});
  for (int t = 0; t < 3; ++t) writer.write(gradientFrame(33, 21, t));
  writer.finish();
  CHECK(probe(dir / "odd.mp4") == "h264,34,22,3");
  fs::remove_all(dir);
}

TEST_CASE("video: an abandoned writer leaves no file under the final name or temporaries") {
  if (!haveFfmpeg()) {
    MESSAGE("skipped: the ffmpeg program is not installed");
    return;
  }
  fs::path dir = freshFolder("video_abandon");
  {
    VideoWriter writer(dir / "gone.mp4", {64, 48, 30.0});
    writer.write(gradientFrame(64, 48, 0));
  }
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("frame output: PNGs and video from a worker, bounded queue, stats") {
  if (!haveFfmpeg()) {
    MESSAGE("skipped: the ffmpeg program is not installed");
    return;
  }
  fs::path dir = freshFolder("frame_output");
  FrameOutputOptions options;
  options.pngFolder = dir;
  options.video = dir / "clip.mp4";
  options.width = 64;
  options.height = 48;
  options.queueDepth = 2;
  FrameOutput output(options);
  for (int t = 0; t < 9; ++t) output.push(gradientFrame(64, 48, t), t);
  output.finish();
  FrameOutputStats stats = output.stats();
  CHECK(stats.frames == 9);
  CHECK(stats.encodeMs > 0.0);
  CHECK(fs::exists(dir / "frame_0000.png"));
  CHECK(fs::exists(dir / "frame_0008.png"));
  CHECK(readPng(dir / "frame_0004.png").at(10, 10) == gradientFrame(64, 48, 4).at(10, 10));
  CHECK(probe(dir / "clip.mp4") == "h264,64,48,9");
  fs::remove_all(dir);
}

TEST_CASE("frame output: several PNG workers write every frame once, in its own file") {
  fs::path dir = freshFolder("frame_output_workers");
  const FrameOutputOptions options = pngOptions(dir, 40, 30, 4, 1);  // depth raised to 5
  FrameOutput output(options);
  for (int t = 0; t < 24; ++t) output.push(gradientFrame(40, 30, t), t);
  output.finish();
  const FrameOutputStats stats = output.stats();
  CHECK(stats.workers == 4);
  CHECK(stats.frames == 24);
  for (int t = 0; t < 24; ++t) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04d.png", t);
    CAPTURE(t);
    REQUIRE(fs::exists(dir / name));
    CHECK(readPng(dir / name).pixels == gradientFrame(40, 30, t).pixels);
  }
  // A video keeps one worker: its frames go in order.
  FrameOutputOptions video = options;
  video.pngFolder.reset();
  video.video = dir / "clip.mp4";
  if (haveFfmpeg()) CHECK(FrameOutput(video).stats().workers == 1);
  fs::remove_all(dir);
}

TEST_CASE("frame output: by default one worker per hardware thread at the lowest priority") {
  fs::path dir = freshFolder("frame_output_default_workers");
  const int threads = int(std::thread::hardware_concurrency());
  for (const bool low : {true, false}) {
    CAPTURE(low);
    FrameOutputOptions options = pngOptions(dir, 8, 8, 0, 1);
    options.lowPriority = low;
    FrameOutput output(options);
    output.finish();
    // At the caller's priority half of them: the other half renders.
    CHECK(output.stats().workers == std::clamp(low ? threads : threads / 2, 1, 8));
  }
  fs::remove_all(dir);
}

TEST_CASE("frame output: workers encode at the lowest priority unless told otherwise") {
  fs::path dir = freshFolder("frame_output_priority");
  errno = 0;
  const int callerNice = getpriority(PRIO_PROCESS, id_t(gettid()));
  REQUIRE(errno == 0);
  for (const bool low : {true, false}) {
    CAPTURE(low);
    FrameOutputOptions options = pngOptions(dir, 8, 8, 1, 1);
    options.lowPriority = low;
    FrameOutput output(options);
    for (int t = 0; t < 3; ++t) output.push(gradientFrame(8, 8, t), t);
    output.finish();
    // Lowering the priority needs no privilege; a worker otherwise inherits the caller's.
    CHECK(output.stats().workerNice == (low ? 19 : callerNice));
  }
  CHECK(getpriority(PRIO_PROCESS, id_t(gettid())) == callerNice);  // the caller's is untouched
  fs::remove_all(dir);
}

TEST_CASE("frame output: a failing encoder's error reaches the frame loop") {
  fs::path dir = freshFolder("frame_output_fail");
  FrameOutputOptions options;
  options.pngFolder = dir / "missing" / "folder";  // not created: the PNG write fails
  options.width = 8;
  options.height = 8;
  FrameOutput output(options);
  bool threw = false;
  try {
    for (int t = 0; t < 50; ++t) output.push(gradientFrame(8, 8, t), t);
    output.finish();
  } catch (const Error& e) {
    threw = true;
    // Whichever worker failed first: one of the first frames.
    CHECK(std::string(e.what()).find("frame_000") != std::string::npos);
  }
  CHECK(threw);
  fs::remove_all(dir);
}

namespace {
uint32_t bigEndian32(const uint8_t* at) {
  return uint32_t(at[0]) << 24 | uint32_t(at[1]) << 16 | uint32_t(at[2]) << 8 | uint32_t(at[3]);
}

// Every chunk after the signature has the CRC of its type and data (the project's own CRC-32,
// not the encoder's library: stb's reader does not check chunk CRCs, other readers reject a file
// whose CRCs are wrong), and IEND ends the file.
void checkChunkCrcs(const std::vector<uint8_t>& png) {
  size_t at = 8;
  std::string last;
  while (at + 12 <= png.size()) {
    const size_t length = bigEndian32(&png[at]);
    REQUIRE(at + 12 + length <= png.size());
    CHECK(bigEndian32(&png[at + 8 + length]) ==
          crc32Ieee(std::span<const uint8_t>(&png[at + 4], length + 4)));
    last.assign(png.begin() + long(at) + 4, png.begin() + long(at) + 8);
    at += 12 + length;
  }
  CHECK(at == png.size());
  CHECK(last == "IEND");
}
}  // namespace

TEST_CASE("png: what encodePng writes reads back pixel for pixel (RGB and RGBA)") {
  fs::path dir = freshFolder("png_round_trip");
  SUBCASE("opaque: written as RGB") {
    ImageRgba8 image = gradientFrame(37, 23, 5);
    image.at(3, 4) = {250, 1, 128, 255};
    std::vector<uint8_t> bytes = encodePng(image);
    REQUIRE(bytes.size() > 33);
    CHECK(bytes[25] == 2);  // IHDR colour type: RGB
    checkChunkCrcs(bytes);
    writePngAtomic(dir / "rgb.png", image);
    ImageRgba8 back = readPng(dir / "rgb.png");
    CHECK(back.width == 37);
    CHECK(back.height == 23);
    CHECK(back.pixels == image.pixels);
  }
  SUBCASE("one translucent pixel: written as RGBA") {
    ImageRgba8 image = gradientFrame(16, 9, 2);
    image.at(15, 8).a = 7;
    CHECK(encodePng(image)[25] == 6);  // RGBA
    checkChunkCrcs(encodePng(image));
    writePngAtomic(dir / "rgba.png", image);
    CHECK(readPng(dir / "rgba.png").pixels == image.pixels);
  }
  SUBCASE("noise, which deflate cannot shrink: stored blocks fit the output") {
    ImageRgba8 image;
    image.width = 301;
    image.height = 257;
    image.pixels.resize(size_t(image.width) * size_t(image.height));
    uint32_t state = 12345u;
    for (Rgba8& p : image.pixels) {
      state = state * 1664525u + 1013904223u;  // a linear congruential generator's top bytes
      p = {uint8_t(state >> 24), uint8_t(state >> 16), uint8_t(state >> 8), uint8_t(state >> 28)};
    }
    const std::vector<uint8_t> bytes = encodePng(image);
    CHECK(bytes[25] == 6);  // RGBA
    checkChunkCrcs(bytes);
    writePngAtomic(dir / "noise.png", image);
    CHECK(readPng(dir / "noise.png").pixels == image.pixels);
  }
  CHECK_THROWS_AS(encodePng(ImageRgba8()), Error);
}

TEST_CASE("png: one encoder, image after image, writes each as a fresh one would") {
  fs::path dir = freshFolder("png_encoder_reuse");
  PngEncoder encoder;
  // Sizes and kinds in an order that makes the kept buffers shrink, grow and change layout.
  ImageRgba8 translucent = gradientFrame(9, 5, 1);
  translucent.at(0, 0).a = 0;
  const ImageRgba8 images[] = {gradientFrame(64, 48, 3), gradientFrame(7, 3, 4), translucent,
                               gradientFrame(65, 49, 6), gradientFrame(1, 1, 7)};
  int k = 0;
  for (const ImageRgba8& image : images) {
    const std::span<const uint8_t> bytes = encoder.encode(image);
    CHECK(std::vector<uint8_t>(bytes.begin(), bytes.end()) == encodePng(image));
    const fs::path file = dir / concat("image_", k++, ".png");
    writeFileAtomic(file, bytes);
    const ImageRgba8 back = readPng(file);
    CHECK(back.width == image.width);
    CHECK(back.height == image.height);
    CHECK(back.pixels == image.pixels);
  }
  CHECK_THROWS_AS(encoder.encode(ImageRgba8()), Error);
  fs::remove_all(dir);
}

TEST_CASE(
    "frame output: encoded frames' buffers come back as spare images, at most a queue's worth") {
  fs::path dir = freshFolder("frame_output_spares");
  FrameOutput output(pngOptions(dir, 24, 16, 1, 2));
  CHECK(output.spareImage().pixels.empty());  // nothing encoded yet
  for (int t = 0; t < 8; ++t) {
    ImageRgba8 frame = output.spareImage();  // filled over, whatever it held
    frame = gradientFrame(24, 16, t);
    output.push(std::move(frame), t);
  }
  output.finish();
  int spares = 0;
  for (ImageRgba8 spare = output.spareImage(); !spare.pixels.empty(); spare = output.spareImage()) {
    CHECK(spare.pixels.size() == size_t(24 * 16));  // a whole frame's buffer
    ++spares;
  }
  CHECK(spares >= 1);
  CHECK(spares <= 2);  // the queue's depth
  for (int t = 0; t < 8; ++t)
    CHECK(readPng(dir / concat("frame_000", t, ".png")).pixels == gradientFrame(24, 16, t).pixels);
  fs::remove_all(dir);
}
