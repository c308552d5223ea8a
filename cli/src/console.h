// SPDX-License-Identifier: MIT
// ddfcam-cli: progress and log output on stderr.
#pragma once

#include <ddfcam/progress.h>

#include <string>

namespace ddfcam::cli {

/// @brief A progress callback that shows "<label>: NN%" on stderr, rewritten in place, when
/// stderr is a terminal (silent otherwise, so redirected output stays clean). Never cancels.
ProgressCallback consoleProgress(const std::string& label);

/// @brief Ends a progress line started by consoleProgress (prints the newline if needed).
void endProgressLine();

/// @brief Routes library log messages of level Warning and above to stderr.
void installLogSink();

/// @brief Human-readable byte count ("12.3 MiB").
std::string formatBytes(double bytes);

}  // namespace ddfcam::cli
