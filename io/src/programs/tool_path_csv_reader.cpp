// SPDX-License-Identifier: MIT
// ddfcam: reading tool-path CSVs: ddfcam's own columns and the common x,y,z[,i,j,k] variants,
// any delimiter, with or without header; every error names the line.
#include <ddfcam/io/programs/tool_path_csv.h>

#include <ddfcam/error.h>

#include "../common/file_access.h"
#include "path_file_limits.h"
#include "tool_path_csv_columns.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <system_error>

namespace ddfcam::io {
namespace {

using detail::CsvColumn;

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{1} << 30;
constexpr std::size_t kMaxComments = 10000;

enum class Delimiter { Comma, Semicolon, Blanks };

bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
  return s;
}

Delimiter detectDelimiter(std::string_view line) {
  if (line.find(';') != std::string_view::npos) return Delimiter::Semicolon;
  if (line.find(',') != std::string_view::npos) return Delimiter::Comma;
  return Delimiter::Blanks;
}

void split(std::string_view line, Delimiter d, std::vector<std::string_view>& fields) {
  fields.clear();
  if (d == Delimiter::Blanks) {
    std::size_t at = 0;
    while (at < line.size()) {
      while (at < line.size() && isBlank(line[at])) ++at;
      std::size_t end = at;
      while (end < line.size() && !isBlank(line[end])) ++end;
      if (end > at) fields.push_back(line.substr(at, end - at));
      at = end;
    }
    return;
  }
  const char c = d == Delimiter::Comma ? ',' : ';';
  std::size_t at = 0;
  for (std::size_t next; (next = line.find(c, at)) != std::string_view::npos; at = next + 1)
    fields.push_back(trimmed(line.substr(at, next - at)));
  fields.push_back(trimmed(line.substr(at)));
}

std::string_view unquoted(std::string_view f) {
  if (f.size() >= 2 && f.front() == '"' && f.back() == '"')
    return trimmed(f.substr(1, f.size() - 2));
  return f;
}

/// The number in @p field, std::nullopt if it is not exactly one (non-finite values included).
std::optional<double> number(std::string_view field) {
  field = unquoted(field);
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || error != std::errc() || end != field.data() + field.size())
    return std::nullopt;
  return value;
}

/// Parses the data lines of one file against its layout; failures name the line.
class RowReader {
 public:
  RowReader(const std::string& source, detail::CsvLayout layout, Delimiter delimiter,
            const CsvReadParams& params, planning::ClProgram& program)
      : source_(source), layout_(std::move(layout)), delimiter_(delimiter), program_(program) {
    const LengthUnit unit = layout_.unit.value_or(params.unitIfUnstated);
    positionScale_ = millimetresPer(unit);
    feedScale_ = millimetresPer(layout_.feedUnit.value_or(unit));
    program_.sourceUnit = unit;
    program_.pointKind = layout_.kind.value_or(params.kindIfUnstated);
    maxRows_ = params.maxRows;
    const auto has = [&](CsvColumn c) {
      return std::find(layout_.columns.begin(), layout_.columns.end(), c) != layout_.columns.end();
    };
    hasAxis_ = has(CsvColumn::I);
    hasNormal_ = has(CsvColumn::Nx);
  }

  void read(std::string_view line, int lineNumber) {
    line_ = lineNumber;
    split(line, delimiter_, fields_);
    if (fields_.size() != layout_.columns.size())
      fail(std::to_string(fields_.size()) + " fields, expected " +
           std::to_string(layout_.columns.size()));
    if (program_.points.size() >= maxRows_)
      throw IoError(source_ + ": line " + std::to_string(line_) + ": more than " +
                    std::to_string(maxRows_) + " rows; files this large are refused");
    planning::ClPoint point;
    point.sourceLine = lineNumber;
    values_.fill(0.0);
    present_.fill(false);
    path_.reset();
    pointIndex_.reset();
    for (std::size_t c = 0; c < fields_.size(); ++c) readField(c, point);
    point.positionMm = positionScale_ * ddf::Vec3(values_[0], values_[1], values_[2]);
    if (const auto problem = detail::positionProblem(point.positionMm)) fail(*problem);
    // An axis left blank keeps the one in force, as APT's 3-value GOTO does after a 6-value
    // one: a blank is no claim that the tool stands vertical.
    if (hasAxis_) point.axis = vector(3, "axis");
    if (point.axis) lastAxis_ = point.axis;
    if (hasAxis_ && !point.axis) point.axis = lastAxis_;
    if (hasNormal_) point.normal = vector(6, "normal");
    point.path = pathIndex(path_.value_or(0));
    int& count = pointCounts_[static_cast<std::size_t>(point.path)];
    point.point = pointIndex_ ? static_cast<int>(*pointIndex_) : count;
    ++count;
    program_.points.push_back(point);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw IoError(source_ + ": line " + std::to_string(line_) + ": " + what);
  }

  std::string fieldName(std::size_t c) const {
    return "field " + std::to_string(c + 1) + " ('" + std::string(fields_[c].substr(0, 40)) + "')";
  }

  double real(std::size_t c) const {
    const auto value = number(fields_[c]);
    if (!value) {
      const bool comma =
          delimiter_ != Delimiter::Comma && fields_[c].find(',') != std::string_view::npos;
      fail(fieldName(c) + " is not a number" + (comma ? " (decimal comma? use '.')" : ""));
    }
    if (!std::isfinite(*value)) fail(fieldName(c) + " is not finite");
    return *value;
  }

  long long integer(std::size_t c) const {
    const double value = real(c);
    if (value < 0 || value > std::numeric_limits<int>::max() || value != std::floor(value))
      fail(fieldName(c) + " is not a non-negative integer index");
    return static_cast<long long>(value);
  }

  /// Field @p c as a feed in mm/min, checked after the unit conversion.
  double feed(std::size_t c) const {
    const double mmPerMin = real(c) * feedScale_;
    if (const auto problem = detail::feedProblem(mmPerMin)) fail(fieldName(c) + ": " + *problem);
    return mmPerMin;
  }

  planning::MoveKind move(std::size_t c) const {
    std::string word(unquoted(fields_[c]));
    for (char& ch : word)
      if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
    if (word.empty() || word == "cut") return planning::MoveKind::Cut;
    if (word == "link") return planning::MoveKind::Link;
    if (word == "rapid") return planning::MoveKind::Rapid;
    fail(fieldName(c) + " is not a move word (cut, link or rapid)");
  }

  void readField(std::size_t c, planning::ClPoint& point) {
    const CsvColumn column = layout_.columns[c];
    const bool empty = unquoted(fields_[c]).empty();
    switch (column) {
      case CsvColumn::Ignore:
        return;
      case CsvColumn::Path:
        path_ = integer(c);
        return;
      case CsvColumn::Point:
        pointIndex_ = integer(c);
        return;
      case CsvColumn::Feed:
        point.feedMmPerMin = empty ? 0.0 : feed(c);
        return;
      case CsvColumn::Move:
        point.move = move(c);
        return;
      default: {
        // X..Nz are consecutive: slots 0-2 position, 3-5 axis, 6-8 normal.
        const auto slot =
            static_cast<std::size_t>(static_cast<int>(column) - static_cast<int>(CsvColumn::X));
        present_[slot] = !empty;
        if (!empty || slot < 3) values_[slot] = real(c);
      }
    }
  }

  /// The axis or normal (slots @p slot..+2): empty when its fields are all empty, else unit.
  std::optional<ddf::Vec3> vector(std::size_t slot, const char* what) const {
    const int given = int{present_[slot]} + int{present_[slot + 1]} + int{present_[slot + 2]};
    if (given == 0) return std::nullopt;
    if (given < 3)
      fail(std::string("the ") + what + " has " + std::to_string(given) + " of 3 values");
    const ddf::Vec3 v(values_[slot], values_[slot + 1], values_[slot + 2]);
    const auto unit = detail::unitDirection(v, 1e-12);
    if (!unit) fail(std::string("the ") + what + " vector is zero");
    return *unit;
  }

  /// 0-based consecutive index of path number @p value, in order of first appearance.
  int pathIndex(long long value) {
    if (!lastPath_ || lastPath_->first != value) {
      const auto [it, inserted] = paths_.try_emplace(value, static_cast<int>(paths_.size()));
      if (inserted) pointCounts_.push_back(0);
      lastPath_ = *it;
    }
    return lastPath_->second;
  }

  const std::string& source_;
  detail::CsvLayout layout_;
  Delimiter delimiter_;
  planning::ClProgram& program_;
  double positionScale_ = 1.0;
  double feedScale_ = 1.0;
  std::size_t maxRows_ = kMaxCsvRows;
  bool hasAxis_ = false;
  bool hasNormal_ = false;
  int line_ = 0;
  std::vector<std::string_view> fields_;
  std::array<double, 9> values_{};
  std::array<bool, 9> present_{};
  std::optional<long long> path_, pointIndex_;
  std::map<long long, int> paths_;
  std::optional<std::pair<long long, int>> lastPath_;
  std::optional<ddf::Vec3> lastAxis_;  // the last axis given, carried over blank axis cells
  std::vector<int> pointCounts_;
};

[[noreturn]] void failAt(const std::string& source, int line, const std::string& what) {
  throw IoError(source + ": line " + std::to_string(line) + ": " + what);
}

/// The next line of @p text (without "\n" and a trailing "\r"); advances @p text.
std::string_view nextLine(std::string_view& text) {
  const std::size_t end = text.find('\n');
  std::string_view line = text.substr(0, end);
  text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

void checkText(std::string_view line, const std::string& source, int lineNumber) {
  for (const char c : line) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && !isBlank(c)) || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", u);
      failAt(source, lineNumber,
             std::string("control character ") + hex + ": binary data, not a CSV text");
    }
  }
}

/// The reader of the file whose first significant line is @p line (header or first row).
/// @return the reader and whether @p line was a header.
std::pair<std::unique_ptr<RowReader>, bool> startReading(std::string_view line, int lineNumber,
                                                         const std::string& source,
                                                         const CsvReadParams& params,
                                                         planning::ClProgram& program) {
  const Delimiter delimiter = detectDelimiter(line);
  std::vector<std::string_view> fields;
  split(line, delimiter, fields);
  const bool header = std::none_of(fields.begin(), fields.end(),
                                   [](std::string_view f) { return number(f).has_value(); });
  if (header) {
    detail::CsvLayoutResult result = detail::layoutFromHeader(fields);
    if (!result.layout) failAt(source, lineNumber, "header: " + result.error);
    for (const std::string& name : result.layout->ignoredColumns)
      program.warnings.push_back({lineNumber, "column '" + name + "' not understood, ignored"});
    return {
        std::make_unique<RowReader>(source, std::move(*result.layout), delimiter, params, program),
        true};
  }
  std::optional<detail::CsvLayout> layout = detail::layoutFromFieldCount(fields.size());
  if (!layout)
    failAt(source, lineNumber,
           std::to_string(fields.size()) + " fields and no header; expected " +
               detail::headerlessLayouts());
  return {std::make_unique<RowReader>(source, std::move(*layout), delimiter, params, program),
          false};
}

}  // namespace

planning::ClProgram decodeToolPathCsv(std::string_view text, const std::string& sourceName,
                                      const CsvReadParams& params) {
  if (text.size() > kMaxFileBytes)
    throw IoError(sourceName + ": " + std::to_string(text.size()) +
                  " bytes; tool-path CSVs larger than 1 GiB are refused");
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  planning::ClProgram program;
  program.partName = std::filesystem::path(sourceName).stem().string();
  std::unique_ptr<RowReader> reader;
  for (int lineNumber = 1; !text.empty(); ++lineNumber) {
    const std::string_view raw = nextLine(text);
    checkText(raw, sourceName, lineNumber);
    std::string_view line = trimmed(raw);
    if (line.empty()) continue;
    if (line.front() == '#') {
      if (program.comments.size() < kMaxComments)
        program.comments.emplace_back(trimmed(line.substr(1)));
      continue;
    }
    line = trimmed(line.substr(0, line.find('#')));
    if (!reader) {
      auto [started, header] = startReading(line, lineNumber, sourceName, params, program);
      reader = std::move(started);
      if (header) continue;
    }
    reader->read(line, lineNumber);
  }
  if (!reader) throw IoError(sourceName + ": no header and no data row: not a tool-path CSV");
  if (program.points.empty()) throw IoError(sourceName + ": a header but no data row: no points");
  return program;
}

planning::ClProgram readToolPathCsv(const std::filesystem::path& file,
                                    const CsvReadParams& params) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (!error && size > kMaxFileBytes)
    throw IoError(file.string() + ": " + std::to_string(size) +
                  " bytes; tool-path CSVs larger than 1 GiB are refused");
  return decodeToolPathCsv(detail::readFileBytes(file), file.string(), params);
}

}  // namespace ddfcam::io
