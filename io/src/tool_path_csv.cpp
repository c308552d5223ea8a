// SPDX-License-Identifier: MIT
// ddfcam: tool-path CSV rows from poses or linked moves, locale-free writing and strict reading.
#include <ddfcam/io/tool_path_csv.h>

#include <ddfcam/error.h>

#include "file_access.h"

#include <array>
#include <charconv>
#include <cmath>
#include <system_error>

namespace ddfcam::io {
namespace {

constexpr int kColumns = 13;
constexpr int kMaxDecimals = 17;

const char* moveName(planning::MoveKind kind) {
  switch (kind) {
    case planning::MoveKind::Cut:
      return "cut";
    case planning::MoveKind::Link:
      return "link";
    case planning::MoveKind::Rapid:
      return "rapid";
  }
  return "cut";
}

/// Normal from the contact towards the tool reference point (see toolPathCsvRows).
ddf::Vec3 derivedNormal(const planning::PathPose& pose, std::size_t index) {
  const ddf::Vec3 up = pose.pose.translation() - pose.contact;
  const double length = up.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    throw InvalidInput("tool path CSV: pose " + std::to_string(index) +
                       " has its reference point on its contact; its normal is undefined "
                       "(pass the normals explicitly)");
  return up / length;
}

ToolPathCsvRow rowOf(const planning::PathPose& pose, const ddf::Vec3& normal, CsvPointKind kind) {
  ToolPathCsvRow row;
  row.position = kind == CsvPointKind::Contact ? pose.contact : ddf::Vec3(pose.pose.translation());
  row.toolAxis = pose.pose.linear() * ddf::Vec3::UnitX();
  row.normal = normal;
  return row;
}

/// [begin, end) of the pass @p pass of @p path (no passStarts: one pass of all poses).
std::pair<int, int> passRange(const planning::ToolPath& path, int pass) {
  const int poses = static_cast<int>(path.poses.size());
  if (path.passStarts.empty()) return {0, poses};
  const int next =
      pass + 1 < static_cast<int>(path.passStarts.size()) ? path.passStarts[pass + 1] : poses;
  return {path.passStarts[pass], next};
}

int passCount(const planning::ToolPath& path) {
  if (path.passStarts.empty()) return path.poses.empty() ? 0 : 1;
  return static_cast<int>(path.passStarts.size());
}

void appendReal(std::string& out, double value, int decimals) {
  std::array<char, 400> buffer;  // fixed notation of 1e308 with 17 decimals fits
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                          std::chars_format::fixed, decimals);
  if (error != std::errc()) throw InvalidInput("tool path CSV: a value does not fit the buffer");
  out.append(buffer.data(), end);
}

void appendVec(std::string& out, const ddf::Vec3& v, int decimals) {
  for (int i = 0; i < 3; ++i) {
    out += ',';
    appendReal(out, v[i], decimals);
  }
}

}  // namespace

ToolPathCsv toolPathCsvRows(const planning::ToolPath& path, CsvPointKind kind,
                            const std::vector<ddf::Vec3>& normals) {
  if (!normals.empty() && normals.size() != path.poses.size())
    throw InvalidInput("tool path CSV: " + std::to_string(normals.size()) + " normals for " +
                       std::to_string(path.poses.size()) + " poses of path '" + path.name + "'");
  ToolPathCsv table{kind, {}};
  table.rows.reserve(path.poses.size());
  for (int pass = 0; pass < passCount(path); ++pass) {
    const auto [begin, end] = passRange(path, pass);
    for (int p = begin; p < end; ++p) {
      const planning::PathPose& pose = path.poses[p];
      ToolPathCsvRow row = rowOf(pose, normals.empty() ? derivedNormal(pose, p) : normals[p], kind);
      row.path = pass;
      row.point = p - begin;
      row.feedMmPerMin = path.feedMmPerMin;
      table.rows.push_back(row);
    }
  }
  return table;
}

namespace {

/// Appends the rows of Cut move @p move (index @p m) from the poses of its pass.
const planning::PathPose& appendCut(ToolPathCsv& table, const planning::PathMove& move, int m,
                                    const planning::ToolPath& path,
                                    const std::vector<ddf::Vec3>& normals) {
  const std::string item = "tool path CSV: cut move " + std::to_string(m);
  if (move.path < 0 || move.path >= passCount(path))
    throw InvalidInput(item + " refers to pass " + std::to_string(move.path) + " of " +
                       std::to_string(passCount(path)));
  const auto [begin, end] = passRange(path, move.path);
  if (static_cast<int>(move.points.size()) != end - begin)
    throw InvalidInput(item + ": " + std::to_string(move.points.size()) + " points, pass " +
                       std::to_string(move.path) + " has " + std::to_string(end - begin) +
                       " poses");
  const planning::PathPose* last = nullptr;
  for (int i = 0; i < end - begin; ++i) {
    const planning::PathPose& pose = path.poses[move.reversed ? end - 1 - i : begin + i];
    if ((pose.contact - move.points[i]).norm() > 1e-9)
      throw InvalidInput(item + ": point " + std::to_string(i) + " is not the contact of its pose");
    const int index = move.reversed ? end - 1 - i : begin + i;
    ToolPathCsvRow row =
        rowOf(pose, normals.empty() ? derivedNormal(pose, index) : normals[index], table.pointKind);
    row.path = m;
    row.point = i;
    row.feedMmPerMin = path.feedMmPerMin;
    table.rows.push_back(row);
    last = &pose;
  }
  return *last;
}

void appendIdle(ToolPathCsv& table, const planning::PathMove& move, int m,
                const planning::PathPose& from, const ddf::Vec3& normal, double feed) {
  const ddf::Vec3 offset = table.pointKind == CsvPointKind::Contact
                               ? ddf::Vec3::Zero()
                               : ddf::Vec3(from.pose.translation() - from.contact);
  for (std::size_t i = 0; i < move.points.size(); ++i) {
    ToolPathCsvRow row = rowOf(from, normal, table.pointKind);
    row.path = m;
    row.point = static_cast<int>(i);
    row.position = move.points[i] + offset;
    row.feedMmPerMin = move.kind == planning::MoveKind::Rapid ? 0.0 : feed;
    row.move = move.kind;
    table.rows.push_back(row);
  }
}

}  // namespace

ToolPathCsv linkedToolPathCsvRows(const planning::LinkedPaths& linked,
                                  const planning::ToolPath& path, CsvPointKind kind,
                                  const std::vector<ddf::Vec3>& normals) {
  if (!normals.empty() && normals.size() != path.poses.size())
    throw InvalidInput("tool path CSV: " + std::to_string(normals.size()) + " normals for " +
                       std::to_string(path.poses.size()) + " poses");
  ToolPathCsv table{kind, {}};
  const planning::PathPose* last = nullptr;
  for (std::size_t m = 0; m < linked.moves.size(); ++m) {
    const planning::PathMove& move = linked.moves[m];
    if (move.kind == planning::MoveKind::Cut) {
      last = &appendCut(table, move, static_cast<int>(m), path, normals);
    } else {
      if (!last) throw InvalidInput("tool path CSV: move 0 is not a cut");
      const auto index = static_cast<std::size_t>(last - path.poses.data());
      appendIdle(table, move, static_cast<int>(m), *last,
                 normals.empty() ? derivedNormal(*last, index) : normals[index], path.feedMmPerMin);
    }
  }
  return table;
}

std::string toolPathCsvHeader(CsvPointKind kind) {
  const std::string p = kind == CsvPointKind::Contact ? "contact" : "tool";
  return "path,point," + p + "_x_mm," + p + "_y_mm," + p +
         "_z_mm,axis_i,axis_j,axis_k,normal_x,normal_y,normal_z,feed_mm_per_min,move";
}

std::string encodeToolPathCsv(const ToolPathCsv& table, const ToolPathCsvParams& params) {
  if (params.decimals < 0 || params.decimals > kMaxDecimals)
    throw InvalidInput("tool path CSV: " + std::to_string(params.decimals) +
                       " decimals, expected 0.." + std::to_string(kMaxDecimals));
  std::string out = toolPathCsvHeader(table.pointKind) + "\n";
  out.reserve(out.size() + table.rows.size() * (40 + 10 * (params.decimals + 3)));
  for (const ToolPathCsvRow& row : table.rows) {
    out += std::to_string(row.path);
    out += ',';
    out += std::to_string(row.point);
    appendVec(out, row.position, params.decimals);
    appendVec(out, row.toolAxis, params.decimals);
    appendVec(out, row.normal, params.decimals);
    out += ',';
    appendReal(out, row.feedMmPerMin, params.decimals);
    out += ',';
    out += moveName(row.move);
    out += '\n';
  }
  return out;
}

namespace {

/// Parses the fields of one data line; every failure names the line and the column.
class LineParser {
 public:
  LineParser(std::string_view line, std::string context) : context_(std::move(context)) {
    std::size_t at = 0;
    for (std::size_t comma; (comma = line.find(',', at)) != std::string_view::npos; at = comma + 1)
      fields_.push_back(line.substr(at, comma - at));
    fields_.push_back(line.substr(at));
    if (fields_.size() != kColumns)
      fail(std::to_string(fields_.size()) + " fields, expected " + std::to_string(kColumns));
  }

  int integer(int column, const char* name) const {
    const std::string_view f = fields_[column];
    int value = 0;
    const auto [end, error] = std::from_chars(f.data(), f.data() + f.size(), value);
    if (error != std::errc() || end != f.data() + f.size() || value < 0)
      fail("column " + std::to_string(column + 1) + " (" + name + "): '" + std::string(f) +
           "' is not a non-negative integer");
    return value;
  }

  double real(int column, const char* name) const {
    const std::string_view f = fields_[column];
    double value = 0.0;
    const auto [end, error] = std::from_chars(f.data(), f.data() + f.size(), value);
    if (f.empty() || error != std::errc() || end != f.data() + f.size())
      fail("column " + std::to_string(column + 1) + " (" + name + "): '" + std::string(f) +
           "' is not a number");
    return value;
  }

  ddf::Vec3 vec(int column, const char* name) const {
    return {real(column, name), real(column + 1, name), real(column + 2, name)};
  }

  planning::MoveKind move() const {
    const std::string_view f = fields_[12];
    for (const auto kind :
         {planning::MoveKind::Cut, planning::MoveKind::Link, planning::MoveKind::Rapid})
      if (f == moveName(kind)) return kind;
    fail("column 13 (move): '" + std::string(f) + "' is not cut, link or rapid");
  }

  [[noreturn]] void fail(const std::string& what) const { throw IoError(context_ + ": " + what); }

 private:
  std::vector<std::string_view> fields_;
  std::string context_;
};

ToolPathCsvRow parseRow(std::string_view line, std::string context) {
  const LineParser in(line, std::move(context));
  ToolPathCsvRow row;
  row.path = in.integer(0, "path");
  row.point = in.integer(1, "point");
  row.position = in.vec(2, "x y z");
  row.toolAxis = in.vec(5, "axis");
  row.normal = in.vec(8, "normal");
  row.feedMmPerMin = in.real(11, "feed");
  row.move = in.move();
  return row;
}

std::string_view withoutCr(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

}  // namespace

ToolPathCsv decodeToolPathCsv(std::string_view text, const std::string& sourceName) {
  ToolPathCsv table;
  std::size_t lineNumber = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = withoutCr(text.substr(0, end));
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    const std::string context = sourceName + ": line " + std::to_string(++lineNumber);
    if (lineNumber == 1) {
      if (line == toolPathCsvHeader(CsvPointKind::Contact))
        table.pointKind = CsvPointKind::Contact;
      else if (line == toolPathCsvHeader(CsvPointKind::ToolReference))
        table.pointKind = CsvPointKind::ToolReference;
      else
        throw IoError(context + ": not a ddfcam tool-path CSV header (expected '" +
                      toolPathCsvHeader(CsvPointKind::Contact) + "' or its 'tool_' variant)");
      continue;
    }
    if (line.empty() && text.empty()) break;  // the final line end
    table.rows.push_back(parseRow(line, context));
  }
  if (lineNumber == 0) throw IoError(sourceName + ": empty file, not a tool-path CSV");
  return table;
}

void writeToolPathCsv(const ToolPathCsv& table, const std::filesystem::path& file,
                      const ToolPathCsvParams& params) {
  detail::writeFileAtomically(file, encodeToolPathCsv(table, params));
}

ToolPathCsv readToolPathCsv(const std::filesystem::path& file) {
  return decodeToolPathCsv(detail::readFileBytes(file), file.string());
}

}  // namespace ddfcam::io
