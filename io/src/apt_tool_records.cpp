// SPDX-License-Identifier: MIT
// ddfcam: APT tool and machine records (LOADTL, CUTTER, TLDATA, SPINDL, COOLNT, MSYS).
#include "apt_tool_records.h"

#include <cmath>

namespace ddfcam::io::detail {

void readLoadTool(const AptLexer& lexer, const AptRecord& r, ClProgram& program) {
  const auto values = splitValues(r.rest);
  if (values.empty()) lexer.fail(r.line, "LOADTL without a tool number");
  const double n = aptNumber(lexer, r, values[0]);
  if (n < 0.0 || n > 1e9 || n != std::floor(n)) {
    lexer.fail(r.line, "LOADTL: tool number must be a whole number >= 0");
  }
  program.toolNumber = static_cast<int>(n);
}

void readCutter(const AptLexer& lexer, const AptRecord& r, double per, ClProgram& program) {
  const auto v = aptNumbers(lexer, r, splitValues(r.rest));
  if (v.empty() || v.size() > 7) lexer.fail(r.line, "CUTTER needs 1 to 7 values");
  ClCutter c;
  c.diameterMm = v[0] * per;
  if (v.size() >= 2) c.cornerRadiusMm = v[1] * per;
  c.eMm = v.size() >= 3 ? v[2] * per : c.diameterMm / 2.0 - c.cornerRadiusMm;
  c.fMm = v.size() >= 4 ? v[3] * per : c.cornerRadiusMm;
  if (v.size() >= 5) c.alphaDeg = v[4];
  if (v.size() >= 6) c.betaDeg = v[5];
  if (v.size() >= 7) c.heightMm = v[6] * per;
  program.cutter = c;
}

/// NX: TLDATA/MILL,diameter,corner radius,length,taper angle,tip angle.
void readToolData(const AptLexer& lexer, const AptRecord& r, double per, ClProgram& program) {
  const auto values = splitValues(r.rest);
  if (values.size() < 3 || upperAscii(values[0]) != "MILL") {
    program.comments.push_back(r.text);
    program.warnings.push_back({r.line, "TLDATA other than MILL kept as a comment"});
    return;
  }
  const auto v =
      aptNumbers(lexer, r, std::vector<std::string_view>(values.begin() + 1, values.end()));
  ClCutter c;
  c.diameterMm = v[0] * per;
  c.cornerRadiusMm = v[1] * per;
  c.eMm = c.diameterMm / 2.0 - c.cornerRadiusMm;
  c.fMm = c.cornerRadiusMm;
  if (v.size() >= 3) c.heightMm = v[2] * per;
  if (v.size() >= 4) c.betaDeg = v[3];
  if (v.size() >= 5) c.alphaDeg = v[4];
  program.cutter = c;
}

void readSpindle(const AptLexer& lexer, const AptRecord& r, ClProgram& program) {
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

void readCoolant(const AptRecord& r, ClProgram& program) {
  const auto values = splitValues(r.rest);
  if (values.empty()) return;
  if (upperAscii(values[0]) != "OFF") program.coolant = true;
}

void readMachineSystem(const AptLexer& lexer, const AptRecord& r, ClProgram& program) {
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
