// SPDX-License-Identifier: MIT
#include <ddfcam/log.h>

#include <mutex>

namespace ddfcam {
namespace {

std::mutex& sinkMutex() {
  static std::mutex m;
  return m;
}

LogSink& sinkStorage() {
  static LogSink sink;
  return sink;
}

}  // namespace

LogSink setLogSink(LogSink sink) {
  std::lock_guard lock(sinkMutex());
  LogSink previous = std::move(sinkStorage());
  sinkStorage() = std::move(sink);
  return previous;
}

void log(LogLevel level, const std::string& message) {
  LogSink sink;
  {
    std::lock_guard lock(sinkMutex());
    sink = sinkStorage();
  }
  if (sink) sink(level, message);
}

}  // namespace ddfcam
