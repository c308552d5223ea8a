// SPDX-License-Identifier: MIT
// ddfcam: explicit little/big-endian encoding, byte by byte, independent of the host order.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace ddfcam::io::detail {

/// @brief Appends the @p bytes low-order bytes of @p value, least significant first.
inline void putLe(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 0xFFu);
}
inline void putU16(std::string& out, std::uint16_t v) {
  putLe(out, v, 2);
}
inline void putU32(std::string& out, std::uint32_t v) {
  putLe(out, v, 4);
}
inline void putU64(std::string& out, std::uint64_t v) {
  putLe(out, v, 8);
}
inline void putF32(std::string& out, float v) {
  putU32(out, std::bit_cast<std::uint32_t>(v));
}
inline void putF64(std::string& out, double v) {
  putU64(out, std::bit_cast<std::uint64_t>(v));
}

/// @brief Unsigned integer of @p bytes bytes at @p p, little-endian (or big-endian).
inline std::uint64_t getUnsigned(const char* p, int bytes, bool bigEndian = false) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) {
    const int shift = 8 * (bigEndian ? bytes - 1 - i : i);
    v |= static_cast<std::uint64_t>(static_cast<unsigned char>(p[i])) << shift;
  }
  return v;
}
inline std::uint16_t getU16(const char* p) {
  return static_cast<std::uint16_t>(getUnsigned(p, 2));
}
inline std::uint32_t getU32(const char* p) {
  return static_cast<std::uint32_t>(getUnsigned(p, 4));
}
inline std::uint64_t getU64(const char* p) {
  return getUnsigned(p, 8);
}
inline float getF32(const char* p) {
  return std::bit_cast<float>(getU32(p));
}
inline double getF64(const char* p) {
  return std::bit_cast<double>(getU64(p));
}

}  // namespace ddfcam::io::detail
