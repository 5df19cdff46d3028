// Logging goes through spdlog's default logger, which main() points at
// stderr. Library code logs; it never prints to stdout.
#pragma once

#include <spdlog/spdlog.h>

namespace apprentice {

enum class LogLevel { kQuiet, kWarn, kInfo, kDebug };

// Sends log lines to stderr at the given level. Called once, by main().
void configure_logging(LogLevel level);

}  // namespace apprentice
