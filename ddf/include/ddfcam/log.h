// SPDX-License-Identifier: MIT
// ddfcam: the log facade. The core never prints; a host (GUI console, CLI stderr) installs a sink.
#pragma once

#include <functional>
#include <string>

namespace ddfcam {

enum class LogLevel { Debug, Info, Warning, Error };

/// @brief Receives every message logged by the libraries. Must be thread-safe.
using LogSink = std::function<void(LogLevel level, const std::string& message)>;

/// @brief Installs @p sink (an empty function discards messages); returns the previous sink.
LogSink setLogSink(LogSink sink);

/// @brief Forwards @p message to the installed sink, if any.
void log(LogLevel level, const std::string& message);

}  // namespace ddfcam
