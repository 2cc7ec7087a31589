#include "menge/read_file.h"

#include <system_error>

#include "core/error.h"
#include "core/file_io.h"
#include "menge/menge.h"

namespace throng::menge::detail {

std::string readBoundedFile(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    fail(path.string(), ": expected a readable file (", error ? error.message() : "not a file",
         ")");
  }
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error) fail(path.string(), ": cannot read its size: ", error.message());
  if (size > kMaxFileBytes) {
    fail(path.string(), ": expected at most ", kMaxFileBytes, " bytes, the file has ", size);
  }
  return readTextFile(path);
}

}  // namespace throng::menge::detail
