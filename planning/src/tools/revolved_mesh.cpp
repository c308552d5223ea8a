// SPDX-License-Identifier: MIT
// ddfcam: closed triangle meshes of solids of revolution from a 2D profile polyline.
#include <ddfcam/planning/tools/revolved_mesh.h>

#include <ddfcam/error.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace ddfcam::planning {
namespace {

void checkProfile(std::span<const ProfilePoint> profile, int segments) {
  if (segments < 3)
    throw InvalidInput("revolved mesh: " + std::to_string(segments) +
                       " segments, at least 3 are needed");
  if (profile.size() < 3)
    throw InvalidInput("revolved mesh: a profile of " + std::to_string(profile.size()) +
                       " points, at least 3 are needed");
  if (profile.front().radial != 0.0 || profile.back().radial != 0.0)
    throw InvalidInput("revolved mesh: the profile must start and end on the axis (radial 0)");
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const ProfilePoint& p = profile[i];
    if (!std::isfinite(p.axial) || !std::isfinite(p.radial))
      throw InvalidInput("revolved mesh: profile point " + std::to_string(i) + " is not finite");
    if (i > 0 && i + 1 < profile.size() && !(p.radial > 0.0))
      throw InvalidInput("revolved mesh: interior profile point " + std::to_string(i) +
                         " lies on the axis");
    if (i > 0 && p == profile[i - 1])
      throw InvalidInput("revolved mesh: profile points " + std::to_string(i - 1) + " and " +
                         std::to_string(i) + " coincide");
  }
}

/// Twice the signed area the profile encloses with the axis (shoelace, closed along the axis).
double twiceEnclosedArea(std::span<const ProfilePoint> profile) {
  double sum = 0.0;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const ProfilePoint& p = profile[i];
    const ProfilePoint& q = profile[(i + 1) % profile.size()];
    sum += p.axial * q.radial - q.axial * p.radial;
  }
  return sum;
}

Eigen::Vector3d placePoint(const ProfilePoint& p, RevolveAxis axis, double c, double s) {
  if (axis == RevolveAxis::X) return {p.axial, p.radial * c, p.radial * s};
  return {p.radial * c, p.radial * s, p.axial};
}

}  // namespace

ddf::TriangleMesh revolveProfile(std::span<const ProfilePoint> profile, RevolveAxis axis,
                                 int segments) {
  checkProfile(profile, segments);
  const double area = twiceEnclosedArea(profile);
  if (area == 0.0) throw InvalidInput("revolved mesh: the profile encloses no area");
  // A clockwise profile in the (axial, radial) plane gives outward triangles in this order; the
  // (x, y, z) <- (a, r cos, r sin) and (r cos, r sin, a) maps share the handedness.
  const bool flip = area > 0.0;
  ddf::TriangleMesh mesh;
  const int s = segments;
  std::vector<double> cosines(s), sines(s);
  for (int j = 0; j < s; ++j) {
    const double t = 2.0 * std::numbers::pi * j / s;
    cosines[j] = std::cos(t);
    sines[j] = std::sin(t);
  }
  // First vertex index of each profile point: a pole has one vertex, a ring s.
  std::vector<int> first(profile.size());
  for (std::size_t k = 0; k < profile.size(); ++k) {
    first[k] = static_cast<int>(mesh.vertices.size());
    const bool pole = k == 0 || k + 1 == profile.size();
    for (int j = 0; j < (pole ? 1 : s); ++j)
      mesh.vertices.push_back(placePoint(profile[k], axis, cosines[j], sines[j]));
  }
  auto vertex = [&](std::size_t k, int j) {
    const bool pole = k == 0 || k + 1 == profile.size();
    return pole ? first[k] : first[k] + j % s;
  };
  auto add = [&](int a, int b, int c) {
    if (a == b || b == c || a == c) return;  // the degenerate half of a quad at a pole
    mesh.triangles.push_back(flip ? std::array<int, 3>{a, c, b} : std::array<int, 3>{a, b, c});
  };
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    for (int j = 0; j < s; ++j) {
      const int a = vertex(k, j), b = vertex(k, j + 1);
      const int c = vertex(k + 1, j + 1), d = vertex(k + 1, j);
      add(a, b, c);
      add(a, c, d);
    }
  }
  return mesh;
}

void appendMesh(ddf::TriangleMesh& mesh, const ddf::TriangleMesh& part) {
  const int offset = static_cast<int>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (const auto& t : part.triangles)
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

}  // namespace ddfcam::planning
