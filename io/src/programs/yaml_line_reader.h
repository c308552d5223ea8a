// SPDX-License-Identifier: MIT
// ddfcam: the significant lines of a block-YAML text: indentation, content, comments removed.
#pragma once

#include <string>
#include <string_view>

namespace ddfcam::io::detail {

/// @brief True for the blanks YAML allows between tokens (space, tab).
inline bool isYamlBlank(char c) {
  return c == ' ' || c == '\t';
}

/// @brief @p s without trailing blanks.
std::string_view trimYamlRight(std::string_view s);

/// @brief @p s without leading blanks (advances @p s).
void skipYamlBlanks(std::string_view& s);

/// @brief True if @p content starts a block sequence item ("-" alone or "- ...").
bool isYamlSequenceItem(std::string_view content);

/// @brief Content of a line without a trailing "#" comment; quotes protect "#".
std::string_view stripYamlComment(std::string_view s);

/// @brief One line with content.
struct YamlLine {
  int number = 0;            ///< 1-based line number
  int indent = 0;            ///< column of the content (spaces)
  std::string_view content;  ///< without indentation, comment and trailing blanks
};

/// @brief Walks the lines with content of one YAML document: skips blank and comment lines,
/// a leading "---" and a closing "..."; rejects control characters, tabs in indentation,
/// directives and several documents. Errors name the source and the line.
class YamlLineReader {
 public:
  /// @param text whole document (not owned); @param sourceName used in messages (not owned).
  YamlLineReader(std::string_view text, const std::string& sourceName);

  /// @brief True while current() holds a line.
  bool has() const { return has_; }
  /// @brief The current line; its indent and content may be narrowed by the parser (the
  /// content of a "- " item starts a node in its own column).
  YamlLine& current() { return cur_; }
  /// @brief Loads the next line with content; has() is false at the end.
  /// @throws IoError for the rejected lines described above.
  void advance();

  /// @brief Throws IoError "<source>: line N: <what>".
  [[noreturn]] void fail(int line, const std::string& what) const;

 private:
  /// True if the line with @p lead blanks and @p content is a document marker ("---" or
  /// "..."); fails for directives and for a second document.
  bool marker(std::size_t lead, std::string_view content);

  std::string_view text_;
  const std::string& name_;
  std::size_t pos_ = 0;
  int lineNo_ = 0;
  YamlLine cur_;
  bool has_ = false;
  bool ended_ = false;
  bool seenContent_ = false;
};

}  // namespace ddfcam::io::detail
