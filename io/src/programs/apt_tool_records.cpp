// SPDX-License-Identifier: MIT
// ddfcam: APT tool and machine records (LOADTL, CUTTER, TLDATA, SPINDL, COOLNT, MSYS).
#include "apt_tool_records.h"

#include "path_file_limits.h"

#include <cmath>

namespace ddfcam::io::detail {
namespace {

/// A cutter length @p value in the file's unit as mm; fails if the conversion overflows.
double toolLengthMm(const AptLexer& lexer, const AptRecord& r, double value, double per) {
  const double mm = value * per;
  if (!(std::abs(mm) <= kMaxCoordinateMm)) {
    lexer.fail(r.line, r.major + ": length " + std::to_string(value) + " is beyond 1e12 mm");
  }
  return mm;
}

}  // namespace

void readLoadTool(const AptLexer& lexer, const AptRecord& r, planning::ClProgram& program) {
  const auto values = splitValues(r.rest);
  if (values.empty()) lexer.fail(r.line, "LOADTL without a tool number");
  const double n = aptNumber(lexer, r, values[0]);
  if (n < 0.0 || n > 1e9 || n != std::floor(n)) {
    lexer.fail(r.line, "LOADTL: tool number must be a whole number >= 0");
  }
  program.toolNumber = static_cast<int>(n);
}

void readCutter(const AptLexer& lexer, const AptRecord& r, double per,
                planning::ClProgram& program) {
  const auto v = aptNumbers(lexer, r, splitValues(r.rest));
  if (v.empty() || v.size() > 7) lexer.fail(r.line, "CUTTER needs 1 to 7 values");
  const auto mm = [&](std::size_t k) { return toolLengthMm(lexer, r, v[k], per); };
  planning::ClCutter c;
  c.diameterMm = mm(0);
  if (v.size() >= 2) c.cornerRadiusMm = mm(1);
  c.eMm = v.size() >= 3 ? mm(2) : c.diameterMm / 2.0 - c.cornerRadiusMm;
  c.fMm = v.size() >= 4 ? mm(3) : c.cornerRadiusMm;
  if (v.size() >= 5) c.alphaDeg = v[4];
  if (v.size() >= 6) c.betaDeg = v[5];
  if (v.size() >= 7) c.heightMm = mm(6);
  program.cutter = c;
}

/// NX: TLDATA/MILL,diameter,corner radius,length,taper angle,tip angle.
void readToolData(const AptLexer& lexer, const AptRecord& r, double per,
                  planning::ClProgram& program) {
  const auto values = splitValues(r.rest);
  if (values.size() < 3 || upperAscii(values[0]) != "MILL") {
    program.comments.push_back(r.text);
    program.warnings.push_back({r.line, "TLDATA other than MILL kept as a comment"});
    return;
  }
  const auto v =
      aptNumbers(lexer, r, std::vector<std::string_view>(values.begin() + 1, values.end()));
  const auto mm = [&](std::size_t k) { return toolLengthMm(lexer, r, v[k], per); };
  planning::ClCutter c;
  c.diameterMm = mm(0);
  c.cornerRadiusMm = mm(1);
  c.eMm = c.diameterMm / 2.0 - c.cornerRadiusMm;
  c.fMm = c.cornerRadiusMm;
  if (v.size() >= 3) c.heightMm = mm(2);
  if (v.size() >= 4) c.betaDeg = v[3];
  if (v.size() >= 5) c.alphaDeg = v[4];
  program.cutter = c;
}

void readSpindle(const AptLexer& lexer, const AptRecord& r, planning::ClProgram& program) {
  for (const std::string_view v : splitValues(r.rest)) {
    const std::string w = upperAscii(v);
    if (w == "CLW") {
      program.spindleClockwise = true;
    } else if (w == "CCLW") {
      program.spindleClockwise = false;
    } else if (w == "RPM" || w == "SFM" || w == "SMM" || w == "OFF" || w == "ON" || w == "MAXRPM") {
      continue;
    } else {
      const double rpm = aptNumber(lexer, r, v);
      if (rpm < 0.0) lexer.fail(r.line, "SPINDL: negative speed");
      if (program.spindleRpm == 0.0) program.spindleRpm = rpm;
    }
  }
}

void readCoolant(const AptRecord& r, planning::ClProgram& program) {
  const auto values = splitValues(r.rest);
  if (values.empty()) return;
  if (upperAscii(values[0]) != "OFF") program.coolant = true;
}

void readMachineSystem(const AptLexer& lexer, const AptRecord& r, planning::ClProgram& program) {
  const auto v = aptNumbers(lexer, r, splitValues(r.rest));
  if (v.size() != 9) lexer.fail(r.line, "MSYS needs 9 values, got " + std::to_string(v.size()));
  static constexpr double kIdentity[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  for (int k = 0; k < 9; ++k) {
    if (std::abs(v[k] - kIdentity[k]) > 1e-9) {
      program.warnings.push_back({r.line,
                                  "MSYS is not the identity; positions are kept in the MSYS frame "
                                  "(not transformed)"});
      return;
    }
  }
}

}  // namespace ddfcam::io::detail
