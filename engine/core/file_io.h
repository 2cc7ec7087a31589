#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

namespace throng {
// Whole file as text; throws Error naming the file when it cannot be read.
std::string readTextFile(const std::filesystem::path& path);
// The one way files are written: into "<path>.tmp-<pid>" in the same directory, fsync'd,
// renamed over `path`, then the directory fsync'd; so a reader (or a crash) never sees a
// half-written file and a failure leaves nothing behind. Errors name `path`.
using ByteSink = std::function<void(const uint8_t* data, size_t size)>;
void writeFileAtomic(const std::filesystem::path& path,
                     const std::function<void(const ByteSink& sink)>& produce);
void writeFileAtomic(const std::filesystem::path& path, std::span<const uint8_t> bytes);
void writeTextFileAtomic(const std::filesystem::path& path, const std::string& text);
// "<path>.tmp-<pid><suffix>": where a writer that is another program (ffmpeg, gnuplot) writes
// before commitTemporaryFile moves it into place.
std::filesystem::path temporaryPathFor(const std::filesystem::path& path,
                                       const std::string& suffix = "");
// The end of writeFileAtomic for a temporary something else wrote: fsync it, rename it over
// `path`, fsync the directory; removes the temporary and throws Error naming `path` on failure.
void commitTemporaryFile(const std::filesystem::path& temporary, const std::filesystem::path& path);
// Throws Error unless `dir` exists (or can be created) and accepts a new file.
void ensureWritableDirectory(const std::filesystem::path& dir);
// `relative` inside the third-party data folder shared/data that lies beside the repository:
// ../shared/data/<relative> from the working directory (the repository root) when it exists,
// else the same beside the repository that holds this executable (build/bin/throng), so
// commands find it from the build folder too; the first when neither exists.
std::filesystem::path sharedDataPath(const std::filesystem::path& relative);
}  // namespace throng
