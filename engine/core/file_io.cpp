#include "core/file_io.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace throng {
namespace fs = std::filesystem;

std::string readTextFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path.string(), ": cannot open for reading (", std::strerror(errno), ")");
  std::ostringstream data;
  data << in.rdbuf();
  if (in.bad()) fail(path.string(), ": read error");
  return data.str();
}

void writeFileAtomic(const fs::path& path, std::span<const uint8_t> bytes) {
  fs::path tmp = path;
  tmp += concat(".tmp-", ::getpid());
  std::FILE* file = std::fopen(tmp.c_str(), "wb");
  if (!file) fail(path.string(), ": cannot open for writing (", std::strerror(errno), ")");
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  ok = (std::fflush(file) == 0) && ok;
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) {
    std::remove(tmp.c_str());
    fail(path.string(), ": write failed (", std::strerror(errno), ")");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    fail(path.string(), ": cannot rename temporary file into place (", ec.message(), ")");
  }
}

void writeTextFileAtomic(const fs::path& path, const std::string& text) {
  writeFileAtomic(path, {reinterpret_cast<const uint8_t*>(text.data()), text.size()});
}

void ensureWritableDirectory(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) {
    fs::create_directories(dir, ec);
    if (ec) fail(dir.string(), ": cannot create output directory (", ec.message(), ")");
  }
  if (!fs::is_directory(dir, ec)) fail(dir.string(), ": not a directory");
  if (::access(dir.c_str(), W_OK) != 0) fail(dir.string(), ": output directory is not writable");
}
}  // namespace throng
