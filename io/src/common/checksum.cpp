// SPDX-License-Identifier: MIT
// ddfcam: CRC-32 by zlib's crc32_z (already linked for compressed VTK XML arrays).
#include <ddfcam/io/common/checksum.h>

#include <zlib.h>

namespace ddfcam::io {

void Crc32::update(std::span<const std::byte> bytes) {
  state_ = static_cast<std::uint32_t>(
      crc32_z(state_, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

std::uint32_t crc32(std::span<const std::byte> bytes) {
  Crc32 crc;
  crc.update(bytes);
  return crc.value();
}

}  // namespace ddfcam::io
