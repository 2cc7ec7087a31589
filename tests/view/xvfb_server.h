#pragma once
// A private X server for the window tests: Xvfb on a free display number, a private
// XDG_RUNTIME_DIR, stopped when the test program exits.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include <doctest/doctest.h>

namespace throng::test {

class XvfbServer {
 public:
  // The shared server, started on first use. display() is empty when it could not start.
  static XvfbServer& instance() {
    static XvfbServer server;
    return server;
  }
  const std::string& display() const { return display_; }
  const std::string& error() const { return error_; }

  ~XvfbServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      int status = 0;
      waitpid(pid_, &status, 0);
    }
    std::error_code ec;
    if (!runtimeDir_.empty()) std::filesystem::remove_all(runtimeDir_, ec);
  }

 private:
  XvfbServer() {
    namespace fs = std::filesystem;
    std::string xvfb;
    for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"})
      if (fs::exists(fs::path(dir) / "Xvfb")) xvfb = (fs::path(dir) / "Xvfb").string();
    if (xvfb.empty()) {
      error_ = "Xvfb not found: install the xvfb package (scripts/install_deps.sh)";
      return;
    }
    char runtime[] = "/tmp/throng-view-test-XXXXXX";
    if (mkdtemp(runtime)) runtimeDir_ = runtime;
    // Another test program may pick the same number at the same moment: if our server dies at
    // start, try the next free one.
    for (int attempt = 0; attempt < 100 && display_.empty(); ++attempt) {
      int n = 99 + (getpid() + attempt) % 100;
      if (fs::exists("/tmp/.X11-unix/X" + std::to_string(n)) ||
          fs::exists("/tmp/.X" + std::to_string(n) + "-lock"))
        continue;
      Start result = start(xvfb, n);
      if (result == Start::Running) display_ = ":" + std::to_string(n);
      if (result == Start::GiveUp) return;
    }
    if (display_.empty() && error_.empty())
      error_ = "no free X display number between :99 and :198";
  }

  enum class Start { Running, TryAnother, GiveUp };

  // Starts Xvfb on display `number` and waits until its socket exists while it still runs.
  Start start(const std::string& xvfb, int number) {
    namespace fs = std::filesystem;
    std::string display = ":" + std::to_string(number);
    pid_ = fork();
    if (pid_ == 0) {
      // Quiet child: Xvfb's log would interleave with the test output.
      if (!freopen("/dev/null", "w", stdout)) _exit(126);
      if (!freopen("/dev/null", "w", stderr)) _exit(126);
      execl(xvfb.c_str(), "Xvfb", display.c_str(), "-screen", "0", "1280x1024x24", "-nolisten",
            "tcp", nullptr);
      _exit(127);
    }
    if (pid_ < 0) {
      error_ = "fork failed";
      return Start::GiveUp;
    }
    std::string socket = "/tmp/.X11-unix/X" + std::to_string(number);
    for (int i = 0; i < 200; ++i) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        error_ = "Xvfb " + display + " exited at start";
        return Start::TryAnother;
      }
      if (fs::exists(socket)) {
        error_.clear();
        return Start::Running;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
    error_ = "Xvfb " + display + " did not open " + socket + " within 10 s";
    return Start::GiveUp;
  }

  pid_t pid_ = -1;
  std::string display_;
  std::string error_;
  std::string runtimeDir_;

 public:
  const std::string& runtimeDir() const { return runtimeDir_; }
};

// Points the commands this process starts at the test's X server (or at none).
inline void useDisplay(const std::string& display) {
  if (display.empty()) {
    unsetenv("DISPLAY");
  } else {
    setenv("DISPLAY", display.c_str(), 1);
  }
  unsetenv("WAYLAND_DISPLAY");
  const std::string& runtime = XvfbServer::instance().runtimeDir();
  if (!runtime.empty()) setenv("XDG_RUNTIME_DIR", runtime.c_str(), 1);
}

}  // namespace throng::test
