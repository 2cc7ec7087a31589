#pragma once
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace throng {
// Whole file as text; throws Error naming the file when it cannot be read.
std::string readTextFile(const std::filesystem::path& path);
// Writes to "<path>.tmp-<pid>" and renames it over `path`, so a reader never sees a
// half-written file and a failure leaves nothing behind.
void writeFileAtomic(const std::filesystem::path& path, std::span<const uint8_t> bytes);
void writeTextFileAtomic(const std::filesystem::path& path, const std::string& text);
// Throws Error unless `dir` exists (or can be created) and accepts a new file.
void ensureWritableDirectory(const std::filesystem::path& dir);
}  // namespace throng
