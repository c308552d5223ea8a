// SPDX-License-Identifier: MIT
// Helpers for the io tests: scratch directories and file writing.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/cl_program.h>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace ddfcam::test {

/// True if the @p bytes bytes at @p a and @p b are identical (NaN payloads and -0 included).
inline bool sameBits(const void* a, const void* b, std::size_t bytes) {
  return bytes == 0 || std::memcmp(a, b, bytes) == 0;
}

/// Expects two fields to be bit-identical: positions, vectors, face vertex order, heights.
inline void expectBitwiseEqual(const ddf::DisplacementField& a, const ddf::DisplacementField& b) {
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  ASSERT_EQ(a.faceCount(), b.faceCount());
  ASSERT_EQ(a.resolution(), b.resolution());
  for (int v = 0; v < a.vertexCount(); ++v) {
    EXPECT_TRUE(sameBits(a.position(v).data(), b.position(v).data(), 24)) << "position " << v;
    EXPECT_TRUE(sameBits(a.vector(v).data(), b.vector(v).data(), 24)) << "vector " << v;
  }
  for (int f = 0; f < a.faceCount(); ++f) EXPECT_EQ(a.faceVertices(f), b.faceVertices(f)) << f;
  ASSERT_EQ(a.allHeights().size(), b.allHeights().size());
  EXPECT_TRUE(sameBits(a.allHeights().data(), b.allHeights().data(), 4 * a.allHeights().size()));
}

/// The tool axis in force at each point of @p program: its own, else the last one given
/// before it (APT's axis is modal); none before the first.
inline std::vector<std::optional<ddf::Vec3>> axesInForce(const planning::ClProgram& program) {
  std::vector<std::optional<ddf::Vec3>> axes;
  std::optional<ddf::Vec3> last;
  for (const planning::ClPoint& p : program.points) {
    if (p.axis) last = p.axis;
    axes.push_back(last);
  }
  return axes;
}

/// A fresh directory under the system temp dir, removed with its content on destruction.
class ScratchDir {
 public:
  ScratchDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("ddfcam_io_test_" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Runs @p fn, expects an IoError and returns its unrolled message ("" if none was thrown).
inline std::string ioErrorMessage(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const IoError& e) {
    return unrollMessage(e);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected IoError, got: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected IoError, nothing thrown";
  return "";
}

}  // namespace ddfcam::test
