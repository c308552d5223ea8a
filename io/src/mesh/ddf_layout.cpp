// SPDX-License-Identifier: MIT
// ddfcam: .ddf header writing and envelope validation.
#include "ddf_layout.h"

#include <ddfcam/error.h>
#include <ddfcam/io/common/checksum.h>
#include <ddfcam/io/mesh/ddf_file.h>

#include "../common/byte_codec.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace ddfcam::io::detail {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw IoError(name + ": " + what);
}

/// a * b + c, or nullopt on 64-bit overflow.
std::optional<std::uint64_t> mulAdd(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  constexpr auto kMax = std::numeric_limits<std::uint64_t>::max();
  if (b != 0 && a > (kMax - c) / b) return std::nullopt;
  return a * b + c;
}

void checkIdentity(std::string_view bytes, const std::string& name) {
  if (bytes.empty()) fail(name, "file is empty, not a .ddf file");
  if (bytes.size() < kDdfMagic.size()) {
    if (kDdfMagic.substr(0, bytes.size()) == bytes)
      fail(name,
           "truncated .ddf file: " + std::to_string(bytes.size()) + " bytes, ends in the magic");
    fail(name, "not a .ddf file (wrong magic)");
  }
  if (bytes.substr(0, kDdfMagic.size()) != kDdfMagic) fail(name, "not a .ddf file (wrong magic)");
  if (bytes.size() >= 12) {
    const std::uint32_t version = getU32(bytes.data() + 8);
    if (version > kDdfFormatVersion)
      fail(name, "unsupported .ddf format version " + std::to_string(version) +
                     ": this build reads versions up to " + std::to_string(kDdfFormatVersion) +
                     " (file from a newer ddfcam, or a corrupted header)");
    if (version == 0) fail(name, "invalid .ddf format version 0 (corrupted header)");
  }
  if (bytes.size() >= 16) {
    const std::uint32_t mark = getU32(bytes.data() + 12);
    if (mark == 0x04030201u)
      fail(name,
           "byte-order marker is big-endian: written by a foreign writer, not a valid "
           "little-endian .ddf file");
    if (mark != kDdfByteOrderMark) fail(name, "corrupted byte-order marker in the .ddf header");
  }
  if (bytes.size() < kDdfHeaderBytes)
    fail(name, "truncated .ddf file: " + std::to_string(bytes.size()) +
                   " bytes, shorter than the " + std::to_string(kDdfHeaderBytes) + "-byte header");
}

DdfHeader parseHeader(std::string_view bytes, const std::string& name) {
  DdfHeader header;
  header.version = getU32(bytes.data() + 8);
  header.vertexCount = getU64(bytes.data() + 16);
  header.faceCount = getU64(bytes.data() + 24);
  header.m = getU32(bytes.data() + 32);
  if (getU32(bytes.data() + 36) != 0) fail(name, "corrupted .ddf header (reserved field not 0)");
  if (header.m < 2 || header.m > kDdfMaxResolution)
    fail(name, "corrupted .ddf header: raster resolution m = " + std::to_string(header.m) +
                   " outside [2, " + std::to_string(kDdfMaxResolution) + "]");
  constexpr std::uint64_t kMaxCount = std::numeric_limits<std::int32_t>::max();
  if (header.vertexCount > kMaxCount || header.faceCount > kMaxCount)
    fail(name, "corrupted .ddf header: implausible counts (" + std::to_string(header.vertexCount) +
                   " vertices, " + std::to_string(header.faceCount) + " faces)");
  return header;
}

}  // namespace

void putDdfHeader(std::string& out, const DdfHeader& header) {
  out.append(kDdfMagic);
  putU32(out, header.version);
  putU32(out, kDdfByteOrderMark);
  putU64(out, header.vertexCount);
  putU64(out, header.faceCount);
  putU32(out, header.m);
  putU32(out, 0);
}

DdfHeader checkDdfEnvelope(std::string_view bytes, const std::string& name) {
  checkIdentity(bytes, name);
  DdfHeader header = parseHeader(bytes, name);
  const std::uint64_t perFace = std::uint64_t{header.m} * (header.m + 1) / 2;
  auto size = mulAdd(header.vertexCount, 48, kDdfHeaderBytes + kDdfChecksumBytes);
  if (size) size = mulAdd(header.faceCount, 12, *size);
  if (size && mulAdd(header.faceCount, perFace, 0))
    size = mulAdd(header.faceCount * perFace, 4, *size);
  else
    size.reset();
  if (!size) fail(name, "corrupted .ddf header: counts overflow the file size");
  if (header.version >= 2) {
    // The section's length sits where a version-1 file has its checksum.
    const std::uint64_t at = *size - kDdfChecksumBytes;
    if (bytes.size() < at + 4)
      fail(name, "truncated .ddf file: it ends before the length of its metadata section");
    header.metadataBytes = getU32(bytes.data() + at);
    size = *size + 4 + header.metadataBytes;
  }
  if (bytes.size() < *size)
    fail(name, "truncated .ddf file: the header promises " + std::to_string(*size) +
                   " bytes but the file has " + std::to_string(bytes.size()));
  if (bytes.size() > *size)
    fail(name, "corrupted .ddf file: " + std::to_string(bytes.size()) +
                   " bytes where the header "
                   "promises " +
                   std::to_string(*size) + " (trailing data or corrupted counts)");
  const std::size_t body = bytes.size() - kDdfChecksumBytes;
  const std::uint32_t stored = getU32(bytes.data() + body);
  const std::uint32_t actual = crc32(std::as_bytes(std::span(bytes.data(), body)));
  if (stored != actual) fail(name, "checksum mismatch: the .ddf file is corrupted");
  return header;
}

void reorderHeights(const std::array<int, 3>& storedOrder, const std::array<int, 3>& actualOrder,
                    const ddf::Raster& raster, std::span<const float> stored,
                    std::span<float> out) {
  std::array<int, 3> slot{};
  for (int s = 0; s < 3; ++s) {
    const auto at = std::find(actualOrder.begin(), actualOrder.end(), storedOrder[s]);
    if (at == actualOrder.end()) throw IoError("face vertex orders are not permutations");
    slot[s] = static_cast<int>(at - actualOrder.begin());
  }
  const int n = raster.steps();
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n - k; ++i) {
      const int weights[3] = {i, n - i - k, k};
      int moved[3] = {0, 0, 0};
      for (int s = 0; s < 3; ++s) moved[slot[s]] = weights[s];
      out[raster.index(moved[0], moved[2])] = stored[raster.index(i, k)];
    }
}

}  // namespace ddfcam::io::detail
