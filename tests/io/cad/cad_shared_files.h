// SPDX-License-Identifier: MIT
// Test support for the shared STEP parts (skipped without ../shared/data): their paths.
#pragma once

#include <filesystem>
#include <string>

namespace ddfcam::io::test {

inline std::filesystem::path cadPath(const std::string& file) {
  return std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "cad" / file;
}

}  // namespace ddfcam::io::test

/// Skips the test when the shared file @p path is absent.
#define REQUIRE_SHARED(path) \
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data not found at " << (path)
