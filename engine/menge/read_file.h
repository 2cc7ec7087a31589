#pragma once
// Whole-file reads for the Menge readers, refused beyond kMaxFileBytes so that a wrong path (a
// device, a huge log) cannot exhaust memory.
#include <filesystem>
#include <string>

namespace throng::menge::detail {
std::string readBoundedFile(const std::filesystem::path& path);
}  // namespace throng::menge::detail
