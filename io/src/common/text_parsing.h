// SPDX-License-Identifier: MIT
// ddfcam: line cursor, tokenizer and number parsing with file:line error messages.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io::detail {

/// @brief Walks the lines of a text buffer; errors name the file and the 1-based line.
class LineCursor {
 public:
  /// @param text whole buffer (not owned); @param fileName used in messages;
  /// @param firstLine number of the buffer's first line (for bodies after a header).
  LineCursor(std::string_view text, std::string fileName, int firstLine = 1);

  /// @brief Next line without its line terminator; false at the end of the buffer.
  bool next(std::string_view& line);
  /// @brief Line number of the line last returned by next().
  int lineNumber() const { return line_; }
  /// @brief Bytes not yet returned.
  std::string_view rest() const { return text_.substr(pos_); }
  const std::string& fileName() const { return fileName_; }

  /// @brief Throws IoError "<file>:<line>: <what>".
  [[noreturn]] void fail(const std::string& what) const;
  /// @brief Throws IoError "<file>: <what>" (no line, e.g. for a missing section at the end).
  [[noreturn]] void failFile(const std::string& what) const;

  /// @brief Parses a finite double; fails with the line number otherwise.
  double toDouble(std::string_view token) const;
  /// @brief Parses a signed integer; fails with the line number otherwise.
  std::int64_t toInt(std::string_view token) const;

 private:
  std::string_view text_;
  std::string fileName_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

/// @brief Splits @p line at blanks (space, tab, CR, VT, FF).
void splitTokens(std::string_view line, std::vector<std::string_view>& out);

/// @brief @p line without everything from the first @p comment character on.
std::string_view stripComment(std::string_view line, char comment);

/// @brief True if @p text holds a NUL byte or other control characters that no text mesh
/// format contains (used to reject binary garbage early with a clear message).
bool looksBinary(std::string_view text);

/// @brief Shortest decimal form of @p value that reads back to the same double.
void appendNumber(std::string& out, double value);

}  // namespace ddfcam::io::detail
