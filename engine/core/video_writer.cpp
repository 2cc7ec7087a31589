#include "core/video_writer.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/file_io.h"

extern char** environ;

namespace throng {
namespace fs = std::filesystem;
namespace {

constexpr int kMaxVideoSide = 8192;  // x264 level limits stop well before this

bool programOnPath(const char* name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  size_t start = 0;
  while (start <= dirs.size()) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

std::string tail(const fs::path& log) {
  std::string text;
  try {
    text = readTextFile(log);
  } catch (const Error&) {
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  size_t cut = text.rfind('\n');
  return cut == std::string::npos ? text : text.substr(cut + 1);
}

std::vector<std::string> ffmpegArguments(const VideoOptions& o, const fs::path& tmp) {
  char rate[32];
  std::snprintf(rate, sizeof(rate), "%.6g", o.fps);
  return {"ffmpeg", "-nostdin", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
          "-pix_fmt", "rgba", "-s", concat(o.width, "x", o.height), "-framerate", rate, "-i",
          "pipe:0", "-an",
          // yuv420p needs even sides; an odd one gets a black row or column.
          "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-preset", "veryfast", "-crf",
          std::to_string(o.crf), "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f", "mp4",
          tmp.string()};
}

}  // namespace

void checkVideoOptions(const fs::path& path, const VideoOptions& o) {
  if (path.extension() != ".mp4")
    fail(path.string(), ": --video expects a file name ending in .mp4");
  if (o.width < 2 || o.height < 2 || o.width > kMaxVideoSide || o.height > kMaxVideoSide)
    fail(path.string(), ": video size ", o.width, "x", o.height, " is outside 2..", kMaxVideoSide,
         " per side");
  if (!(o.fps >= 1.0 && o.fps <= 240.0)) fail("--fps: expected 1..240, got ", o.fps);
  if (o.crf < 0 || o.crf > 51) fail("video quality (crf): expected 0..51, got ", o.crf);
  if (fs::is_directory(path)) fail(path.string(), ": is a directory, expected a .mp4 file name");
  fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  ensureWritableDirectory(dir);
  if (!programOnPath("ffmpeg"))
    fail(path.string(),
         ": writing video needs the ffmpeg program (Debian package ffmpeg), not found on PATH");
}

VideoWriter::VideoWriter(fs::path path, const VideoOptions& options)
    : path_(std::move(path)), options_(options) {
  checkVideoOptions(path_, options_);
  tmp_ = temporaryPathFor(path_, ".mp4");
  log_ = temporaryPathFor(path_, ".log");
  ::signal(SIGPIPE, SIG_IGN);  // a dead encoder must give EPIPE, not kill the engine

  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    fail(path_.string(), ": cannot create a pipe (", std::strerror(errno), ")");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = ffmpegArguments(options_, tmp_);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int rc = ::posix_spawnp(&pid_, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[0]);
  if (rc != 0) {
    ::close(fds[1]);
    pid_ = -1;
    fail(path_.string(), ": cannot start ffmpeg (", std::strerror(rc), ")");
  }
  pipe_ = fds[1];
}

VideoWriter::VideoWriter(VideoWriter&& o) noexcept
    : path_(std::move(o.path_)),
      tmp_(std::move(o.tmp_)),
      log_(std::move(o.log_)),
      options_(o.options_),
      pid_(o.pid_),
      pipe_(o.pipe_),
      frames_(o.frames_) {
  o.pid_ = -1;
  o.pipe_ = -1;
}

VideoWriter::~VideoWriter() {
  abandon();
}

void VideoWriter::abandon() noexcept {
  if (pipe_ >= 0) ::close(pipe_);
  pipe_ = -1;
  if (pid_ > 0) {
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    std::error_code ec;
    fs::remove(tmp_, ec);
    fs::remove(log_, ec);
  }
}

void VideoWriter::write(const ImageRgba8& frame) {
  if (pipe_ < 0) fail(path_.string(), ": video already finished");
  if (frame.width != options_.width || frame.height != options_.height)
    fail(path_.string(), ": frame of ", frame.width, "x", frame.height, ", the video is ",
         options_.width, "x", options_.height);
  const auto* bytes = reinterpret_cast<const uint8_t*>(frame.pixels.data());
  size_t left = frame.pixels.size() * sizeof(Rgba8);
  while (left > 0) {
    ssize_t n = ::write(pipe_, bytes, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      std::string why = tail(log_);
      abandon();
      fail(path_.string(), ": the ffmpeg encoder stopped (",
           why.empty() ? std::strerror(errno) : why, ")");
    }
    bytes += n;
    left -= size_t(n);
  }
  ++frames_;
}

void VideoWriter::finish() {
  if (pid_ <= 0) fail(path_.string(), ": video already finished");
  ::close(pipe_);
  pipe_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  std::string why = tail(log_);
  std::error_code ec;
  fs::remove(log_, ec);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || frames_ == 0) {
    fs::remove(tmp_, ec);
    fail(path_.string(), ": ffmpeg could not encode the video (", frames_ == 0 ? "no frames" : why,
         ")");
  }
  commitTemporaryFile(tmp_, path_);
}

}  // namespace throng
