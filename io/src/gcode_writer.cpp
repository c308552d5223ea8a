// SPDX-License-Identifier: MIT
// ddfcam: RS274NGC G-code output of a cutter-location program, 3-axis or 5-axis table-table.
#include "file_access.h"

#include <ddfcam/error.h>
#include <ddfcam/io/cutter_tool.h>
#include <ddfcam/io/gcode_writer.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <string_view>
#include <vector>

namespace ddfcam::io {
namespace {

using Mode = GCodeWriteParams::Mode;

/// Tolerance on |v| - 1 of axes and normals read from files with 6 to 9 decimals.
constexpr double kUnitTolerance = 1e-4;
/// Largest |axis - Z| of a 3-axis point (files write +Z as 0,0,1 to 6+ decimals).
constexpr double kVerticalTolerance = 1e-6;

/// Concatenation of @p parts (avoids GCC 12's -Wrestrict false positive on "lit" + string).
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (std::string_view part : parts) s.append(part);
  return s;
}

/// Fixed-point text of @p v, locale-independent, "-0.000" written as "0.000".
std::string fixed(double v, int decimals) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (res.ec != std::errc()) throw InvalidInput("G-code: number too large to write");
  std::string s(buf, res.ptr);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string vecText(const ddf::Vec3& v) {
  return cat({"(", fixed(v.x(), 6), ", ", fixed(v.y(), 6), ", ", fixed(v.z(), 6), ")"});
}

/// Text naming point @p i of @p program for messages.
std::string pointName(const ClProgram& program, std::size_t i) {
  const ClPoint& p = program.points[i];
  std::string s = "G-code: point " + std::to_string(i) + " (path " + std::to_string(p.path) +
                  ", point " + std::to_string(p.point);
  if (p.sourceLine > 0) s += ", line " + std::to_string(p.sourceLine);
  return s + ")";
}

/// Comment text safe for RS274: no parentheses, printable ASCII, bounded length.
std::string commentText(std::string_view text) {
  std::string s;
  for (char c : text.substr(0, 200)) {
    if (c == '(') c = '[';
    if (c == ')') c = ']';
    if (c < 32 || c > 126) c = '?';
    s += c;
  }
  return s;
}

void validateParams(const GCodeWriteParams& p) {
  if (p.unit == LengthUnit::Metre) {
    throw InvalidInput("G-code: unit must be mm (G21) or inch (G20), not m");
  }
  if (p.decimals < 1 || p.decimals > 8 || p.angleDecimals < 1 || p.angleDecimals > 8) {
    throw InvalidInput("G-code: decimals and angleDecimals must lie in 1..8");
  }
  if (p.lineNumberStep < 1 || p.lineNumberStep > 1000) {
    throw InvalidInput("G-code: lineNumberStep must lie in 1..1000");
  }
  if (!std::isfinite(p.rapidClearanceMm) || p.rapidClearanceMm < 0.0) {
    throw InvalidInput("G-code: rapidClearanceMm must be finite and >= 0");
  }
  if (!std::isfinite(p.spindleRpm) || p.spindleRpm < 0.0) {
    throw InvalidInput("G-code: spindleRpm must be finite and >= 0");
  }
  if (!std::isfinite(p.defaultFeedMmPerMin) || p.defaultFeedMmPerMin <= 0.0) {
    throw InvalidInput("G-code: defaultFeedMmPerMin must be finite and > 0");
  }
  if (p.toolNumber != -1 && p.toolNumber < 1) {
    throw InvalidInput("G-code: toolNumber must be >= 1 (or -1 for the program's)");
  }
  if (p.mode == Mode::FiveAxis) planning::validateKinematics(p.kinematics);
}

/// Ball, corner and rim radii of a cutter: {R, r} with r the corner radius.
std::pair<double, double> cutterRadii(const planning::Tool& tool) {
  planning::validateTool(tool);
  switch (tool.kind) {
    case planning::ToolKind::BallEnd:
      return {tool.radiusMm, tool.radiusMm};
    case planning::ToolKind::FlatEnd:
      return {tool.radiusMm, 0.0};
    case planning::ToolKind::TorusCutter:
      return {tool.radiusMm, tool.edgeRadiusMm};
    default:
      break;
  }
  throw InvalidInput("G-code: tool '" + tool.name + "' is a " +
                     std::string(planning::toolKindName(tool.kind)) +
                     "; G-code needs a cutter (ball_end, flat_end or torus_cutter)");
}

/// Unit version of @p v (a file's axis or normal), or an error naming the point.
ddf::Vec3 unitOf(const ddf::Vec3& v, const std::string& what, const std::string& where) {
  if (!v.allFinite()) throw InvalidInput(where + ": " + what + " is not finite");
  if (std::abs(v.norm() - 1.0) > kUnitTolerance) {
    throw InvalidInput(where + ": " + what + " " + vecText(v) + " is not a unit vector");
  }
  return v.normalized();
}

/// Tool tip of point @p i given its unit tool axis @p axis (part frame, mm).
ddf::Vec3 tipOf(const ClProgram& program, std::size_t i, const ddf::Vec3& axis,
                std::pair<double, double> radii) {
  const ClPoint& p = program.points[i];
  if (program.pointKind == ClPointKind::ToolReference) return p.positionMm;
  const std::string where = pointName(program, i);
  if (!p.normal) throw InvalidInput(where + ": a contact point needs a surface normal");
  const ddf::Vec3 n = unitOf(*p.normal, "normal", where);
  if (n.dot(axis) < -1e-9) {
    throw InvalidInput(where + ": normal " + vecText(n) +
                       " points away from the tool (undercut not reachable)");
  }
  const ddf::Vec3 across = n - n.dot(axis) * axis;
  const double acrossLength = across.norm();
  const ddf::Vec3 h = acrossLength > 1e-12 ? ddf::Vec3(across / acrossLength) : ddf::Vec3::Zero();
  const auto [big, corner] = radii;
  // The corner circle's centre lies at corner n from the contact; the tip is below it.
  return p.positionMm + corner * n + (big - corner) * h - corner * axis;
}

/// Why a tilted axis cannot go into a 3-axis program, and what would take it.
std::string threeAxisAdvice(const ddf::Vec3& axis) {
  const double tiltDeg = std::acos(std::clamp(axis.z(), -1.0, 1.0)) * 180.0 / std::numbers::pi;
  const planning::TableKinematics generic;
  if (tiltDeg <= generic.tiltMaxDeg) {
    return " is tilted by " + fixed(tiltDeg, 3) +
           " deg; a 3-axis program needs +Z: write it for a 5-axis machine (a machine file, or "
           "the generic A/C or B/C table)";
  }
  return " is tilted by " + fixed(tiltDeg, 3) +
         " deg (the tool points up at the part from below); neither a 3-axis machine nor a "
         "table tilting up to 120 deg reaches it: turn the part over (fixture it the other way "
         "up, or transform the program) so that the tool comes from above";
}

/// Unit tool axis of point @p i (part frame): the file's, else the axis in force @p inForce
/// (the last one given: a point without an axis keeps it, as APT's GOTO does), else +Z.
ddf::Vec3 axisOf(const ClProgram& program, std::size_t i, Mode mode,
                 std::optional<ddf::Vec3>& inForce) {
  const ClPoint& p = program.points[i];
  const std::string where = pointName(program, i);
  if (p.axis) inForce = unitOf(*p.axis, "tool axis", where);
  const ddf::Vec3 a = inForce.value_or(ddf::Vec3::UnitZ());
  if (mode == Mode::ThreeAxis && (a - ddf::Vec3::UnitZ()).norm() > kVerticalTolerance) {
    throw InvalidInput(where + ": tool axis " + vecText(a) + threeAxisAdvice(a));
  }
  return a;
}

/// Radii of the tool cutting point @p i: @p tool's, or after a tool change that tool's CUTTER.
/// Only contact programs need them; tool reference programs pass through.
std::pair<double, double> radiiAt(const ClProgram& program, const ClToolChange* change,
                                  const std::pair<double, double>& first) {
  if (!change || program.pointKind == ClPointKind::ToolReference) return first;
  if (!change->cutter) {
    throw InvalidInput("G-code: tool T" + std::to_string(change->toolNumber) +
                       " has no CUTTER record, so the tool tips of the contact points it cuts "
                       "cannot be computed; give every tool a CUTTER");
  }
  return cutterRadii(toolFromCutter(*change->cutter, change->toolName));
}

/// The tool change starting at point @p i, if any (changes in order of firstPoint).
const ClToolChange* changeAt(const ClProgram& program, std::size_t i) {
  for (const ClToolChange& c : program.toolChanges)
    if (c.firstPoint == i) return &c;
  return nullptr;
}

/// Positions of every point as written, in program order (mm, degrees): machine X Y Z from the
/// kinematics, or with tcpPositions the tip in the part frame.
std::vector<planning::MachinePose> machinePoses(const ClProgram& program,
                                                const planning::Tool& tool,
                                                const GCodeWriteParams& params) {
  const std::pair<double, double> firstRadii = cutterRadii(tool);
  std::pair<double, double> radii = firstRadii;
  std::vector<planning::MachinePose> poses;
  poses.reserve(program.points.size());
  planning::MachinePose previous = params.startPose;
  std::optional<ddf::Vec3> inForce;
  for (std::size_t i = 0; i < program.points.size(); ++i) {
    const ClPoint& p = program.points[i];
    if (!p.positionMm.allFinite() || !std::isfinite(p.feedMmPerMin) || p.feedMmPerMin < 0.0) {
      throw InvalidInput(pointName(program, i) + ": position or feed is not finite (or < 0)");
    }
    if (const ClToolChange* change = changeAt(program, i))
      radii = radiiAt(program, change, firstRadii);
    const ddf::Vec3 axis = axisOf(program, i, params.mode, inForce);
    const ddf::Vec3 tip = tipOf(program, i, axis, radii);
    if (params.mode == Mode::ThreeAxis) {
      poses.push_back({tip, 0.0, 0.0});
      continue;
    }
    const planning::InverseKinematicsResult r =
        planning::inverseKinematics(params.kinematics, tip, axis, previous);
    if (!r.pose) throw InvalidInput(pointName(program, i) + ": " + r.reason);
    previous = *r.pose;
    poses.push_back(*r.pose);
    if (params.tcpPositions) poses.back().xyzMm = tip;
  }
  return poses;
}

/// Collects blocks, numbering them when asked.
class Blocks {
 public:
  explicit Blocks(const GCodeWriteParams& p) : params_(p) {}
  void raw(std::string_view text) { (out_ += text) += '\n'; }
  void block(std::string_view text) {
    if (params_.lineNumbers) {
      number_ += params_.lineNumberStep;
      out_ += cat({"N", std::to_string(number_), " "});
    }
    raw(text);
  }
  void comment(std::string_view text) { block(cat({"(", commentText(text), ")"})); }
  std::string take() { return std::move(out_); }

 private:
  const GCodeWriteParams& params_;
  std::string out_;
  long long number_ = 0;
};

/// "X.. Y.. Z.. [A|B.. C..]" of @p pose in the output unit.
std::string axisWords(const planning::MachinePose& pose, const GCodeWriteParams& p) {
  const double scale = 1.0 / millimetresPer(p.unit);
  std::string s = cat({"X", fixed(pose.xyzMm.x() * scale, p.decimals), " Y",
                       fixed(pose.xyzMm.y() * scale, p.decimals), " Z",
                       fixed(pose.xyzMm.z() * scale, p.decimals)});
  if (p.mode == Mode::FiveAxis) {
    s += p.kinematics.pair == planning::RotaryPair::AC ? " A" : " B";
    s += fixed(pose.tiltDeg, p.angleDecimals) + " C" + fixed(pose.rotaryDeg, p.angleDecimals);
  }
  return s;
}

/// T word of a program's tool number: G-code has no tool 0, which becomes T1.
int toolNumberOf(int programTool) {
  return std::max(1, programTool);
}

/// @p text with every "{tool}" replaced by @p number.
std::string withTool(std::string text, int number) {
  for (std::size_t at = text.find("{tool}"); at != std::string::npos; at = text.find("{tool}"))
    text.replace(at, 6, std::to_string(number));
  return text;
}

/// Tool change to @p number: T M6, the length offset and the control's TCP block if any.
void toolBlocks(Blocks& out, int number, const GCodeWriteParams& p) {
  const std::string text = std::to_string(number);
  out.block(std::string("T").append(text).append(" M6"));
  if (p.toolLengthOffset && p.tcpOnBlock.empty()) out.block(std::string("G43 H").append(text));
  if (!p.tcpOnBlock.empty()) out.block(withTool(p.tcpOnBlock, number));
}

/// Spindle on (S M3|M4) and coolant (M8): at the start and again after every tool change,
/// since M6 stops the spindle.
void spindleBlocks(Blocks& out, const ClProgram& program, const GCodeWriteParams& p) {
  const double rpm = p.spindleRpm > 0.0 ? p.spindleRpm
                     : program.spindleRpm > 0.0 && std::isfinite(program.spindleRpm)
                         ? program.spindleRpm
                         : 6000.0;
  out.block(
      std::string("S").append(fixed(rpm, 1)).append(program.spindleClockwise ? " M3" : " M4"));
  if (program.coolant) out.block("M8");
}

void writeHeader(Blocks& out, const ClProgram& program, const planning::Tool& tool,
                 const GCodeWriteParams& p) {
  out.raw("%");
  const bool five = p.mode == Mode::FiveAxis;
  const bool ac = p.kinematics.pair == planning::RotaryPair::AC;
  out.comment(std::string("ddfcam G-code, ") +
              (five ? (ac ? "5-axis table-table A/C" : "5-axis table-table B/C") : "3-axis"));
  if (!program.partName.empty()) out.comment("part: " + program.partName);
  out.comment("tool: " + std::string(planning::toolKindName(tool.kind)) + " R" +
              fixed(tool.radiusMm, 4) + " mm, " + tool.name);
  out.comment("positions: tool tip, " + std::string(lengthUnitName(p.unit)));
  if (five) {
    out.comment("pivot " + vecText(p.kinematics.pivotMm) + " mm, C offset " +
                vecText(p.kinematics.rotaryOffsetMm) + " mm");
  }
  if (!p.machineName.empty()) out.comment("machine: " + p.machineName);
  if (p.tcpPositions) out.comment("X Y Z: tool tip in the part frame (tool centre point control)");
  for (const ClToolChange& c : program.toolChanges) {
    out.comment("tool change at point " + std::to_string(c.firstPoint) + ": T" +
                std::to_string(toolNumberOf(c.toolNumber)) + " " + c.toolName);
  }
  for (const std::string& c : program.comments) out.comment("note: " + c);
  const bool inch = p.unit == LengthUnit::Inch;
  out.block(std::string("G17 ") + (inch ? "G20" : "G21") + " G40 G49 G80 G90 " +
            (p.inverseTimeFeed ? "G93" : "G94"));
  toolBlocks(out, p.toolNumber >= 1 ? p.toolNumber : toolNumberOf(program.toolNumber), p);
  spindleBlocks(out, program, p);
}

/// F value of a G1 move from @p from to @p to at @p feedMmPerMin: per minute in the output
/// unit, or with inverseTimeFeed 1 / minutes of the move (see GCodeWriteParams).
std::string feedValue(double feedMmPerMin, const planning::MachinePose& from,
                      const planning::MachinePose& to, const GCodeWriteParams& p) {
  if (!p.inverseTimeFeed) return fixed(feedMmPerMin / millimetresPer(p.unit), p.decimals);
  const double distance = p.tcpPositions ? (to.xyzMm - from.xyzMm).norm()
                                         : (planning::forwardKinematics(p.kinematics, to).tipMm -
                                            planning::forwardKinematics(p.kinematics, from).tipMm)
                                               .norm();
  const double turn = std::abs(to.tiltDeg - from.tiltDeg) + std::abs(to.rotaryDeg - from.rotaryDeg);
  // A move that goes nowhere gets a nominal 1e-4 minutes; RS274 needs some F > 0.
  const double minutes = distance > 1e-6 ? distance / feedMmPerMin
                         : turn > 1e-9   ? turn / feedMmPerMin
                                         : 1e-4;
  std::string text = fixed(1.0 / minutes, p.decimals);
  // Moves longer than 10^decimals minutes would round to F0, which RS274 refuses.
  if (text.find_first_not_of("0.") == std::string::npos)
    text = fixed(std::pow(10.0, -p.decimals), p.decimals);
  return text;
}

/// Retracts to the safe plane, changes to the tool of @p change and comes down to @p above,
/// the safe plane over its first point, as at the start.
void changeTool(Blocks& out, const ClProgram& program, const ClToolChange& change,
                const planning::MachinePose& above, const GCodeWriteParams& p) {
  if (!p.tcpOffBlock.empty()) out.block(p.tcpOffBlock);
  out.block("G0 Z" + fixed(above.xyzMm.z() / millimetresPer(p.unit), p.decimals));
  out.comment("tool: T" + std::to_string(toolNumberOf(change.toolNumber)) + " " + change.toolName);
  toolBlocks(out, toolNumberOf(change.toolNumber), p);
  spindleBlocks(out, program, p);
  out.block("G0 " + axisWords(above, p));
}

void writeMotion(Blocks& out, const ClProgram& program,
                 const std::vector<planning::MachinePose>& poses, const GCodeWriteParams& p) {
  if (poses.empty()) return;
  double topZ = -std::numeric_limits<double>::infinity();
  for (const planning::MachinePose& pose : poses) topZ = std::max(topZ, pose.xyzMm.z());
  const double safeZ = topZ + p.rapidClearanceMm;
  const double scale = 1.0 / millimetresPer(p.unit);
  out.block("G0 Z" + fixed(safeZ * scale, p.decimals));
  planning::MachinePose above = poses.front();
  above.xyzMm.z() = safeZ;
  out.block("G0 " + axisWords(above, p));
  std::string lastFeed;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const ClPoint& point = program.points[i];
    if (const ClToolChange* change = changeAt(program, i); change && i > 0) {
      above = poses[i];
      above.xyzMm.z() = safeZ;
      changeTool(out, program, *change, above, p);
      lastFeed.clear();
    }
    if (point.move == planning::MoveKind::Rapid) {
      out.block("G0 " + axisWords(poses[i], p));
      continue;
    }
    const double feed = point.feedMmPerMin > 0.0 ? point.feedMmPerMin : p.defaultFeedMmPerMin;
    std::string line = "G1 " + axisWords(poses[i], p);
    const bool fromAbove = i == 0 || (changeAt(program, i) != nullptr);
    const std::string feedText = feedValue(feed, fromAbove ? above : poses[i - 1], poses[i], p);
    if (feedText != lastFeed || p.inverseTimeFeed) line += " F" + feedText;
    lastFeed = feedText;
    out.block(line);
  }
  planning::MachinePose retract = poses.back();
  retract.xyzMm.z() = safeZ;
  out.block("G0 " + axisWords(retract, p));
  if (!p.tcpOffBlock.empty()) out.block(p.tcpOffBlock);
}

}  // namespace

std::string encodeGCode(const ClProgram& program, const planning::Tool& tool,
                        const GCodeWriteParams& params) {
  validateParams(params);
  const std::vector<planning::MachinePose> poses = machinePoses(program, tool, params);
  Blocks out(params);
  writeHeader(out, program, tool, params);
  writeMotion(out, program, poses, params);
  out.block("M5 M9");
  out.block("M30");
  out.raw("%");
  return out.take();
}

void writeGCode(const std::filesystem::path& path, const ClProgram& program,
                const planning::Tool& tool, const GCodeWriteParams& params) {
  detail::writeFileAtomically(path, encodeGCode(program, tool, params));
}

}  // namespace ddfcam::io
