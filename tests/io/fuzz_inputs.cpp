// SPDX-License-Identifier: MIT
// ddfcam tests: deterministic mutations of path-file texts and the reader contract they check.
#include "fuzz_inputs.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace ddfcam::test {
namespace {

constexpr std::size_t kMaxText = 256 * 1024;

/// Numbers readers must refuse or survive: overflow, NaN, empty, int limits, odd syntax.
// clang-format off
const std::vector<std::string> kHostileNumbers = {
    "", "1e308", "-1e308", "1e999", "-1e999", "nan", "NaN", "-nan", "inf", "-inf", "0", "-0",
    "1e-320", "0x1p3", "99999999999999999999", "2147483647", "2147483648", "-2147483649",
    "4294967296", "9223372036854775808", "+", "-", ".", "1.2.3", "1e", "--1", "1,5", " 7 ",
    "1e400", "-1e-400", "0.0000000000000000000000000000001", "123456789012345678901234567890"};
// clang-format on

bool isNumberChar(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' ||
         c == 'e' || c == 'E';
}

}  // namespace

TextMutator::TextMutator(std::uint64_t seed, std::vector<std::string> tokens)
    : rng_(seed), tokens_(std::move(tokens)) {
  tokens_.insert(tokens_.end(), kHostileNumbers.begin(), kHostileNumbers.end());
}

std::size_t TextMutator::below(std::size_t n) {
  return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_);
}

std::string TextMutator::mutate(std::string_view text, std::string_view other) {
  std::string out(text);
  const std::size_t edits = 1 + below(4);
  for (std::size_t e = 0; e < edits; ++e) mutateOnce(out, other);
  if (out.size() > kMaxText) out.resize(kMaxText);
  return out;
}

void TextMutator::mutateOnce(std::string& text, std::string_view other) {
  const std::size_t at = below(text.size() + 1);
  switch (below(14)) {
    case 0:  // flip one bit
      if (!text.empty()) text[below(text.size())] ^= static_cast<char>(1u << below(8));
      break;
    case 1:  // overwrite a byte
      if (!text.empty()) text[below(text.size())] = static_cast<char>(below(256));
      break;
    case 2:  // insert a few random bytes
      for (std::size_t n = 1 + below(8); n > 0; --n)
        text.insert(text.begin() + below(text.size() + 1), static_cast<char>(below(256)));
      break;
    case 3:  // delete a range
      text.erase(at, below(std::min<std::size_t>(text.size() - at, 64) + 1));
      break;
    case 4:  // duplicate a range
      text.insert(at, text.substr(at, below(128)));
      break;
    case 5:  // splice: a prefix of this text with a suffix of the other
      if (!other.empty())
        text = text.substr(0, at) + std::string(other.substr(below(other.size())));
      break;
    case 6:
    case 7:
      replaceNumber(text);
      break;
    case 8:  // truncate the whole text
      text.resize(at);
      break;
    case 9:
      editLines(text);
      break;
    case 10:  // long inputs are slow to read: keep them to about one input in twenty
      if (below(4) == 0) insertLong(text);
      break;
    case 11: {  // binary garbage
      std::string garbage(1 + below(256), '\0');
      for (char& c : garbage) c = static_cast<char>(below(256));
      text.insert(at, garbage);
      break;
    }
    case 12:
    case 13:  // a format token
      text.insert(at, tokens_[below(tokens_.size())]);
      break;
  }
}

void TextMutator::replaceNumber(std::string& text) {
  // Start at a random digit and widen to the whole number token around it.
  std::size_t start = below(text.size() + 1);
  while (start < text.size() && !std::isdigit(static_cast<unsigned char>(text[start]))) ++start;
  if (start >= text.size()) return;
  std::size_t end = start;
  while (start > 0 && isNumberChar(text[start - 1])) --start;
  while (end < text.size() && isNumberChar(text[end])) ++end;
  const std::string& replacement = below(4) == 0 ? tokens_[below(tokens_.size())]
                                                 : kHostileNumbers[below(kHostileNumbers.size())];
  text.replace(start, end - start, replacement);
}

void TextMutator::editLines(std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    lines.emplace_back(text.substr(at, end - at));
    at = end + 1;
  }
  const std::size_t i = below(lines.size());
  const std::size_t j = below(lines.size());
  switch (below(6)) {
    case 0:  // truncated line
      lines[i].resize(below(lines[i].size() + 1));
      break;
    case 1:
      lines.erase(lines.begin() + i);
      break;
    case 2:
      lines.insert(lines.begin() + i, lines[j]);
      break;
    case 3:
      std::swap(lines[i], lines[j]);
      break;
    case 4:  // repeat one line many times
      lines.insert(lines.begin() + i, 1 + below(500), lines[j]);
      break;
    case 5:  // other line ends
      for (std::string& line : lines) line += below(2) ? "\r" : "";
      break;
  }
  text.clear();
  for (std::size_t k = 0; k < lines.size(); ++k) text += (k ? "\n" : "") + lines[k];
}

void TextMutator::insertLong(std::string& text) {
  const std::size_t at = below(text.size() + 1);
  switch (below(4)) {
    case 0:  // one very long line of digits
      text.insert(at, 1 + below(30000), '9');
      break;
    case 1: {  // very many fields
      std::string fields;
      for (std::size_t n = 1 + below(3000); n > 0; --n) fields += "1,";
      text.insert(at, fields);
      break;
    }
    case 2:  // deep nesting / deep indentation (YAML)
      text.insert(at, std::string(1 + below(5000), below(2) ? '[' : '{'));
      break;
    case 3: {
      std::string nested;
      for (std::size_t depth = 1 + below(120), d = 0; d < depth; ++d) {
        nested += '\n';
        nested.append(2 * d, ' ');
        nested += "- a:";
      }
      text.insert(at, nested);
      break;
    }
  }
}

int lineCount(std::string_view text) {
  if (text.empty()) return 0;
  const auto ends = std::count(text.begin(), text.end(), '\n');
  return static_cast<int>(ends + (text.back() == '\n' ? 0 : 1));
}

std::optional<long long> lineNumberIn(std::string_view message) {
  for (std::size_t at = message.find("line "); at != std::string_view::npos;
       at = message.find("line ", at + 1)) {
    std::size_t digits = at + 5;
    long long value = 0;
    bool any = false;
    for (; digits < message.size() && std::isdigit(static_cast<unsigned char>(message[digits]));
         ++digits) {
      value = std::min(value * 10 + (message[digits] - '0'), 1LL << 40);
      any = true;
    }
    if (any) return value;
  }
  return std::nullopt;
}

std::optional<std::string> messageViolation(std::string_view message, std::string_view text,
                                            std::string_view sourceName) {
  if (message.substr(0, sourceName.size()) != sourceName)
    return "message does not start with the file name: " + std::string(message);
  const auto line = lineNumberIn(message);
  // Some readers count the line after the last line end (an unexpected end of file).
  if (line && (*line < 1 || *line > lineCount(text) + 1))
    return "line " + std::to_string(*line) + " outside 1.." + std::to_string(lineCount(text) + 1) +
           ": " + std::string(message);
  return std::nullopt;
}

namespace {

bool finite(const ddf::Vec3& v) {
  return v.allFinite();
}

bool unit(const ddf::Vec3& v) {
  return v.allFinite() && std::abs(v.norm() - 1.0) < 1e-6;
}

std::string str(const ddf::Vec3& v) {
  char text[128];
  std::snprintf(text, sizeof text, "(%.17g, %.17g, %.17g)", v.x(), v.y(), v.z());
  return text;
}

}  // namespace

std::optional<std::string> programViolation(const planning::ClProgram& program,
                                            std::string_view text) {
  const int lines = lineCount(text);
  for (std::size_t p = 0; p < program.points.size(); ++p) {
    const planning::ClPoint& point = program.points[p];
    const std::string where =
        "point " + std::to_string(p) + " (line " + std::to_string(point.sourceLine) + "): ";
    if (!finite(point.positionMm)) return where + "position not finite: " + str(point.positionMm);
    if (point.axis && !unit(*point.axis))
      return where + "axis not a unit vector: " + str(*point.axis);
    if (point.normal && !unit(*point.normal))
      return where + "normal not a unit vector: " + str(*point.normal);
    if (!std::isfinite(point.feedMmPerMin) || point.feedMmPerMin < 0.0)
      return where + "feed not finite and >= 0: " + std::to_string(point.feedMmPerMin);
    if (point.path < 0 || point.point < 0) return where + "negative path or point index";
    if (point.sourceLine < 0 || point.sourceLine > lines + 1)
      return where + "source line outside 0.." + std::to_string(lines + 1);
  }
  if (!std::isfinite(program.spindleRpm)) return "spindle speed not finite";
  if (program.toolNumber < 0) return "negative tool number";
  return std::nullopt;
}

std::string escaped(std::string_view text, std::size_t maxBytes) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < maxBytes; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\\' || c == '"') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c >= 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (text.size() > maxBytes) out += "...(" + std::to_string(text.size()) + " bytes)";
  return out;
}

}  // namespace ddfcam::test
