// SPDX-License-Identifier: MIT
// ddfcam: a curvature tensor stored into and read back from a CurvatureField entry (shared by
// the vertex fits and the transfer from a design mesh).
#pragma once

#include <ddfcam/planning/analysis/curvature.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>

namespace ddfcam::planning::detail {

/// @brief The tensor k_max d_max d_max^T + k_min d_min d_min^T of entry @p at of @p field
/// (1/mm, part frame; zero in the normal direction).
inline Eigen::Matrix3d curvatureTensor(const CurvatureField& field, std::size_t at) {
  const ddf::Vec3& a = field.dirMax[at];
  const ddf::Vec3& b = field.dirMin[at];
  return double(field.kMax[at]) * a * a.transpose() + double(field.kMin[at]) * b * b.transpose();
}

/// @brief Stores the two tangential principal curvatures and directions of tensor @p s in the
/// plane of unit normal @p n into entry @p at of @p out, with its umbilic flag
/// (CurvatureParams::umbilicTolerance and flatCurvaturePerMm).
inline void storeCurvatureTensor(const Eigen::Matrix3d& s, const ddf::Vec3& n,
                                 double umbilicTolerance, double flatCurvaturePerMm,
                                 CurvatureField& out, std::size_t at) {
  const ddf::Vec3 b1 = n.unitOrthogonal(), b2 = n.cross(b1);
  const double s11 = b1.dot(s * b1), s12 = b1.dot(s * b2), s22 = b2.dot(s * b2);
  const double mean = 0.5 * (s11 + s22);
  const double radius = std::hypot(0.5 * (s11 - s22), s12);
  const double angle = 0.5 * std::atan2(2.0 * s12, s11 - s22);
  const double kMax = mean + radius, kMin = mean - radius;
  out.kMax[at] = static_cast<float>(kMax);
  out.kMin[at] = static_cast<float>(kMin);
  out.mean[at] = static_cast<float>(mean);
  out.gaussian[at] = static_cast<float>(kMax * kMin);
  out.dirMax[at] = std::cos(angle) * b1 + std::sin(angle) * b2;
  out.dirMin[at] = n.cross(out.dirMax[at]);
  const double scale = std::max(std::abs(kMax), std::abs(kMin));
  out.umbilic[at] = kMax - kMin <= umbilicTolerance * scale + flatCurvaturePerMm;
}

/// @brief @p out sized for @p count entries, all zero.
inline void resizeCurvatureField(CurvatureField& out, std::size_t count) {
  out.kMax.assign(count, 0.0f), out.kMin.assign(count, 0.0f), out.mean.assign(count, 0.0f);
  out.gaussian.assign(count, 0.0f);
  out.dirMax.assign(count, ddf::Vec3::Zero()), out.dirMin.assign(count, ddf::Vec3::Zero());
  out.umbilic.assign(count, 0);
}

}  // namespace ddfcam::planning::detail
