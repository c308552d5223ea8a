// SPDX-License-Identifier: MIT
// ddfcam: APT/CLDATA source input as real CAM systems write it (NX CLSF, Pro/CLfile, ...).
#include <ddfcam/io/programs/apt_reader.h>

#include "../common/file_access.h"
#include "apt_arc.h"
#include "apt_lexer.h"
#include "apt_tool_records.h"
#include "path_file_limits.h"

#include <ddfcam/error.h>

#include <cmath>
#include <set>

namespace ddfcam::io {
namespace {

using detail::AptRecord;
using planning::MoveKind;

constexpr std::size_t kMaxPoints = 50'000'000;
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{1} << 30;
/// Largest CIRCLE radius, mm (1 km): far beyond any machine. Bounds the chords of one arc.
constexpr double kMaxArcRadiusMm = 1e6;
/// Most points interpolated for all the CIRCLE records of one program together: a few
/// hundred bytes of CIRCLE records must not expand into gigabytes of points.
constexpr std::size_t kMaxArcPoints = 1'000'000;

/// The length unit named by a UNITS value or a feed word; nullopt for any other word.
std::optional<LengthUnit> unitWord(std::string_view word) {
  const std::string w = detail::upperAscii(word);
  if (w == "MM" || w == "MILLIMETERS" || w == "MILLIMETRES" || w == "MMPM" || w == "MMPR") {
    return LengthUnit::Millimetre;
  }
  if (w == "INCHES" || w == "INCH" || w == "IN" || w == "IPM" || w == "IPR") {
    return LengthUnit::Inch;
  }
  return std::nullopt;
}

/// Unit of the positions before the first UNITS record: that record's unit if there is one,
/// else (NX CLSFs have none) the unit of the first FEDRAT's IPM/MMPM word, else mm.
struct UnitGuess {
  LengthUnit unit = LengthUnit::Millimetre;
  bool fromFeed = false;
};

UnitGuess guessUnit(std::string_view text, const std::string& sourceName) {
  detail::AptLexer lexer(text, sourceName);
  AptRecord record;
  std::optional<LengthUnit> fromFeed;
  while (lexer.next(record, nullptr)) {
    if (record.major == "UNITS" || record.major == "UNIT") {
      const auto values = detail::splitValues(record.rest);
      if (!values.empty()) {
        if (const auto unit = unitWord(values[0])) return {*unit, false};
      }
    } else if (record.major == "FEDRAT" && !fromFeed) {
      for (const std::string_view v : detail::splitValues(record.rest)) {
        if (const auto unit = unitWord(v)) fromFeed = unit;
      }
    } else if (record.major == "FINI") {
      break;
    }
  }
  if (fromFeed) return {*fromFeed, true};
  return {};
}

class AptParser {
 public:
  AptParser(std::string_view text, const std::string& sourceName, const AptReadParams& params)
      : lexer_(text, sourceName), params_(params) {
    const UnitGuess guess = guessUnit(text, sourceName);
    unit_ = guess.unit;
    program_.sourceUnit = guess.unit;
    program_.pointKind = planning::ClPointKind::ToolReference;
    if (guess.fromFeed) {
      program_.warnings.push_back({0, std::string("no UNITS record; positions taken in ") +
                                          (unit_ == LengthUnit::Inch ? "inch" : "mm") +
                                          " from the FEDRAT unit"});
    }
  }

  planning::ClProgram run() {
    AptRecord record;
    std::vector<detail::AptComment> comments;
    while (lexer_.next(record, &comments)) {
      for (auto& c : comments) program_.comments.push_back(std::move(c.text));
      comments.clear();
      if (record.major == "FINI") break;
      dispatch(record);
    }
    for (auto& c : comments) program_.comments.push_back(std::move(c.text));
    if (circle_) fail(circle_->line, "CIRCLE is not followed by a GOTO");
    restoreFirstTool();
    if (program_.points.empty()) {
      throw IoError(lexer_.sourceName() +
                    ": no GOTO or FROM record: the file holds no tool motion (is it the whole "
                    "CL file, or only its header?)");
    }
    return std::move(program_);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const { lexer_.fail(line, what); }

  double number(const AptRecord& r, std::string_view token) const {
    return detail::aptNumber(lexer_, r, token);
  }

  std::vector<double> numbers(const AptRecord& r, const std::vector<std::string_view>& values) {
    return detail::aptNumbers(lexer_, r, values);
  }

  void dispatch(const AptRecord& r) {
    if (circle_ && r.major != "GOTO") fail(circle_->line, "CIRCLE is not followed by a GOTO");
    const std::string& m = r.major;
    if (m == "GOTO" || m == "FROM") return motion(r, m == "FROM");
    if (m == "CIRCLE") return circle(r);
    if (m == "RAPID") {
      rapid_ = true;
      return;
    }
    if (m == "FEDRAT") return feed(r);
    if (m == "UNITS" || m == "UNIT") return units(r);
    if (m == "PARTNO") {
      program_.partName = r.rest;
      return;
    }
    const double per = millimetresPer(unit_);
    if (m == "LOADTL" || m == "CUTTER" || m == "TLDATA" || m == "TOOL PATH") toolLine_ = r.line;
    if (m == "LOADTL") return detail::readLoadTool(lexer_, r, program_);
    if (m == "CUTTER") return detail::readCutter(lexer_, r, per, program_);
    if (m == "TLDATA") return detail::readToolData(lexer_, r, per, program_);
    if (m == "SPINDL") return detail::readSpindle(lexer_, r, program_);
    if (m == "COOLNT") return detail::readCoolant(r, program_);
    if (m == "MSYS") return detail::readMachineSystem(lexer_, r, program_);
    if (m == "MULTAX") return multiAxis(r);
    if (m == "END" || m == "END-OF-PATH") return;
    unknown(r);
  }

  void unknown(const AptRecord& r) {
    program_.comments.push_back(r.text);
    if (r.major == "TOOL PATH") {
      const auto values = detail::splitValues(r.rest);
      if (values.size() >= 3 && detail::upperAscii(values[1]) == "TOOL") {
        program_.toolName = std::string(values[2]);
      }
    }
    if (unknownWords_.insert(r.major).second) {
      program_.warnings.push_back({r.line, "unknown record '" + r.major + "' kept as a comment"});
    }
  }

  ddf::Vec3 vector3(const std::vector<double>& v, std::size_t first) const {
    return {v[first], v[first + 1], v[first + 2]};
  }

  /// Values @p first..+2 of @p v as a position in mm, checked after the unit conversion.
  ddf::Vec3 positionMm(const AptRecord& r, const std::vector<double>& v, std::size_t first) const {
    const ddf::Vec3 p = vector3(v, first) * millimetresPer(unit_);
    if (const auto problem = detail::positionProblem(p)) fail(r.line, r.major + ": " + *problem);
    return p;
  }

  /// Values @p first..+2 of @p v as a unit vector; @p what names it in the error.
  ddf::Vec3 direction(const AptRecord& r, const std::vector<double>& v, std::size_t first,
                      const char* what) const {
    const auto unit = detail::unitDirection(vector3(v, first), 1e-9);
    if (!unit) fail(r.line, r.major + ": zero " + what + " vector");
    return *unit;
  }

  void motion(const AptRecord& r, bool from) {
    const auto v = numbers(r, detail::splitValues(r.rest));
    if (v.size() != 3 && v.size() != 6) {
      fail(r.line,
           r.major + " needs 3 or 6 values (x,y,z[,i,j,k]), got " + std::to_string(v.size()));
    }
    planning::ClPoint p;
    p.positionMm = positionMm(r, v, 0);
    // The tool axis is modal: a 3-value GOTO keeps the axis of the last 6-value one (until
    // MULTAX/OFF), so a tilted tool stays tilted.
    if (v.size() == 6) axis_ = direction(r, v, 3, "tool axis");
    p.axis = axis_;
    p.sourceLine = r.line;
    const bool rapid = from || rapid_;
    rapid_ = false;
    if (circle_) {
      arc(p, rapid);
      circle_.reset();
    }
    add(p, rapid);
  }

  void circle(const AptRecord& r) {
    const auto v = numbers(r, detail::splitValues(r.rest));
    if (v.size() < 7) {
      fail(r.line,
           "CIRCLE needs at least 7 values (xc,yc,zc,i,j,k,r), got " + std::to_string(v.size()));
    }
    if (!havePoint_) fail(r.line, "CIRCLE without a preceding point to start from");
    const double per = millimetresPer(unit_);
    detail::AptCircle c;
    c.centreMm = positionMm(r, v, 0);
    c.axis = direction(r, v, 3, "axis");
    c.radiusMm = v[6] * per;
    if (!(c.radiusMm > 0.0)) fail(r.line, "CIRCLE: radius must be > 0");
    if (!(c.radiusMm <= kMaxArcRadiusMm)) {
      fail(r.line, "CIRCLE: radius " + std::to_string(c.radiusMm) +
                       " mm is beyond 1e6 mm; not a machine arc");
    }
    // Radius check tolerance: 1e-3 of the radius, at least 1e-3 of the file unit, which
    // covers files that round every value to 4 decimals.
    c.radiusToleranceMm = 1e-3 * std::max(v[6], 1.0) * per;
    c.line = r.line;
    circle_ = c;
  }

  void arc(const planning::ClPoint& end, bool rapid) {
    std::vector<ddf::Vec3> points;
    std::string problem;
    if (!detail::interpolateAptArc(*circle_, last_, end.positionMm, params_.chordToleranceMm,
                                   kMaxArcPoints - arcPoints_, points, problem)) {
      fail(circle_->line, "CIRCLE: " + problem);
    }
    arcPoints_ += points.size();
    for (const ddf::Vec3& q : points) {
      planning::ClPoint p = end;
      p.positionMm = q;
      p.sourceLine = circle_->line;
      add(p, rapid);
    }
  }

  /// The tool the records so far describe (LOADTL, CUTTER, TLDATA, TOOL PATH).
  planning::ClToolChange currentTool() const {
    return {program_.points.size(), program_.toolNumber, program_.toolName, program_.cutter,
            toolLine_};
  }

  static bool sameTool(const planning::ClToolChange& a, const planning::ClToolChange& b) {
    return a.toolNumber == b.toolNumber && a.toolName == b.toolName && a.cutter == b.cutter;
  }

  /// A tool record between motions is a tool change: recorded where the next point starts.
  void noteTool() {
    planning::ClToolChange now = currentTool();
    if (!firstTool_) {
      firstTool_ = now;
    } else if (!sameTool(now, lastTool_)) {
      program_.toolChanges.push_back(now);
    }
    lastTool_ = std::move(now);
  }

  /// The program's header fields describe the first tool; later ones are in toolChanges.
  void restoreFirstTool() {
    if (!firstTool_) return;
    program_.toolNumber = firstTool_->toolNumber;
    program_.toolName = firstTool_->toolName;
    program_.cutter = firstTool_->cutter;
  }

  void add(planning::ClPoint p, bool rapid) {
    if (program_.points.size() >= kMaxPoints) {
      fail(p.sourceLine, "more than 50000000 points; the program is too large");
    }
    noteTool();
    if (rapid) {
      p.move = MoveKind::Rapid;
      p.feedMmPerMin = 0.0;
      afterRapid_ = true;
    } else {
      p.move = MoveKind::Cut;
      p.feedMmPerMin = feedMmPerMin_;
      // A path is a run of feed moves; the first feed move after a rapid starts a new one.
      if (afterRapid_ && seenCut_) {
        ++path_;
        pointInPath_ = 0;
      }
      afterRapid_ = false;
      seenCut_ = true;
    }
    p.path = path_;
    p.point = pointInPath_++;
    last_ = p.positionMm;
    havePoint_ = true;
    program_.points.push_back(std::move(p));
  }

  /// MULTAX/OFF ends multi-axis motion: later 3-value GOTOs have the vertical axis again.
  void multiAxis(const AptRecord& r) {
    const auto values = detail::splitValues(r.rest);
    if (!values.empty() && detail::upperAscii(values[0]) == "OFF") axis_.reset();
  }

  void feed(const AptRecord& r) {
    const auto values = detail::splitValues(r.rest);
    std::optional<double> value;
    std::string word;
    for (const std::string_view v : values) {
      if (unitWord(v) || detail::upperAscii(v) == "RAPID") {
        word = detail::upperAscii(v);
      } else if (!value) {
        value = number(r, v);
      } else {
        fail(r.line, "FEDRAT has more than one number");
      }
    }
    if (!value) fail(r.line, "FEDRAT without a feed value");
    if (*value < 0.0) fail(r.line, "FEDRAT: negative feed");
    double perMin = *value * millimetresPer(unit_);
    if (word == "MMPM") perMin = *value;
    if (word == "IPM") perMin = *value * 25.4;
    if (word == "MMPR" || word == "IPR") {
      const double per = word == "IPR" ? 25.4 : 1.0;
      perMin = *value * per * program_.spindleRpm;
      program_.warnings.push_back(
          {r.line, "FEDRAT per revolution converted with the spindle speed (" +
                       std::to_string(program_.spindleRpm) + " rpm)"});
    }
    if (const auto problem = detail::feedProblem(perMin)) fail(r.line, "FEDRAT: " + *problem);
    feedMmPerMin_ = perMin;
  }

  void units(const AptRecord& r) {
    const auto values = detail::splitValues(r.rest);
    if (values.size() != 1) fail(r.line, r.major + " needs one value (MM or INCHES)");
    const auto unit = unitWord(values[0]);
    if (!unit) fail(r.line, r.major + ": unknown unit '" + std::string(values[0]) + "'");
    unit_ = *unit;
  }

  detail::AptLexer lexer_;
  AptReadParams params_;
  planning::ClProgram program_;
  LengthUnit unit_ = LengthUnit::Millimetre;
  double feedMmPerMin_ = 0.0;
  bool rapid_ = false;
  bool afterRapid_ = false;
  bool seenCut_ = false;
  int path_ = 0;
  int pointInPath_ = 0;
  bool havePoint_ = false;
  ddf::Vec3 last_ = ddf::Vec3::Zero();
  std::optional<planning::ClToolChange> firstTool_;  // the tool of the first point
  planning::ClToolChange lastTool_;                  // the tool of the last point
  int toolLine_ = 0;                                 // line of the last tool record
  std::optional<ddf::Vec3> axis_;  // tool axis in force (modal), empty: vertical / 3-axis
  std::optional<detail::AptCircle> circle_;
  std::size_t arcPoints_ = 0;  // points interpolated for CIRCLE records so far
  std::set<std::string> unknownWords_;
};

}  // namespace

planning::ClProgram decodeApt(std::string_view text, const std::string& sourceName,
                              const AptReadParams& params) {
  if (!(params.chordToleranceMm > 0.0) || !std::isfinite(params.chordToleranceMm)) {
    throw InvalidInput("APT reader: chord tolerance must be finite and > 0");
  }
  if (text.size() > kMaxFileBytes) {
    throw IoError(sourceName + ": larger than 1 GiB; refused as an APT file");
  }
  if (const int line = detail::firstBinaryLine(text); line > 0) {
    throw IoError(sourceName + ": line " + std::to_string(line) +
                  ": binary data (control characters), not APT text");
  }
  return AptParser(text, sourceName, params).run();
}

planning::ClProgram readApt(const std::filesystem::path& path, const AptReadParams& params) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxFileBytes) {
    throw IoError(path.string() + ": larger than 1 GiB; refused as an APT file");
  }
  const std::string bytes = detail::readFileBytes(path);
  planning::ClProgram program = decodeApt(bytes, path.string(), params);
  if (program.partName.empty()) program.partName = path.stem().string();
  return program;
}

}  // namespace ddfcam::io
