// SPDX-License-Identifier: MIT
// ddfcam: table-driven CRC-32.
#include <ddfcam/io/checksum.h>

#include <array>

namespace ddfcam::io {
namespace {

constexpr std::array<std::uint32_t, 256> makeTable() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int bit = 0; bit < 8; ++bit) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[i] = c;
  }
  return table;
}

constexpr auto kTable = makeTable();

}  // namespace

void Crc32::update(std::span<const std::byte> bytes) {
  std::uint32_t c = state_;
  for (const std::byte b : bytes)
    c = kTable[(c ^ static_cast<std::uint32_t>(b)) & 0xFFu] ^ (c >> 8);
  state_ = c;
}

std::uint32_t crc32(std::span<const std::byte> bytes) {
  Crc32 crc;
  crc.update(bytes);
  return crc.value();
}

}  // namespace ddfcam::io
