// SPDX-License-Identifier: MIT
// ddfcam: forward and inverse kinematics of a table-table 5-axis machine (A/C or B/C).
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <optional>
#include <string>

namespace ddfcam::planning {

/// @brief Which rotary axes a table-table machine has: a tilting axis (A about machine X, or B
/// about machine Y) carrying a rotary table C about the table normal.
enum class RotaryPair {
  AC,  ///< tilt A about machine +X, rotary table C
  BC   ///< tilt B about machine +Y, rotary table C
};

/// @brief Which of the two rotary solutions of a tool axis a machine takes.
enum class RotarySolution {
  Nearest,       ///< the one nearest to the previous position (|delta tilt| + |delta C|)
  PositiveTilt,  ///< tilt >= 0 (as the control counts it) when within limits, else the other
  NegativeTilt   ///< tilt <= 0 when within limits, else the other
};

/// @brief A table-table 5-axis machine: the spindle is fixed along machine +Z, the tables turn
/// the part. Convention: a part point p maps to machine coordinates m = T (Rz(c) (p - Q) + Q - P) +
/// P, where T = Rx(t) (AC) or Ry(t) (BC) are right-hand rotations by the physical angles
/// t = tiltDirection * A|B and c = rotaryDirection * C in degrees (A|B and C being the values the
/// control is programmed with), P = pivotMm and Q = pivotMm + rotaryOffsetMm. At A|B = 0, C = 0 the
/// part frame coincides with the machine (work) frame. The tool axis in the part frame is then
/// (sin t sin c, sin t cos c, cos t) for AC and (-sin t cos c, sin t sin c, cos t) for BC: with
/// both directions +1, a tool axis tilted towards part +y is A = +30, C = 0 (or A = -30,
/// C = 180). Haas's UMC B/C trunnion counts both axes the other way (directions -1): there the
/// axis is (sin B cos C, sin B sin C, cos B).
struct TableKinematics {
  RotaryPair pair = RotaryPair::AC;  ///< rotary axes (default AC)
  /// A point of the tilting axis (A: parallel to X; B: parallel to Y), machine frame, mm
  /// (default origin).
  ddf::Vec3 pivotMm = ddf::Vec3::Zero();
  /// Offset of the C axis (direction +Z at tilt 0) from the pivot, at tilt 0, mm; only its x
  /// and y components matter (default zero: the C axis passes through the pivot).
  ddf::Vec3 rotaryOffsetMm = ddf::Vec3::Zero();
  double tiltMinDeg = -120.0;    ///< lower limit of A or B, degrees (default -120)
  double tiltMaxDeg = 120.0;     ///< upper limit of A or B, degrees (default 120)
  bool rotaryLimited = false;    ///< whether C has limits (default false: endless table)
  double rotaryMinDeg = -360.0;  ///< lower limit of C when limited, degrees (default -360)
  double rotaryMaxDeg = 360.0;   ///< upper limit of C when limited, degrees (default 360)
  /// +1: the programmed A|B turns the tilting table right-handed about machine +X|+Y; -1: the
  /// other way (default +1).
  double tiltDirection = 1.0;
  /// +1: the programmed C turns the table right-handed about its normal (+Z at tilt 0); -1: the
  /// other way (default +1).
  double rotaryDirection = 1.0;
  /// Which of the two solutions is taken (default Nearest).
  RotarySolution solution = RotarySolution::Nearest;
  /// Tilt below which the axis counts as +Z (singular pose: C undetermined, the previous C is
  /// kept), degrees (default 1e-7, so the written axis is off by at most ~2e-9 rad).
  double singularToleranceDeg = 1e-7;

  bool operator==(const TableKinematics&) const = default;
};

/// @brief Machine axis positions: linear X, Y, Z of the tool tip in the machine frame (mm) and
/// the rotary axes in degrees (C unwrapped: it may leave -180..180 to avoid spins).
struct MachinePose {
  ddf::Vec3 xyzMm = ddf::Vec3::Zero();  ///< X, Y, Z, mm
  double tiltDeg = 0.0;                 ///< A (pair AC) or B (pair BC), degrees
  double rotaryDeg = 0.0;               ///< C, degrees

  bool operator==(const MachinePose&) const = default;
};

/// @brief Tool tip and unit tool axis (tip towards holder) in the part frame.
struct PartToolPose {
  ddf::Vec3 tipMm = ddf::Vec3::Zero();  ///< tool tip, part frame, mm
  ddf::Vec3 axis = ddf::Vec3::UnitZ();  ///< unit tool axis, part frame
};

/// @brief Result of inverseKinematics(): a pose, or the reason there is none.
struct InverseKinematicsResult {
  std::optional<MachinePose> pose;  ///< the chosen solution; empty when unreachable
  std::string reason;               ///< why there is no solution; empty when pose is set
  bool singular = false;            ///< the axis was +Z within tolerance: C kept from previous
};

/// @brief Checks limits and offsets: finite values, tiltMinDeg < tiltMaxDeg within
/// [-360, 360], rotaryMinDeg < rotaryMaxDeg when limited, singularToleranceDeg in (0, 1),
/// directions +1 or -1.
/// @throws InvalidInput naming the offending field.
void validateKinematics(const TableKinematics& kinematics);

/// @brief Tool tip and axis in the part frame for machine positions @p pose (no limit check).
/// @throws InvalidInput if @p pose is not finite.
PartToolPose forwardKinematics(const TableKinematics& kinematics, const MachinePose& pose);

/// @brief Machine positions putting the tool tip at @p tipMm with axis @p axis (part frame).
/// Of the two solutions (tilt t, C) and (-t, C + 180) within the limits, chooses by
/// kinematics.solution (Nearest: the one nearest to @p previous, |delta tilt| + |delta C|),
/// with C unwrapped by multiples of 360 to the value nearest previous C (within the C limits
/// if limited), so no move spins the table by 360.
/// At the singular pose (axis +Z within singularToleranceDeg) C stays at previous C.
/// @param axis unit tool axis, part frame (|axis| within 1e-6 of 1).
/// @return no pose, with a reason naming the axis and the limits and saying what would reach
/// it, when both solutions lie outside the limits.
/// @throws InvalidInput if the inputs are not finite, the axis is not a unit vector, or the
/// kinematics are invalid (validateKinematics()).
InverseKinematicsResult inverseKinematics(const TableKinematics& kinematics, const ddf::Vec3& tipMm,
                                          const ddf::Vec3& axis, const MachinePose& previous);

}  // namespace ddfcam::planning
