// SPDX-License-Identifier: MIT
// ddfcam: whole-file reads and atomic writes (temporary file + rename) shared by the formats.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace ddfcam::io::detail {

/// @brief The whole content of @p path.
/// @throws IoError naming the file if it is missing, a directory or unreadable.
std::string readFileBytes(const std::filesystem::path& path);

/// @brief Writes a file under a temporary name in the target's directory and renames it over
/// the target on commit(), so readers never see a half-written file. Without commit() (an
/// exception while writing) the destructor removes the temporary file.
class AtomicFileWriter {
 public:
  /// @throws IoError if the temporary file cannot be created.
  explicit AtomicFileWriter(std::filesystem::path target);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  /// @throws IoError if the bytes cannot be written (disk full, ...).
  void write(std::string_view bytes);
  /// @brief Flushes, syncs and renames the temporary file over the target.
  /// @throws IoError on failure (the target is left unchanged).
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what) const;

  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

/// @brief Writes @p bytes to @p path atomically (see AtomicFileWriter).
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

/// @brief The extension of @p path in lower case, dot included (".stl"); empty if none.
std::string lowerExtension(const std::filesystem::path& path);

}  // namespace ddfcam::io::detail
