// SPDX-License-Identifier: MIT
// ddfcam: RS274NGC G-code output of a cutter-location program, 3-axis or 5-axis table-table.
#include "../common/file_access.h"
#include "gcode_poses.h"

#include <ddfcam/error.h>
#include <ddfcam/io/programs/gcode_writer.h>
#include <ddfcam/planning/placement/cutter_tool.h>

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
using detail::cat;
using detail::changeAt;
using detail::commentText;
using detail::fixed;
using detail::vecText;

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
void spindleBlocks(Blocks& out, const planning::ClProgram& program, const GCodeWriteParams& p) {
  const double rpm = p.spindleRpm > 0.0 ? p.spindleRpm
                     : program.spindleRpm > 0.0 && std::isfinite(program.spindleRpm)
                         ? program.spindleRpm
                         : 6000.0;
  out.block(
      std::string("S").append(fixed(rpm, 1)).append(program.spindleClockwise ? " M3" : " M4"));
  if (program.coolant) out.block("M8");
}

void writeHeader(Blocks& out, const planning::ClProgram& program, const planning::Tool& tool,
                 const GCodeWriteParams& p) {
  out.raw("%");
  const bool five = p.mode == Mode::FiveAxis;
  const bool ac = p.kinematics.pair == planning::RotaryPair::AC;
  out.comment(std::string("ddfcam G-code, ") +
              (five ? (ac ? "5-axis table-table A/C" : "5-axis table-table B/C") : "3-axis"));
  if (!program.partName.empty()) out.comment("part: " + program.partName);
  out.comment("tool: " + std::string(planning::toolKindName(tool.kind)) + " R" +
              fixed(tool.radiusMm, 4) + " mm, " + tool.name);
  out.comment("positions: tool tip, " + std::string(unitSymbol(p.unit)));
  if (five) {
    out.comment("pivot " + vecText(p.kinematics.pivotMm) + " mm, C offset " +
                vecText(p.kinematics.rotaryOffsetMm) + " mm");
  }
  if (!p.machineName.empty()) out.comment("machine: " + p.machineName);
  if (p.tcpPositions) out.comment("X Y Z: tool tip in the part frame (tool centre point control)");
  for (const planning::ClToolChange& c : program.toolChanges) {
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
void changeTool(Blocks& out, const planning::ClProgram& program,
                const planning::ClToolChange& change, const planning::MachinePose& above,
                const GCodeWriteParams& p) {
  if (!p.tcpOffBlock.empty()) out.block(p.tcpOffBlock);
  out.block("G0 Z" + fixed(above.xyzMm.z() / millimetresPer(p.unit), p.decimals));
  out.comment("tool: T" + std::to_string(toolNumberOf(change.toolNumber)) + " " + change.toolName);
  toolBlocks(out, toolNumberOf(change.toolNumber), p);
  spindleBlocks(out, program, p);
  out.block("G0 " + axisWords(above, p));
}

void writeMotion(Blocks& out, const planning::ClProgram& program,
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
    const planning::ClPoint& point = program.points[i];
    if (const planning::ClToolChange* change = changeAt(program, i); change && i > 0) {
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

std::string encodeGCode(const planning::ClProgram& program, const planning::Tool& tool,
                        const GCodeWriteParams& params) {
  detail::validateGCodeParams(params);
  const std::vector<planning::MachinePose> poses = detail::machinePoses(program, tool, params);
  Blocks out(params);
  writeHeader(out, program, tool, params);
  writeMotion(out, program, poses, params);
  out.block("M5 M9");
  out.block("M30");
  out.raw("%");
  return out.take();
}

void writeGCode(const std::filesystem::path& path, const planning::ClProgram& program,
                const planning::Tool& tool, const GCodeWriteParams& params) {
  detail::writeFileAtomically(path, encodeGCode(program, tool, params));
}

}  // namespace ddfcam::io
