#include "core/file_io.h"

#include <fcntl.h>
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

fs::path temporaryPathFor(const fs::path& path, const std::string& suffix) {
  fs::path tmp = path;
  tmp += concat(".tmp-", ::getpid(), suffix);
  return tmp;
}

namespace {
// fsync of a path opened read-only (a file written by another process, or a directory).
bool syncPath(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | flags);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  return (::close(fd) == 0) && ok;
}

void renameAndSyncDirectory(const fs::path& tmp, const fs::path& path) {
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    fail(path.string(), ": cannot rename temporary file into place (", ec.message(), ")");
  }
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!syncPath(dir, O_DIRECTORY))
    fail(dir.string(), ": cannot sync the directory after writing ", path.filename().string(), " (",
         std::strerror(errno), ")");
}
}  // namespace

void writeFileAtomic(const fs::path& path, const std::function<void(const ByteSink&)>& produce) {
  const fs::path tmp = temporaryPathFor(path);
  std::FILE* file = std::fopen(tmp.c_str(), "wb");
  if (!file) fail(path.string(), ": cannot open for writing (", std::strerror(errno), ")");
  bool ok = true;
  try {
    produce([&](const uint8_t* data, size_t size) {
      ok = ok && std::fwrite(data, 1, size, file) == size;
    });
  } catch (...) {
    std::fclose(file);
    std::remove(tmp.c_str());
    throw;
  }
  ok = (std::fflush(file) == 0) && ok;
  ok = (::fsync(fileno(file)) == 0) && ok;
  const int err = errno;
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) {
    std::remove(tmp.c_str());
    fail(path.string(), ": write failed (", std::strerror(err), ")");
  }
  renameAndSyncDirectory(tmp, path);
}

void writeFileAtomic(const fs::path& path, std::span<const uint8_t> bytes) {
  writeFileAtomic(path, [bytes](const ByteSink& sink) { sink(bytes.data(), bytes.size()); });
}

void commitTemporaryFile(const fs::path& temporary, const fs::path& path) {
  if (!syncPath(temporary, 0)) {
    const int err = errno;
    std::error_code ec;
    fs::remove(temporary, ec);
    fail(path.string(), ": cannot sync the written file (", std::strerror(err), ")");
  }
  renameAndSyncDirectory(temporary, path);
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
std::filesystem::path sharedDataPath(const std::filesystem::path& relative) {
  namespace fs = std::filesystem;
  const fs::path fromWorkingDirectory = fs::path("..") / "shared" / "data" / relative;
  if (fs::exists(fromWorkingDirectory)) return fromWorkingDirectory;
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (error) return fromWorkingDirectory;
  // build/bin/throng → the repository is two folders up, shared/ beside it.
  const fs::path besideRepository =
      executable.parent_path().parent_path().parent_path().parent_path() / "shared" / "data" /
      relative;
  return fs::exists(besideRepository) ? besideRepository : fromWorkingDirectory;
}

}  // namespace throng
