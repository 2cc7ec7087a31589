#include "fuzz_support.h"

#include <cxxabi.h>
#include <sys/mman.h>
#include <unistd.h>

#include <memory>
#include <typeinfo>

namespace throng::fuzz {

MemoryFile::MemoryFile(std::span<const uint8_t> bytes) {
  fd_ = memfd_create("throng-fuzz", 0);
  if (fd_ < 0) finding("memfd_create failed", std::strerror(errno));
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) finding("memfd write failed", std::strerror(errno));
    done += size_t(n);
  }
  path_ = "/proc/self/fd/" + std::to_string(fd_);
}

MemoryFile::~MemoryFile() {
  if (fd_ >= 0) close(fd_);
}

void finding(std::string_view what, std::string_view message) {
  std::fprintf(stderr, "throng fuzz finding: %.*s: %.*s\n", int(what.size()), what.data(),
               int(message.size()), message.data());
  std::abort();
}

std::string typeName(const std::exception& e) {
  int status = 0;
  const std::unique_ptr<char, decltype(&std::free)> name(
      abi::__cxa_demangle(typeid(e).name(), nullptr, nullptr, &status), &std::free);
  return status == 0 && name ? std::string(name.get()) : std::string(typeid(e).name());
}

bool isInternalCheck(std::string_view message) {
  const std::string prefix = std::string(THRONG_SOURCE_DIR) + "/engine/";
  return message.starts_with(prefix) && message.find(" failed: ") != std::string_view::npos;
}

}  // namespace throng::fuzz
