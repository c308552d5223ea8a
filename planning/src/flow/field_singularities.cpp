// SPDX-License-Identifier: MIT
// ddfcam: singularities of line fields on DDFs from the rotation around raster triangles.
#include <ddfcam/error.h>
#include <ddfcam/planning/flow/flow_field.h>

#include "field_frames.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

namespace ddfcam::planning {

namespace {

using ddf::PointId;
using ddf::Vec3;
using detail::SurfaceFrames;

// Doubled angle of the first stored copy of every point; NaN where the line is undefined.
std::vector<double> pointAngles(const SurfaceFrames& frames, const LineField& field) {
  std::vector<double> psi(frames.position.size(), std::nan(""));
  std::vector<char> seen(psi.size(), 0);
  for (std::size_t copy = 0; copy < field.size(); ++copy) {
    const PointId p = frames.idOfCopy[copy];
    if (seen[p]) continue;
    seen[p] = 1;
    const std::complex<double> z = detail::doubledAngle(frames, p, field[copy]);
    if (std::abs(z) > 0.0) psi[p] = std::arg(z);
  }
  return psi;
}

// Signed solid angle of the spherical triangle of the three point normals (Van Oosterom and
// Strackee), in (-2 pi, 2 pi): the curvature the triangle encloses.
double normalSolidAngle(const SurfaceFrames& frames, const std::array<PointId, 3>& t) {
  const Vec3 &a = frames.normal[t[0]], &b = frames.normal[t[1]], &c = frames.normal[t[2]];
  return 2.0 * std::atan2(a.dot(b.cross(c)), 1.0 + a.dot(b) + b.dot(c) + c.dot(a));
}

// Angle by which transport from p to q turns p's frame into q's: the smallest rotation taking
// p's normal to q's. Around a triangle its holonomy is the solid angle of the three normals
// (modulo 2 pi) even where a crease turns the normals by more than 90 degrees, where angles of
// the edge projected into both tangent planes are meaningless.
double rotationTransportAngle(const SurfaceFrames& frames, PointId p, PointId q) {
  const Vec3 &np = frames.normal[p], &nq = frames.normal[q], &v = frames.axis1[p];
  const Vec3 k = np.cross(nq);
  const double c = np.dot(nq), s2 = k.squaredNorm();
  Vec3 w = v;
  if (s2 > 1e-24) w = c * v + k.cross(v) + k * (k.dot(v) * (1.0 - c) / s2);
  return std::atan2(w.dot(frames.axis2[q]), w.dot(frames.axis1[q]));
}

// Twice the index: the field's rotation relative to transport around the triangle plus twice
// the holonomy (transport around a loop turns vectors by the enclosed curvature), over 2 pi.
// The transport angles give the holonomy only modulo 2 pi; of its values the one nearest the
// normals' solid angle (equal to it up to rounding) is taken, so that a triangle across a
// sharp crease (more than pi of enclosed curvature) still adds its share to the Euler
// characteristic.
int doubledIndex(const SurfaceFrames& frames, const std::vector<double>& psi,
                 const std::array<PointId, 3>& t) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double turning = 0.0, holonomy = 0.0;
  for (int a = 0; a < 3; ++a) {
    const PointId p = t[a], q = t[(a + 1) % 3];
    const double rho = rotationTransportAngle(frames, p, q);
    holonomy += rho;
    turning += detail::wrapAngle(psi[q] - psi[p] - 2.0 * rho);
  }
  holonomy = detail::wrapAngle(holonomy);
  holonomy += kTwoPi * std::round((normalSolidAngle(frames, t) - holonomy) / kTwoPi);
  const double total = turning + 2.0 * holonomy;
  return static_cast<int>(std::lround(total / kTwoPi));
}

FieldSingularity locate(const ddf::DisplacementField& ddf, const detail::RasterTriangle& t,
                        int doubled) {
  FieldSingularity s;
  s.face = t.face;
  double h = 0.0;
  const double n = ddf.raster().steps();
  for (std::uint32_t local : t.local) {
    const ddf::RasterCoord c = ddf.topology().coord({t.face, local});
    s.bary += Vec3(c.i, c.j, c.k) / (3.0 * n);
    h += ddf.heights(t.face)[local] / 3.0;
  }
  s.point = ddf.pointAt(t.face, s.bary, h);
  s.index = 0.5 * doubled;
  return s;
}

}  // namespace

std::vector<FieldSingularity> findSingularities(const ddf::DisplacementField& ddf,
                                                const LineField& field) {
  const std::size_t expected = ddf.pointsPerFace() * ddf.faceCount();
  if (field.size() != expected)
    throw InvalidInput("findSingularities: the line field has " + std::to_string(field.size()) +
                       " entries, the DDF " + std::to_string(expected) + " raster point copies");
  std::vector<FieldSingularity> out;
  if (expected == 0) return out;
  const SurfaceFrames frames = detail::buildSurfaceFrames(ddf);
  const std::vector<double> psi = pointAngles(frames, field);
  for (const detail::RasterTriangle& t : frames.triangles) {
    if (std::isnan(psi[t.point[0]]) || std::isnan(psi[t.point[1]]) || std::isnan(psi[t.point[2]]))
      continue;
    const int doubled = doubledIndex(frames, psi, t.point);
    if (doubled != 0) out.push_back(locate(ddf, t, doubled));
  }
  return out;
}

}  // namespace ddfcam::planning
