#include "core/log.h"

#include <atomic>
#include <cstdio>

namespace throng {
namespace {
std::atomic<LogLevel> gLevel{LogLevel::Info};
void emit(const char* prefix, std::string_view message) {
  std::fprintf(stderr, "%s%.*s\n", prefix, static_cast<int>(message.size()), message.data());
}
}  // namespace

void setLogLevel(LogLevel level) { gLevel = level; }
LogLevel logLevel() { return gLevel; }
void logInfo(std::string_view message) {
  if (gLevel != LogLevel::Quiet) emit("", message);
}
void logVerbose(std::string_view message) {
  if (gLevel == LogLevel::Verbose) emit("", message);
}
void logWarning(std::string_view message) { emit("warning: ", message); }
}  // namespace throng
