// SPDX-License-Identifier: MIT
// ddfcam: forward and inverse kinematics of a table-table 5-axis machine (A/C or B/C).
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/machine_kinematics.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>

namespace ddfcam::planning {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

bool finite(const ddf::Vec3& v) {
  return v.allFinite();
}

/// Rotation of the tilting table by @p deg (part side to machine side).
Eigen::Matrix3d tiltRotation(RotaryPair pair, double deg) {
  const ddf::Vec3 axis = pair == RotaryPair::AC ? ddf::Vec3::UnitX() : ddf::Vec3::UnitY();
  return Eigen::AngleAxisd(deg * kDegToRad, axis).toRotationMatrix();
}

Eigen::Matrix3d rotaryRotation(double deg) {
  return Eigen::AngleAxisd(deg * kDegToRad, ddf::Vec3::UnitZ()).toRotationMatrix();
}

std::string describe(const ddf::Vec3& v) {
  std::ostringstream out;
  out.precision(9);
  out << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return out.str();
}

/// @p c shifted by a multiple of 360 to the value nearest @p reference; with limits, the
/// nearest such value inside [lo, hi] (none: nullopt).
std::optional<double> unwrapRotary(double c, double reference, const TableKinematics& k) {
  double best = c + 360.0 * std::round((reference - c) / 360.0);
  if (!k.rotaryLimited) return best;
  if (best >= k.rotaryMinDeg && best <= k.rotaryMaxDeg) return best;
  // The nearest in-range value is the in-range multiple closest to the reference.
  std::optional<double> found;
  const double first = c + 360.0 * std::ceil((k.rotaryMinDeg - c) / 360.0);
  for (double v = first; v <= k.rotaryMaxDeg; v += 360.0) {
    if (!found || std::abs(v - reference) < std::abs(*found - reference)) found = v;
  }
  return found;
}

/// The tilt-table angle and C (within -180..180) that turn @p axis (unit, part frame) onto +Z,
/// first solution (tilt >= 0).
std::array<double, 2> principalAngles(RotaryPair pair, const ddf::Vec3& axis) {
  const double tilt = std::acos(std::clamp(axis.z(), -1.0, 1.0)) * kRadToDeg;
  // AC: axis = (sin A sin C, sin A cos C, cos A); BC: axis = (-sin B cos C, sin B sin C, cos B).
  const double c =
      pair == RotaryPair::AC ? std::atan2(axis.x(), axis.y()) : std::atan2(axis.y(), -axis.x());
  return {tilt, c * kRadToDeg};
}

}  // namespace

void validateKinematics(const TableKinematics& k) {
  if (!finite(k.pivotMm)) throw InvalidInput("machine kinematics: pivotMm is not finite");
  if (!finite(k.rotaryOffsetMm)) {
    throw InvalidInput("machine kinematics: rotaryOffsetMm is not finite");
  }
  if (!(k.tiltMinDeg < k.tiltMaxDeg) || k.tiltMinDeg < -360.0 || k.tiltMaxDeg > 360.0) {
    throw InvalidInput(
        "machine kinematics: tilt limits must satisfy -360 <= tiltMinDeg < "
        "tiltMaxDeg <= 360 (got " +
        std::to_string(k.tiltMinDeg) + ".." + std::to_string(k.tiltMaxDeg) + ")");
  }
  if (k.rotaryLimited && !(k.rotaryMinDeg < k.rotaryMaxDeg && std::isfinite(k.rotaryMinDeg) &&
                           std::isfinite(k.rotaryMaxDeg))) {
    throw InvalidInput("machine kinematics: C limits must satisfy rotaryMinDeg < rotaryMaxDeg");
  }
  if (std::abs(k.tiltDirection) != 1.0 || std::abs(k.rotaryDirection) != 1.0) {
    throw InvalidInput("machine kinematics: tiltDirection and rotaryDirection must be +1 or -1");
  }
  if (!(k.singularToleranceDeg > 0.0 && k.singularToleranceDeg < 1.0)) {
    throw InvalidInput("machine kinematics: singularToleranceDeg must lie in (0, 1)");
  }
}

PartToolPose forwardKinematics(const TableKinematics& k, const MachinePose& pose) {
  if (!finite(pose.xyzMm) || !std::isfinite(pose.tiltDeg) || !std::isfinite(pose.rotaryDeg)) {
    throw InvalidInput("forward kinematics: machine pose is not finite");
  }
  const Eigen::Matrix3d tilt = tiltRotation(k.pair, k.tiltDirection * pose.tiltDeg);
  const Eigen::Matrix3d rotary = rotaryRotation(k.rotaryDirection * pose.rotaryDeg);
  const ddf::Vec3& p = k.pivotMm;
  const ddf::Vec3 q = k.pivotMm + k.rotaryOffsetMm;
  // Invert m = T (Rz (x - Q) + Q - P) + P for the tip, and T Rz a = +Z for the axis.
  const ddf::Vec3 untilted = tilt.transpose() * (pose.xyzMm - p) + p;
  PartToolPose out;
  out.tipMm = rotary.transpose() * (untilted - q) + q;
  out.axis = rotary.transpose() * (tilt.transpose() * ddf::Vec3::UnitZ());
  return out;
}

namespace {

/// Machine X Y Z of the part point @p tip at programmed rotary positions (@p tiltDeg, @p cDeg).
ddf::Vec3 machineXyz(const TableKinematics& k, const ddf::Vec3& tip, double tiltDeg, double cDeg) {
  const ddf::Vec3 q = k.pivotMm + k.rotaryOffsetMm;
  const ddf::Vec3 turned = rotaryRotation(k.rotaryDirection * cDeg) * (tip - q) + q;
  return tiltRotation(k.pair, k.tiltDirection * tiltDeg) * (turned - k.pivotMm) + k.pivotMm;
}

/// 1 when a candidate with programmed tilt @p tiltDeg goes against the preferred solution.
int againstPreference(const TableKinematics& k, double tiltDeg) {
  switch (k.solution) {
    case RotarySolution::PositiveTilt:
      return tiltDeg < 0.0 ? 1 : 0;
    case RotarySolution::NegativeTilt:
      return tiltDeg > 0.0 ? 1 : 0;
    case RotarySolution::Nearest:
      break;
  }
  return 0;
}

/// What would reach an axis that needs the physical tilt @p tiltDeg (>= 0) and is out of reach.
std::string reachAdvice(const TableKinematics& k, double tiltDeg) {
  std::ostringstream out;
  const char* name = k.pair == RotaryPair::AC ? "A" : "B";
  if (tiltDeg > 179.0) {
    out << "the tool points up at the part from below: turn the part over (fixture it the "
           "other way up, or transform the program) so that the tool comes from above";
  } else {
    out << "give a machine whose " << name << " limits include +" << tiltDeg << " or -" << tiltDeg
        << " deg (a machine file, --machine), or fixture the part so that the tool axis "
           "tilts less";
  }
  return out.str();
}

std::string limitsText(const TableKinematics& k) {
  std::ostringstream out;
  out << (k.pair == RotaryPair::AC ? "A" : "B") << " in [" << k.tiltMinDeg << ", " << k.tiltMaxDeg
      << "] deg";
  if (k.rotaryLimited) out << ", C in [" << k.rotaryMinDeg << ", " << k.rotaryMaxDeg << "] deg";
  return out.str();
}

}  // namespace

InverseKinematicsResult inverseKinematics(const TableKinematics& k, const ddf::Vec3& tipMm,
                                          const ddf::Vec3& axis, const MachinePose& previous) {
  validateKinematics(k);
  if (!finite(tipMm) || !finite(axis)) {
    throw InvalidInput("inverse kinematics: tip or axis is not finite");
  }
  if (!std::isfinite(previous.tiltDeg) || !std::isfinite(previous.rotaryDeg)) {
    throw InvalidInput("inverse kinematics: previous rotary positions are not finite");
  }
  if (std::abs(axis.norm() - 1.0) > 1e-6) {
    throw InvalidInput("inverse kinematics: tool axis " + describe(axis) + " is not a unit vector");
  }
  const ddf::Vec3 a = axis.normalized();
  InverseKinematicsResult result;
  const std::array<double, 2> principal = principalAngles(k.pair, a);
  const double sinTilt = std::hypot(a.x(), a.y());
  result.singular = a.z() > 0.0 && sinTilt < std::sin(k.singularToleranceDeg * kDegToRad);
  // Candidates (tilt, C): the two solutions; at the singular pose C is free and kept.
  // Programmed values of the two physical solutions (t, c) and (-t, c + 180).
  const double st = k.tiltDirection, sr = k.rotaryDirection;
  std::array<std::array<double, 2>, 2> candidates{
      {{st * principal[0], sr * principal[1]}, {-st * principal[0], sr * (principal[1] + 180.0)}}};
  if (result.singular) candidates = {{{0.0, previous.rotaryDeg}, {0.0, previous.rotaryDeg}}};
  double bestCost = 0.0;
  int bestRank = 0;
  for (const auto& [tilt, c] : candidates) {
    if (tilt < k.tiltMinDeg || tilt > k.tiltMaxDeg) continue;
    const std::optional<double> unwrapped = unwrapRotary(c, previous.rotaryDeg, k);
    if (!unwrapped) continue;
    const double cost =
        std::abs(tilt - previous.tiltDeg) + std::abs(*unwrapped - previous.rotaryDeg);
    const int rank = againstPreference(k, tilt);
    if (result.pose && (rank > bestRank || (rank == bestRank && cost >= bestCost))) continue;
    bestCost = cost;
    bestRank = rank;
    result.pose = MachinePose{machineXyz(k, tipMm, tilt, *unwrapped), tilt, *unwrapped};
  }
  if (!result.pose) {
    std::ostringstream out;
    out << "tool axis " << describe(a) << " needs " << (k.pair == RotaryPair::AC ? "A" : "B")
        << " = +-" << principal[0] << " deg, outside the machine limits (" << limitsText(k) << "); "
        << reachAdvice(k, principal[0]);
    result.reason = out.str();
  }
  return result;
}

}  // namespace ddfcam::planning
