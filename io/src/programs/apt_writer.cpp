// SPDX-License-Identifier: MIT
// ddfcam: APT/CLDATA source output (PARTNO ... GOTO ... FINI) for NC post-processors.
#include <ddfcam/io/programs/apt_writer.h>

#include "../common/file_access.h"

#include <ddfcam/error.h>

#include <array>
#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

namespace ddfcam::io {
namespace {

using planning::MoveKind;

/// Values are written in fixed notation; this bound keeps every number (and so every record
/// piece) short enough for the column limit.
constexpr double kLargest = 1e9;

/// Fixed notation with a '.' whatever the locale; "-0.0000" is written as "0.0000" so that
/// tiny negative values do not carry a meaningless sign.
std::string fixed(double value, int decimals) {
  std::array<char, 400> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::fixed, decimals);
  std::string text(buffer.data(), result.ptr);
  if (!text.empty() && text[0] == '-' && text.find_first_not_of("-0.") == std::string::npos) {
    text.erase(0, 1);
  }
  return text;
}

/// Collects the output lines and breaks records longer than the column limit after a comma,
/// ending the broken line in '$' (APT continuation).
class AptLines {
 public:
  explicit AptLines(int maxColumns) : max_(static_cast<std::size_t>(maxColumns)) {}

  void record(std::string_view head, const std::vector<std::string>& values) {
    std::string line(head);
    bool hasPiece = false;
    for (std::size_t k = 0; k < values.size(); ++k) {
      const bool last = k + 1 == values.size();
      const std::string piece = values[k] + (last ? "" : ",");
      // The continued line must leave room for its '$'; the last piece needs none.
      const std::size_t room = last ? max_ : max_ - 1;
      if (line.size() + piece.size() > room && hasPiece) {
        out_ += line + "$\n";
        line.clear();
      }
      line += piece;
      hasPiece = true;
    }
    out_ += line + "\n";
  }

  void plain(std::string_view text) {
    out_ += text;
    out_ += '\n';
  }

  void comment(std::string_view text) {
    // Split at line ends and at the column limit so every line stays a "$$" line.
    const std::size_t width = max_ - 3;
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t end = std::min(text.find('\n', start), text.size());
      std::string_view part = text.substr(start, end - start);
      if (!part.empty() && part.back() == '\r') part.remove_suffix(1);
      do {
        plain("$$ " + std::string(part.substr(0, width)));
        part.remove_prefix(std::min(width, part.size()));
      } while (!part.empty());
      start = end + 1;
    }
  }

  std::string take() { return std::move(out_); }

 private:
  std::size_t max_;
  std::string out_;
};

void checkParams(const planning::ClProgram& program, const AptWriteParams& params) {
  if (program.pointKind == planning::ClPointKind::Contact) {
    throw InvalidInput("APT output needs tool reference points (APT CL points); program '" +
                       program.partName + "' holds contact points");
  }
  if (params.coordinateDecimals < 4 || params.coordinateDecimals > 6) {
    throw InvalidInput("APT coordinate decimals must be 4..6, got " +
                       std::to_string(params.coordinateDecimals));
  }
  if (params.vectorDecimals < 6 || params.vectorDecimals > 9) {
    throw InvalidInput("APT vector decimals must be 6..9, got " +
                       std::to_string(params.vectorDecimals));
  }
  if (params.maxColumns < 32 || params.maxColumns > 200) {
    throw InvalidInput("APT column limit must be 32..200, got " +
                       std::to_string(params.maxColumns));
  }
  if (params.unit == LengthUnit::Metre) {
    throw InvalidInput("APT output is written in mm or inch, not in metres");
  }
  if (!std::isfinite(program.spindleRpm) || program.spindleRpm < 0.0 ||
      program.spindleRpm >= kLargest) {
    throw InvalidInput("APT output: spindle speed must be finite, >= 0 and < 1e9 rpm");
  }
}

void checkPoint(const planning::ClPoint& p, std::size_t index, double per) {
  const std::string where = "APT output: point " + std::to_string(index);
  if (!p.positionMm.allFinite() || p.positionMm.cwiseAbs().maxCoeff() / per >= kLargest) {
    throw InvalidInput(where + " has a non-finite position or one beyond 1e9 file units");
  }
  if (!std::isfinite(p.feedMmPerMin) || p.feedMmPerMin < 0.0 || p.feedMmPerMin / per >= kLargest) {
    throw InvalidInput(where + " has a non-finite, negative or too large feed");
  }
  if (p.axis && (!p.axis->allFinite() || std::abs(p.axis->norm() - 1.0) > 1e-6)) {
    throw InvalidInput(where + " has a non-unit or non-finite tool axis");
  }
}

/// PARTNO text ends the record at the line end; '$' would start a comment or continuation.
std::string partText(const std::string& name, int maxColumns) {
  std::string text = name.empty() ? std::string("DDFCAM") : name;
  for (char& c : text) {
    if (c == '$' || c == '\n' || c == '\r' || static_cast<unsigned char>(c) < 0x20) c = '_';
  }
  return "PARTNO " + text.substr(0, static_cast<std::size_t>(maxColumns) - 7);
}

/// CUTTER (when known) and LOADTL of one tool.
void writeTool(const std::optional<planning::ClCutter>& cutter, int toolNumber,
               const AptWriteParams& params, AptLines& lines) {
  const double per = millimetresPer(params.unit);
  const int cd = params.coordinateDecimals;
  if (cutter) {
    const planning::ClCutter& c = *cutter;
    const std::array<double, 7> values{
        c.diameterMm / per, c.cornerRadiusMm / per, c.eMm / per, c.fMm / per, c.alphaDeg,
        c.betaDeg,          c.heightMm / per};
    std::vector<std::string> texts;
    for (const double v : values) {
      if (!std::isfinite(v) || std::abs(v) >= kLargest) {
        throw InvalidInput("APT output: non-finite or too large CUTTER value");
      }
      texts.push_back(fixed(v, cd));
    }
    lines.record("CUTTER/", texts);
  }
  lines.plain("LOADTL/" + std::to_string(toolNumber));
}

void writeHeader(const planning::ClProgram& program, const AptWriteParams& params,
                 AptLines& lines) {
  const int cd = params.coordinateDecimals;
  lines.plain(partText(program.partName, params.maxColumns));
  lines.plain(params.unit == LengthUnit::Inch ? "UNITS/INCHES" : "UNITS/MM");
  for (const std::string& c : program.comments) lines.comment(c);
  writeTool(program.cutter, program.toolNumber, params, lines);
  if (program.spindleRpm > 0.0) {
    lines.record("SPINDL/",
                 {fixed(program.spindleRpm, cd), program.spindleClockwise ? "CLW" : "CCLW"});
  }
  if (program.coolant) lines.plain("COOLNT/ON");
  if (program.multiAxis()) lines.plain("MULTAX/ON");
}

void writeMotion(const planning::ClProgram& program, const AptWriteParams& params,
                 AptLines& lines) {
  const double per = millimetresPer(params.unit);
  const int cd = params.coordinateDecimals;
  const std::string feedWord = params.unit == LengthUnit::Inch ? "IPM" : "MMPM";
  std::string lastFeed;
  std::vector<std::string> lastGoto;
  auto change = program.toolChanges.begin();
  for (std::size_t k = 0; k < program.points.size(); ++k) {
    const planning::ClPoint& p = program.points[k];
    checkPoint(p, k, per);
    bool toolChanged = false;
    for (; change != program.toolChanges.end() && change->firstPoint <= k; ++change) {
      if (change->firstPoint == k) writeTool(change->cutter, change->toolNumber, params, lines);
      toolChanged |= change->firstPoint == k;
    }
    if (p.move == MoveKind::Rapid) {
      lines.plain("RAPID");
    } else if (p.feedMmPerMin > 0.0) {
      const std::string feed = fixed(p.feedMmPerMin / per, cd);
      if (feed != lastFeed) {
        lines.record("FEDRAT/", params.feedUnitFirst ? std::vector<std::string>{feedWord, feed}
                                                     : std::vector<std::string>{feed, feedWord});
        lastFeed = feed;
      }
    }
    std::vector<std::string> values;
    for (int a = 0; a < 3; ++a) values.push_back(fixed(p.positionMm[a] / per, cd));
    if (p.axis) {
      for (int a = 0; a < 3; ++a) values.push_back(fixed((*p.axis)[a], params.vectorDecimals));
    }
    // A move to where the tool already is (the first cut point of a pass repeats the end of
    // its approach) would be a GOTO repeated as written: a post-processor gains nothing from it.
    if (values == lastGoto && p.move != MoveKind::Rapid && !toolChanged) continue;
    lines.record("GOTO/", values);
    lastGoto = std::move(values);
  }
}

}  // namespace

std::string encodeApt(const planning::ClProgram& program, const AptWriteParams& params) {
  checkParams(program, params);
  AptLines lines(params.maxColumns);
  writeHeader(program, params, lines);
  writeMotion(program, params, lines);
  if (program.coolant) lines.plain("COOLNT/OFF");
  if (program.spindleRpm > 0.0) lines.plain("SPINDL/OFF");
  lines.plain("END");
  lines.plain("FINI");
  return lines.take();
}

void writeApt(const planning::ClProgram& program, const std::filesystem::path& path,
              const AptWriteParams& params) {
  const std::string text = encodeApt(program, params);
  detail::writeFileAtomically(path, text);
}

}  // namespace ddfcam::io
