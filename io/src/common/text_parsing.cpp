// SPDX-License-Identifier: MIT
// ddfcam: line cursor, tokenizer and number parsing with file:line error messages.
#include "text_parsing.h"

#include <ddfcam/error.h>

#include <charconv>
#include <cmath>

namespace ddfcam::io::detail {
namespace {

bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string s(token.substr(0, kMax));
  if (token.size() > kMax) s += "...";
  return "'" + s + "'";
}

}  // namespace

LineCursor::LineCursor(std::string_view text, std::string fileName, int firstLine)
    : text_(text), fileName_(std::move(fileName)), line_(firstLine - 1) {}

bool LineCursor::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  const std::size_t end = text_.find('\n', pos_);
  const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
  line = text_.substr(pos_, stop - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end == std::string_view::npos ? text_.size() : end + 1;
  ++line_;
  return true;
}

void LineCursor::fail(const std::string& what) const {
  throw IoError(fileName_ + ":" + std::to_string(line_) + ": " + what);
}

void LineCursor::failFile(const std::string& what) const {
  throw IoError(fileName_ + ": " + what);
}

double LineCursor::toDouble(std::string_view token) const {
  std::string_view t = token;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || end != t.data() + t.size() || t.empty())
    fail("expected a number, found " + quoted(token));
  if (!std::isfinite(value)) fail("non-finite number " + quoted(token));
  return value;
}

std::int64_t LineCursor::toInt(std::string_view token) const {
  std::string_view t = token;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || end != t.data() + t.size() || t.empty())
    fail("expected an integer, found " + quoted(token));
  return value;
}

void splitTokens(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isBlank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !isBlank(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

std::string_view stripComment(std::string_view line, char comment) {
  const std::size_t at = line.find(comment);
  return at == std::string_view::npos ? line : line.substr(0, at);
}

bool looksBinary(std::string_view text) {
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\v' && c != '\f') return true;
  }
  return false;
}

void appendNumber(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace ddfcam::io::detail
