// SPDX-License-Identifier: MIT
// ddfcam: the tool library text file (format in tool_library_file.h).
#include <ddfcam/io/project/tool_library_file.h>

#include <ddfcam/error.h>

#include "../common/file_access.h"
#include "../common/text_parsing.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::io {
namespace {

using planning::Tool;

/// A key of the format and the Tool field it sets (kind is handled apart).
struct NumberKey {
  std::string_view key;
  double Tool::*field;
};

constexpr std::array<NumberKey, 9> kNumberKeys{{
    {"radius_mm", &Tool::radiusMm},
    {"width_mm", &Tool::widthMm},
    {"edge_radius_mm", &Tool::edgeRadiusMm},
    {"crown_radius_mm", &Tool::crownRadiusMm},
    {"shank_radius_mm", &Tool::shankRadiusMm},
    {"shank_length_mm", &Tool::shankLengthMm},
    {"holder_radius_mm", &Tool::holderRadiusMm},
    {"holder_length_mm", &Tool::holderLengthMm},
    {"chord_tolerance_mm", &Tool::chordToleranceMm},
}};

constexpr std::string_view kBlanks = " \t\v\f\r";

/// Walks one line; every error names file, line and the 1-based byte column.
class LineParser {
 public:
  LineParser(std::string_view line, const detail::LineCursor& cursor)
      : line_(line), cursor_(cursor) {}

  [[noreturn]] void failAt(std::size_t at, const std::string& what) const {
    throw IoError(cursor_.fileName() + ":" + std::to_string(cursor_.lineNumber()) + ":" +
                  std::to_string(at + 1) + ": " + what);
  }

  /// Skips blanks; false at the end of the line or at a comment.
  bool more() {
    while (pos_ < line_.size() && kBlanks.find(line_[pos_]) != std::string_view::npos) ++pos_;
    return pos_ < line_.size() && line_[pos_] != '#';
  }

  std::size_t pos() const { return pos_; }

  /// The next run of characters up to a blank, a comment, or @p stop.
  std::string_view word(char stop = '\0') {
    const std::size_t start = pos_;
    while (pos_ < line_.size() && kBlanks.find(line_[pos_]) == std::string_view::npos &&
           line_[pos_] != '#' && line_[pos_] != stop)
      ++pos_;
    return line_.substr(start, pos_ - start);
  }

  bool take(char c) {
    if (pos_ >= line_.size() || line_[pos_] != c) return false;
    ++pos_;
    return true;
  }

  std::string quoted() {
    const std::size_t open = pos_;
    if (!take('"')) failAt(pos_, "expected the tool name in double quotes");
    std::string out;
    while (pos_ < line_.size() && line_[pos_] != '"') {
      char c = line_[pos_++];
      if (c == '\\') {
        if (pos_ >= line_.size()) break;
        const char e = line_[pos_++];
        static constexpr std::string_view kFrom = "\\\"nrt", kTo = "\\\"\n\r\t";
        const std::size_t i = kFrom.find(e);
        if (i == std::string_view::npos)
          failAt(pos_ - 2, std::string("unknown escape '\\") + e + "' in the tool name");
        c = kTo[i];
      }
      out += c;
    }
    if (!take('"')) failAt(open, "the tool name has no closing double quote");
    return out;
  }

 private:
  std::string_view line_;
  const detail::LineCursor& cursor_;
  std::size_t pos_ = 0;
};

double parseNumber(const LineParser& p, std::string_view text, std::size_t at,
                   std::string_view key) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() ||
      !std::isfinite(value))
    p.failAt(at,
             "'" + std::string(text) + "' is not a finite number (key '" + std::string(key) + "')");
  return value;
}

int parseInt(const LineParser& p, std::string_view text, std::size_t at, std::string_view key) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size())
    p.failAt(at, "'" + std::string(text) + "' is not an integer (key '" + std::string(key) + "')");
  return value;
}

/// Sets the field of @p key from @p value; false for an unknown key.
bool setField(Tool& tool, std::string_view key, std::string_view value, std::size_t at,
              const LineParser& p) {
  if (key == "kind") {
    const std::optional<planning::ToolKind> kind = planning::toolKindFromName(value);
    if (!kind) p.failAt(at, "unknown tool kind '" + std::string(value) + "'");
    tool.kind = *kind;
    return true;
  }
  if (key == "segments") {
    tool.segments = parseInt(p, value, at, key);
    return true;
  }
  for (const NumberKey& k : kNumberKeys) {
    if (k.key != key) continue;
    tool.*k.field = parseNumber(p, value, at, key);
    return true;
  }
  return false;
}

/// Parses one tool line (not blank, not a comment).
Tool parseToolLine(std::string_view line, const detail::LineCursor& cursor) {
  LineParser p(line, cursor);
  p.more();
  const std::size_t start = p.pos();
  if (p.word() != "tool") p.failAt(start, "expected a line starting with 'tool'");
  p.more();
  Tool tool;
  tool.name = p.quoted();
  std::vector<std::string_view> seen;
  while (p.more()) {
    const std::size_t keyAt = p.pos();
    const std::string_view key = p.word('=');
    if (!p.take('=')) p.failAt(keyAt, "expected key=value, found '" + std::string(key) + "'");
    for (const std::string_view k : seen)
      if (k == key) p.failAt(keyAt, "key '" + std::string(key) + "' given twice");
    const std::size_t valueAt = p.pos();
    if (!setField(tool, key, p.word(), valueAt, p))
      p.failAt(keyAt, "unknown key '" + std::string(key) + "'");
    seen.push_back(key);
  }
  if (std::find(seen.begin(), seen.end(), "kind") == seen.end())
    p.failAt(start, "tool '" + tool.name + "' has no kind (key 'kind')");
  try {
    planning::validateTool(tool);
  } catch (const InvalidInput& e) {
    p.failAt(start, e.what());
  }
  return tool;
}

void appendQuoted(std::string& out, std::string_view text) {
  out += '"';
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n' || c == '\r' || c == '\t')
      out += c == '\n' ? "\\n" : c == '\r' ? "\\r" : "\\t";
    else
      out += c;
  }
  out += '"';
}

}  // namespace

std::vector<Tool> parseToolLibrary(std::string_view text, const std::string& sourceName) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte order mark
  detail::LineCursor cursor(text, sourceName);
  std::vector<Tool> tools;
  std::string_view line;
  while (cursor.next(line)) {
    const std::size_t first = line.find_first_not_of(kBlanks);
    if (first == std::string_view::npos || line[first] == '#') continue;
    tools.push_back(parseToolLine(line, cursor));
  }
  return tools;
}

std::string formatToolLibrary(const std::vector<Tool>& tools) {
  for (const Tool& tool : tools) planning::validateTool(tool);
  std::string out =
      "# ddfcam tool library: one tool per line, lengths in mm\n"
      "# (format documented in io/include/ddfcam/io/project/tool_library_file.h)\n";
  for (const Tool& tool : tools) {
    out += "tool ";
    appendQuoted(out, tool.name);
    out += " kind=";
    out += planning::toolKindName(tool.kind);
    for (const NumberKey& k : kNumberKeys) {
      out += ' ';
      out += k.key;
      out += '=';
      detail::appendNumber(out, tool.*k.field);
    }
    out += " segments=" + std::to_string(tool.segments) + "\n";
  }
  return out;
}

std::vector<Tool> readToolLibrary(const std::filesystem::path& path) {
  return parseToolLibrary(detail::readFileBytes(path), path.string());
}

void writeToolLibrary(const std::filesystem::path& path, const std::vector<Tool>& tools) {
  detail::writeFileAtomically(path, formatToolLibrary(tools));
}

}  // namespace ddfcam::io
