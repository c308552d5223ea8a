// SPDX-License-Identifier: MIT
// ddfcam: APT source records: comments, '$' continuation, major word and values.
#include "apt_lexer.h"

#include <ddfcam/error.h>

#include <cctype>
#include <charconv>
#include <cmath>

namespace ddfcam::io::detail {
namespace {

bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// Splits the record into its major word and the rest. With a '/', the major word is all
/// before it ("TOOL PATH", "GOTO "); without one, the first blank-separated token ("PARTNO
/// CORE_WORK", "RAPID", "FINI").
void splitMajor(AptRecord& record) {
  const std::string_view text = record.text;
  const std::size_t slash = text.find('/');
  std::string_view word;
  if (slash != std::string_view::npos) {
    word = text.substr(0, slash);
    record.rest = std::string(trimBlanks(text.substr(slash + 1)));
    record.slash = true;
  } else {
    std::size_t end = 0;
    while (end < text.size() && !isBlank(text[end])) ++end;
    word = text.substr(0, end);
    record.rest = std::string(trimBlanks(text.substr(end)));
    record.slash = false;
  }
  record.major.clear();
  bool pendingBlank = false;
  for (const char c : trimBlanks(word)) {
    if (isBlank(c)) {
      pendingBlank = true;
      continue;
    }
    if (pendingBlank) record.major += ' ';
    pendingBlank = false;
    record.major += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
}

}  // namespace

std::string_view trimBlanks(std::string_view text) {
  while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
  while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
  return text;
}

std::string upperAscii(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::vector<std::string_view> splitValues(std::string_view rest) {
  std::vector<std::string_view> values;
  rest = trimBlanks(rest);
  if (rest.empty()) return values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = rest.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? rest.size() : comma;
    values.push_back(trimBlanks(rest.substr(start, end - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return values;
}

int firstBinaryLine(std::string_view text) {
  int line = 1;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n') {
      ++line;
    } else if ((c < 0x20 && c != '\t' && c != '\r' && c != '\v' && c != '\f') || c == 0x7f) {
      return line;
    }
  }
  return 0;
}

double aptNumber(const AptLexer& lexer, const AptRecord& r, std::string_view token) {
  std::string_view t = token;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(value)) {
    lexer.fail(r.line, r.major + ": '" + std::string(token) + "' is not a finite number");
  }
  return value;
}

std::vector<double> aptNumbers(const AptLexer& lexer, const AptRecord& r,
                               const std::vector<std::string_view>& values) {
  std::vector<double> out;
  out.reserve(values.size());
  for (const std::string_view v : values) out.push_back(aptNumber(lexer, r, v));
  return out;
}

AptLexer::AptLexer(std::string_view text, std::string sourceName)
    : text_(text), sourceName_(std::move(sourceName)) {}

void AptLexer::fail(int line, const std::string& what) const {
  throw IoError(sourceName_ + ": line " + std::to_string(line) + ": " + what);
}

bool AptLexer::next(AptRecord& record, std::vector<AptComment>* comments) {
  record.text.clear();
  record.line = 0;
  bool continued = false;
  while (pos_ < text_.size()) {
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    // "$$" starts a comment; a single '$' continues the record on the next line (anything
    // after it is ignored, as on APT cards).
    bool continues = false;
    const std::size_t dollar = line.find('$');
    if (dollar != std::string_view::npos) {
      if (dollar + 1 < line.size() && line[dollar + 1] == '$') {
        const std::string_view note = trimBlanks(line.substr(dollar + 2));
        if (comments != nullptr && !note.empty()) comments->push_back({std::string(note), line_});
      } else {
        continues = true;
      }
      line = line.substr(0, dollar);
    }
    line = trimBlanks(line);
    if (!line.empty()) {
      if (record.text.empty()) record.line = line_;
      record.text += line;
    }
    continued = continues;
    if (!continues && !record.text.empty()) {
      splitMajor(record);
      return true;
    }
  }
  if (continued) fail(line_, "record continued with '$' but the file ends (truncated record)");
  if (!record.text.empty()) {
    splitMajor(record);
    return true;
  }
  return false;
}

}  // namespace ddfcam::io::detail
