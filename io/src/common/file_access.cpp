// SPDX-License-Identifier: MIT
// ddfcam: whole-file reads and atomic writes.
#include "file_access.h"

#include <ddfcam/error.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <random>
#if __has_include(<unistd.h>)
#include <unistd.h>
#define DDFCAM_HAVE_FSYNC 1
#endif

namespace ddfcam::io::detail {
namespace {

std::string errnoText() {
  return std::strerror(errno);
}

std::string randomSuffix() {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  std::uint64_t bits = rng();
  for (int i = 0; i < 12; ++i, bits >>= 4) out += kHex[bits & 15u];
  return out;
}

}  // namespace

std::string readFileBytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw IoError("file " + path.string() + " does not exist");
  if (std::filesystem::is_directory(path, ec))
    throw IoError(path.string() + " is a directory, not a file");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw IoError("cannot open " + path.string() + ": " + errnoText());
  std::string bytes;
  char chunk[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file)) > 0) bytes.append(chunk, got);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) throw IoError("cannot read " + path.string());
  return bytes;
}

AtomicFileWriter::AtomicFileWriter(std::filesystem::path target) : target_(std::move(target)) {
  temp_ = target_;
  std::string suffix = randomSuffix();  // appended piecewise: GCC 12 -Wrestrict false positive
  temp_ += ".";
  temp_ += suffix;
  temp_ += ".tmp";
  file_ = std::fopen(temp_.c_str(), "wb");
  if (!file_) fail("cannot create " + temp_.string() + ": " + errnoText());
}

AtomicFileWriter::~AtomicFileWriter() {
  if (file_) std::fclose(file_);
  if (!committed_) {
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
}

void AtomicFileWriter::fail(const std::string& what) const {
  throw IoError("cannot write " + target_.string() + ": " + what);
}

void AtomicFileWriter::write(std::string_view bytes) {
  if (bytes.empty()) return;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    fail("write failed: " + errnoText());
}

void AtomicFileWriter::commit() {
  if (std::fflush(file_) != 0) fail("flush failed: " + errnoText());
#ifdef DDFCAM_HAVE_FSYNC
  if (::fsync(::fileno(file_)) != 0) fail("fsync failed: " + errnoText());
#endif
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0) fail("close failed: " + errnoText());
  std::error_code ec;
  std::filesystem::rename(temp_, target_, ec);
  if (ec) fail("rename from " + temp_.string() + " failed: " + ec.message());
  committed_ = true;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  AtomicFileWriter writer(path);
  writer.write(bytes);
  writer.commit();
}

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace ddfcam::io::detail
