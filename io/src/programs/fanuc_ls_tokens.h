// SPDX-License-Identifier: MIT
// ddfcam: tokens of FANUC TP programs (.ls): blanks, numbers with units, position references.
#pragma once

#include <ddfcam/error.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io::detail {

/// @brief Throws IoError "<source>: line N: <what>" for the readers of one .ls text.
class LsErrors {
 public:
  /// @param sourceName used in messages (not owned).
  explicit LsErrors(const std::string& sourceName) : name_(sourceName) {}
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw IoError(name_ + ": line " + std::to_string(line) + ": " + what);
  }
  const std::string& sourceName() const { return name_; }

 private:
  const std::string& name_;
};

/// @brief Blanks of .ls text (space, tab, CR, LF).
inline bool lsIsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/// @brief @p s without leading and trailing blanks.
inline std::string_view lsTrim(std::string_view s) {
  while (!s.empty() && lsIsSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && lsIsSpace(s.back())) s.remove_suffix(1);
  return s;
}

/// @brief The blank-separated words of @p s.
inline std::vector<std::string_view> lsSplitSpaces(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && lsIsSpace(s[i])) ++i;
    const std::size_t start = i;
    while (i < s.size() && !lsIsSpace(s[i])) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

/// @brief True if @p s starts with @p prefix.
inline bool lsStartsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

/// @brief At most 40 characters of @p s for messages ("..." when cut).
inline std::string lsClip(std::string_view s) {
  return std::string(s.substr(0, 40)) + (s.size() > 40 ? "..." : "");
}

/// @brief Parses a leading number of @p s; advances @p s past it. nullopt if none.
inline std::optional<double> lsLeadingNumber(std::string_view& s) {
  std::string_view t = s;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || !std::isfinite(value)) return std::nullopt;
  s.remove_prefix(static_cast<std::size_t>(end - s.data()));
  return value;
}

/// @brief Parses "P[n]" or "P[n:comment]" at the front of @p s (advances @p s past it);
/// nullopt for a position register "PR[...]". @throws IoError for anything else.
inline std::optional<long> lsPointRef(std::string_view& s, int line, const LsErrors& errors) {
  s = lsTrim(s);
  if (lsStartsWith(s, "PR[")) return std::nullopt;
  if (!lsStartsWith(s, "P["))
    errors.fail(line, "expected a position 'P[n]', found '" + lsClip(s) + "'");
  s.remove_prefix(2);
  long index = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), index);
  if (ec != std::errc() || index < 0)
    errors.fail(line, "bad position number in '" + lsClip(s) + "'");
  s.remove_prefix(static_cast<std::size_t>(end - s.data()));
  if (!s.empty() && s.front() == ':') {
    const std::size_t close = s.size() > 1 && s[1] == '"' ? s.find('"', 2) : 1;
    if (close == std::string_view::npos) errors.fail(line, "unclosed position comment");
    s.remove_prefix(std::min(s.size(), s.find(']', close)));
  }
  if (s.empty() || s.front() != ']') errors.fail(line, "expected ']' after the position number");
  s.remove_prefix(1);
  return index;
}

}  // namespace ddfcam::io::detail
