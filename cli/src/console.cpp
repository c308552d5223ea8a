// SPDX-License-Identifier: MIT
// ddfcam-cli: progress and log output on stderr.
#include "console.h"

#include <ddfcam/log.h>

#include <unistd.h>
#include <cstdio>
#include <memory>

namespace ddfcam::cli {
namespace {

bool progressLineOpen = false;

}  // namespace

ProgressCallback consoleProgress(const std::string& label) {
  if (!::isatty(STDERR_FILENO)) return [](double) { return true; };
  auto lastPercent = std::make_shared<int>(-1);
  return [label, lastPercent](double fraction) {
    const int percent = static_cast<int>(fraction * 100.0 + 0.5);
    if (percent != *lastPercent) {
      *lastPercent = percent;
      std::fprintf(stderr, "\r%s: %3d%%", label.c_str(), percent);
      std::fflush(stderr);
      progressLineOpen = true;
    }
    return true;
  };
}

void endProgressLine() {
  if (progressLineOpen) std::fputc('\n', stderr);
  progressLineOpen = false;
}

void installLogSink() {
  setLogSink([](LogLevel level, const std::string& message) {
    if (level < LogLevel::Warning) return;
    endProgressLine();
    std::fprintf(stderr, "%s: %s\n", level == LogLevel::Error ? "error" : "warning",
                 message.c_str());
  });
}

std::string formatBytes(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 4) bytes /= 1024.0, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", bytes, units[unit]);
  return text;
}

}  // namespace ddfcam::cli
