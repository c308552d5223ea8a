// SPDX-License-Identifier: MIT
// ddfcam: the fixed header of a .ddf file and the checks of its envelope (size, checksum).
#pragma once

#include <ddfcam/ddf/raster.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace ddfcam::io::detail {

inline constexpr std::string_view kDdfMagic{"DDFCAM\x1a\n", 8};
inline constexpr std::uint32_t kDdfByteOrderMark = 0x01020304u;
inline constexpr std::size_t kDdfHeaderBytes = 40;
inline constexpr std::size_t kDdfChecksumBytes = 4;
/// Largest raster resolution accepted when reading (guards against absurd allocations).
inline constexpr std::uint32_t kDdfMaxResolution = 1u << 15;

/// @brief The fixed-size header of a .ddf file.
struct DdfHeader {
  std::uint32_t version = 1;  ///< 1: no metadata section; 2: with one
  std::uint64_t vertexCount = 0;
  std::uint64_t faceCount = 0;
  std::uint32_t m = 2;
  /// Version 2: byte count L of the metadata section after its u32 length (set by
  /// checkDdfEnvelope; not part of the 40 header bytes).
  std::uint64_t metadataBytes = 0;
};

/// @brief Appends the 40 header bytes for @p header (its version, byte-order marker).
void putDdfHeader(std::string& out, const DdfHeader& header);

/// @brief Validates magic, version, byte order, counts, exact file size (for version 2 with
/// the metadata section's length) and checksum.
/// @return the header; after this, the body can be decoded without bounds checks.
/// @throws IoError "<sourceName>: <what is wrong>".
DdfHeader checkDdfEnvelope(std::string_view bytes, const std::string& sourceName);

/// @brief Copies the heights @p stored of a face, in Raster order for the local vertex order
/// @p storedOrder, into @p out in Raster order for @p actualOrder (a permutation of the same
/// vertices): a raster point keeps its weights on each vertex.
/// @throws IoError if @p actualOrder is not a permutation of @p storedOrder.
void reorderHeights(const std::array<int, 3>& storedOrder, const std::array<int, 3>& actualOrder,
                    const ddf::Raster& raster, std::span<const float> stored, std::span<float> out);

}  // namespace ddfcam::io::detail
