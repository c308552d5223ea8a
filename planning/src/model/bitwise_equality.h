// SPDX-License-Identifier: MIT
// ddfcam: bitwise equality helpers behind projectsEqual() and mouldStudiesEqual() (private).
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <cstddef>
#include <cstring>
#include <optional>
#include <type_traits>
#include <vector>

namespace ddfcam::planning::detail {

/// Bitwise equality of contiguous trivially copyable values: NaN equals NaN with the same
/// payload, while 0.0 and -0.0 differ (a round trip must reproduce the bits).
template <class T>
bool sameBits(const T* a, const T* b, std::size_t count) {
  static_assert(std::is_trivially_copyable_v<T>);
  return count == 0 || std::memcmp(a, b, count * sizeof(T)) == 0;
}

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && sameBits(a.data(), b.data(), a.size());
}

inline bool sameBits(double a, double b) {
  return sameBits(&a, &b, 1);
}

inline bool sameBits(const ddf::Vec3& a, const ddf::Vec3& b) {
  return sameBits(a.data(), b.data(), 3);
}

/// Both empty, or both set and equal by @p same.
template <class T, class Same>
bool sameOptional(const std::optional<T>& a, const std::optional<T>& b, Same same) {
  if (a.has_value() != b.has_value()) return false;
  return !a || same(*a, *b);
}

/// Same size and equal element by element by @p same.
template <class T, class Same>
bool sameEach(const std::vector<T>& a, const std::vector<T>& b, Same same) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(a[i], b[i])) return false;
  return true;
}

}  // namespace ddfcam::planning::detail
