// SPDX-License-Identifier: MIT
// ddfcam: the significant lines of a block-YAML text: indentation, content, comments removed.
#include "yaml_line_reader.h"

#include <ddfcam/error.h>

namespace ddfcam::io::detail {

std::string_view trimYamlRight(std::string_view s) {
  while (!s.empty() && isYamlBlank(s.back())) s.remove_suffix(1);
  return s;
}

void skipYamlBlanks(std::string_view& s) {
  while (!s.empty() && isYamlBlank(s.front())) s.remove_prefix(1);
}

bool isYamlSequenceItem(std::string_view content) {
  return content == "-" || (content.size() >= 2 && content[0] == '-' && isYamlBlank(content[1]));
}

std::string_view stripYamlComment(std::string_view s) {
  char quote = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const bool tokenStart =
        i == 0 || isYamlBlank(s[i - 1]) || s[i - 1] == '[' || s[i - 1] == '{' || s[i - 1] == ',';
    if (quote == '"') {
      if (c == '\\')
        ++i;
      else if (c == '"')
        quote = 0;
    } else if (quote == '\'') {
      if (c == '\'' && i + 1 < s.size() && s[i + 1] == '\'')
        ++i;
      else if (c == '\'')
        quote = 0;
    } else if ((c == '"' || c == '\'') && tokenStart) {
      quote = c;
    } else if (c == '#' && (i == 0 || isYamlBlank(s[i - 1]))) {
      return s.substr(0, i);
    }
  }
  return s;
}

YamlLineReader::YamlLineReader(std::string_view text, const std::string& sourceName)
    : text_(text), name_(sourceName) {
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;  // UTF-8 byte order mark
  advance();
}

void YamlLineReader::fail(int line, const std::string& what) const {
  throw IoError(name_ + ": line " + std::to_string(line) + ": " + what);
}

void YamlLineReader::advance() {
  has_ = false;
  while (pos_ < text_.size()) {
    const std::size_t end = text_.find('\n', pos_);
    const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
    std::string_view line = text_.substr(pos_, stop - pos_);
    pos_ = end == std::string_view::npos ? text_.size() : end + 1;
    ++lineNo_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    for (const char c : line)
      if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
        fail(lineNo_, "control character (binary data?)");
    std::size_t lead = 0;
    while (lead < line.size() && isYamlBlank(line[lead])) ++lead;
    const std::string_view content = trimYamlRight(stripYamlComment(line.substr(lead)));
    if (content.empty()) continue;
    if (ended_) fail(lineNo_, "content after the document end marker '...'");
    if (line.substr(0, lead).find('\t') != std::string_view::npos)
      fail(lineNo_, "tab in indentation (YAML indents with spaces)");
    if (marker(lead, content)) continue;
    seenContent_ = true;
    cur_ = {lineNo_, static_cast<int>(lead), content};
    has_ = true;
    return;
  }
}

bool YamlLineReader::marker(std::size_t lead, std::string_view content) {
  if (lead != 0) return false;
  if (content == "...") {
    ended_ = true;
    return true;
  }
  if (content[0] == '%') fail(lineNo_, "YAML directives are not supported");
  if (content.substr(0, 3) == "---") {
    if (seenContent_ || content != "---") fail(lineNo_, "several documents are not supported");
    seenContent_ = true;
    return true;
  }
  return false;
}

}  // namespace ddfcam::io::detail
