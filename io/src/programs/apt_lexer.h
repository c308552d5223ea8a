// SPDX-License-Identifier: MIT
// ddfcam: APT source records: comments, '$' continuation, major word and values.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io::detail {

/// @brief One logical APT record: its physical lines joined, comments and '$' removed.
struct AptRecord {
  std::string text;    ///< the record without comments, continuation marks or line ends
  int line = 0;        ///< 1-based line the record starts on
  std::string major;   ///< major word, upper case, inner blanks collapsed ("TOOL PATH")
  bool slash = false;  ///< the record has a '/' after its major word
  std::string rest;    ///< text after '/' (or after the major word without '/'), trimmed
};

/// @brief A comment of the source: its text after "$$", trimmed, and its line.
struct AptComment {
  std::string text;  ///< comment text
  int line = 0;      ///< 1-based line
};

/// @brief Walks the records of APT source text. Errors name the source and the line.
class AptLexer {
 public:
  /// @param text whole source (not owned); @param sourceName used in messages.
  AptLexer(std::string_view text, std::string sourceName);

  /// @brief Next non-empty record; false at the end. Comments met on the way are appended
  /// to @p comments when it is not null.
  /// @throws IoError for a '$' continuation on the last line.
  bool next(AptRecord& record, std::vector<AptComment>* comments);

  /// @brief Throws IoError "<source>: line N: <what>".
  [[noreturn]] void fail(int line, const std::string& what) const;

  const std::string& sourceName() const { return sourceName_; }

 private:
  std::string_view text_;
  std::string sourceName_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

/// @brief The finite number @p token of record @p r ('+' sign, ".5", "1e3" accepted).
/// @throws IoError "<source>: line N: <major>: '<token>' is not a finite number".
double aptNumber(const AptLexer& lexer, const AptRecord& r, std::string_view token);

/// @brief aptNumber() of every value.
std::vector<double> aptNumbers(const AptLexer& lexer, const AptRecord& r,
                               const std::vector<std::string_view>& values);

/// @brief Blank-trimmed @p text (space, tab, CR, VT, FF).
std::string_view trimBlanks(std::string_view text);

/// @brief Upper-case ASCII copy of @p text.
std::string upperAscii(std::string_view text);

/// @brief The comma-separated values of @p rest, each trimmed; an empty @p rest gives none.
std::vector<std::string_view> splitValues(std::string_view rest);

/// @brief The first line holding a byte no APT text contains (NUL and other controls except
/// tab, CR, LF, VT, FF); 0 if there is none.
int firstBinaryLine(std::string_view text);

}  // namespace ddfcam::io::detail
