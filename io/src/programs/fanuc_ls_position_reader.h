// SPDX-License-Identifier: MIT
// ddfcam: the /POS section of a FANUC TP program (.ls): Cartesian positions P[n] of group GP1.
#pragma once

#include "fanuc_ls_tokens.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>

namespace ddfcam::io::detail {

/// @brief Longest instruction or position entry of a .ls program, bytes (64 KiB).
inline constexpr std::size_t kMaxLsStatementBytes = std::size_t{1} << 16;

/// @brief One position P[n] of group GP1: X Y Z in mm, W P R in degrees (FANUC's fixed
/// angles: R about z, P about y, W about x, applied in that order).
struct LsPosition {
  int line = 0;                          ///< line of the entry's "P[n]{"
  bool joint = false;                    ///< only joint angles J1... given (not readable)
  int userFrame = 0;                     ///< UF number, 0 = world
  double value[6] = {0, 0, 0, 0, 0, 0};  ///< X Y Z (mm, |.| <= 1e12) W P R (deg)
};

/// @brief Collects the entries "P[n]{ GP1: UF : 0, ..., X = 1 mm, ... };" of /POS, fed line by
/// line. Errors name the source and the line of the offending item.
class LsPositionReader {
 public:
  /// @param errors reports errors (not owned).
  explicit LsPositionReader(const LsErrors& errors) : errors_(errors) {}

  /// @brief Reads line @p number of the /POS section.
  /// @throws IoError for text that is not a position entry, a missing group GP1 or value, a
  /// non-number, a wrong unit, a coordinate beyond 1e12 mm or a P[n] defined twice.
  void line(std::string_view line, int number);
  /// @brief At the end of the section. @throws IoError if an entry lacks its "};".
  void close() const {
    if (entryOpen_) errors_.fail(entryLine_, "position entry does not end with '};'");
  }
  /// @brief The positions read so far, by n of P[n].
  const std::unordered_map<long, LsPosition>& positions() const { return positions_; }

 private:
  void entry(std::string_view text, int line);
  LsPosition parseGroup(std::string_view group, std::string_view text, int line, long index) const;
  /// Reads "NAME = value unit" or "NAME : value"; true for a joint value J1...
  bool groupItem(std::string_view item, int line, LsPosition& position, bool* seen) const;

  const LsErrors& errors_;
  bool entryOpen_ = false;
  int entryLine_ = 0;
  std::string entryText_;
  std::unordered_map<long, LsPosition> positions_;
};

}  // namespace ddfcam::io::detail
