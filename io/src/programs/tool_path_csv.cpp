// SPDX-License-Identifier: MIT
// ddfcam: writing cutter-location programs as CSV, locale-free, one file or one per program.
#include <ddfcam/io/programs/tool_path_csv.h>

#include <ddfcam/error.h>

#include "../common/file_access.h"

#include <array>
#include <charconv>
#include <cmath>
#include <set>
#include <system_error>

namespace ddfcam::io {
namespace {

constexpr int kMaxDecimals = 17;

const char* moveName(planning::MoveKind kind) {
  switch (kind) {
    case planning::MoveKind::Link:
      return "link";
    case planning::MoveKind::Rapid:
      return "rapid";
    case planning::MoveKind::Cut:
      break;
  }
  return "cut";
}

/// Appends a finite @p value in fixed notation; @p what names it in the error.
void appendReal(std::string& out, double value, int decimals, const std::string& what) {
  if (!std::isfinite(value)) throw InvalidInput("tool path CSV: " + what + " is not finite");
  std::array<char, 400> buffer;  // fixed notation of 1e308 with 17 decimals fits
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                          std::chars_format::fixed, decimals);
  if (error != std::errc()) throw InvalidInput("tool path CSV: " + what + " does not fit");
  out.append(buffer.data(), end);
}

void appendVec(std::string& out, const std::optional<ddf::Vec3>& v, double scale, int decimals,
               const std::string& what) {
  for (int i = 0; i < 3; ++i) {
    out += ',';
    if (v) appendReal(out, (*v)[i] * scale, decimals, what);
  }
}

std::string pointName(const planning::ClPoint& p, std::size_t index) {
  return "point " + std::to_string(index) + " (path " + std::to_string(p.path) + " point " +
         std::to_string(p.point) + ")";
}

void appendRow(std::string& out, const planning::ClPoint& p, std::size_t index, double perMm,
               int decimals) {
  out += std::to_string(p.path);
  out += ',';
  out += std::to_string(p.point);
  const std::string name = pointName(p, index);
  appendVec(out, p.positionMm, perMm, decimals, name + " position");
  appendVec(out, p.axis, 1.0, decimals, name + " axis");
  appendVec(out, p.normal, 1.0, decimals, name + " normal");
  out += ',';
  appendReal(out, p.feedMmPerMin * perMm, decimals, name + " feed");
  out += ',';
  out += moveName(p.move);
  out += '\n';
}

std::string sanitised(const std::string& name) {
  std::string out;
  for (const char c : name) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_';
    const char w = keep ? c : '_';
    if (w == '_' && (out.empty() || out.back() == '_')) continue;
    out += w;
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out.empty() ? "program" : out;
}

}  // namespace

std::string toolPathCsvHeader(planning::ClPointKind kind, LengthUnit unit) {
  const std::string p = kind == planning::ClPointKind::Contact ? "contact" : "tool";
  const std::string u(unitSymbol(unit));
  return "path,point," + p + "_x_" + u + "," + p + "_y_" + u + "," + p + "_z_" + u +
         ",axis_i,axis_j,axis_k,normal_x,normal_y,normal_z,feed_" + u + "_per_min,move";
}

std::string encodeToolPathCsv(const planning::ClProgram& program, const CsvWriteParams& params) {
  if (params.decimals < 0 || params.decimals > kMaxDecimals)
    throw InvalidInput("tool path CSV: " + std::to_string(params.decimals) +
                       " decimals, expected 0.." + std::to_string(kMaxDecimals));
  const double perMm = 1.0 / millimetresPer(params.unit);
  std::string out = toolPathCsvHeader(program.pointKind, params.unit) + "\n";
  out.reserve(out.size() + program.points.size() * (40 + 10 * (params.decimals + 4)));
  for (std::size_t i = 0; i < program.points.size(); ++i)
    appendRow(out, program.points[i], i, perMm, params.decimals);
  return out;
}

void writeToolPathCsv(const planning::ClProgram& program, const std::filesystem::path& file,
                      const CsvWriteParams& params) {
  detail::writeFileAtomically(file, encodeToolPathCsv(program, params));
}

std::filesystem::path toolPathCsvFileFor(const std::filesystem::path& base,
                                         const std::string& name) {
  const std::string extension = base.has_extension() ? base.extension().string() : ".csv";
  return base.parent_path() / (base.stem().string() + "_" + sanitised(name) + extension);
}

std::vector<std::filesystem::path> writeToolPathCsvFiles(
    const std::vector<planning::NamedProgram>& programs, const std::filesystem::path& base,
    const CsvWriteParams& params) {
  if (programs.empty())
    throw InvalidInput("tool path CSV: no program to write to " + base.string());
  std::vector<std::filesystem::path> files;
  if (programs.size() == 1) {
    files.push_back(base);
  } else {
    std::set<std::filesystem::path> used;
    for (const planning::NamedProgram& named : programs) {
      std::filesystem::path file = toolPathCsvFileFor(base, named.name);
      for (int n = 2; used.count(file) > 0; ++n)
        file = toolPathCsvFileFor(base, named.name + "_" + std::to_string(n));
      used.insert(file);
      files.push_back(file);
    }
  }
  // Encode everything first so a bad value leaves no partial set of files behind.
  std::vector<std::string> texts;
  texts.reserve(programs.size());
  for (const planning::NamedProgram& named : programs)
    texts.push_back(encodeToolPathCsv(named.program, params));
  for (std::size_t i = 0; i < programs.size(); ++i) detail::writeFileAtomically(files[i], texts[i]);
  return files;
}

}  // namespace ddfcam::io
