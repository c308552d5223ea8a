// SPDX-License-Identifier: MIT
// ddfcam: the arc of an APT CIRCLE record as chords within a tolerance.
#include "apt_arc.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ddfcam::io::detail {

bool interpolateAptArc(const AptCircle& circle, const ddf::Vec3& startMm, const ddf::Vec3& endMm,
                       double chordToleranceMm, std::size_t maxPoints, std::vector<ddf::Vec3>& out,
                       std::string& problem) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const ddf::Vec3& a = circle.axis;
  const double r = circle.radiusMm;
  const ddf::Vec3 d0 = startMm - circle.centreMm;
  const ddf::Vec3 d1 = endMm - circle.centreMm;
  const double h0 = d0.dot(a);
  const double h1 = d1.dot(a);
  const ddf::Vec3 u0 = d0 - h0 * a;
  const ddf::Vec3 u1 = d1 - h1 * a;
  const double mismatch = std::max(std::abs(u0.norm() - r), std::abs(u1.norm() - r));
  if (!(mismatch <= circle.radiusToleranceMm)) {
    problem = "start or end point is not at the radius " + std::to_string(r) +
              " mm from the axis (off by " + std::to_string(mismatch) + " mm)";
    return false;
  }
  // Clockwise seen from the tip of the axis: a right-hand turn about -axis.
  const ddf::Vec3 e1 = u0.normalized();
  const ddf::Vec3 e2 = (-a).cross(e1);
  double turn = std::atan2(u1.dot(e2), u1.dot(e1));
  if (turn < 0.0) turn += kTwoPi;
  if ((endMm - startMm).norm() <= 1e-9 * std::max(1.0, r)) turn = kTwoPi;
  // The end points may sit off the radius; leave the chords the rest of the tolerance.
  const double tolerance = std::max(chordToleranceMm - mismatch, 0.25 * chordToleranceMm);
  const double step = tolerance >= r
                          ? std::numbers::pi / 2.0
                          : std::min(std::numbers::pi / 2.0, 2.0 * std::acos(1.0 - tolerance / r));
  const double pieces = std::ceil(turn / step);
  if (!(pieces <= kMaxAptArcChords)) {
    problem = "the arc needs more than 1000000 chords at the chord tolerance";
    return false;
  }
  const int n = std::max(1, static_cast<int>(pieces));
  if (static_cast<std::size_t>(n - 1) > maxPoints) {
    problem = "the arc needs " + std::to_string(n - 1) + " points at the chord tolerance, " +
              "more than the " + std::to_string(maxPoints) +
              " left of the cap on the interpolated points of all arcs of a program";
    return false;
  }
  out.reserve(out.size() + static_cast<std::size_t>(n - 1));
  for (int k = 1; k < n; ++k) {
    const double t = static_cast<double>(k) / n;
    const double phi = turn * t;
    out.push_back(circle.centreMm + (h0 + (h1 - h0) * t) * a +
                  r * (std::cos(phi) * e1 + std::sin(phi) * e2));
  }
  return true;
}

}  // namespace ddfcam::io::detail
