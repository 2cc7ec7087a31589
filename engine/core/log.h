#pragma once
#include <string_view>

namespace throng {
enum class LogLevel { Quiet, Info, Verbose };
void setLogLevel(LogLevel level);
LogLevel logLevel();
void logInfo(std::string_view message);
void logVerbose(std::string_view message);
void logWarning(std::string_view message);
}  // namespace throng
