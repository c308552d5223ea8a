// SPDX-License-Identifier: MIT
// ddfcam: CRC-32 (IEEE 802.3, the zlib/PNG polynomial) for file integrity checks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace ddfcam::io {

/// @brief Incremental CRC-32 (reflected polynomial 0xEDB88320, initial value and final XOR
/// 0xFFFFFFFF), identical to zlib's crc32(); crc32 of "123456789" is 0xCBF43926.
class Crc32 {
 public:
  /// @brief Feeds @p bytes into the checksum.
  void update(std::span<const std::byte> bytes);
  /// @brief Checksum of everything fed so far.
  std::uint32_t value() const { return state_; }

 private:
  std::uint32_t state_ = 0;  // zlib's running value: the checksum of no bytes
};

/// @brief CRC-32 of @p bytes in one call.
std::uint32_t crc32(std::span<const std::byte> bytes);

}  // namespace ddfcam::io
