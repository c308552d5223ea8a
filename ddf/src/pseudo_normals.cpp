// SPDX-License-Identifier: MIT
// ddfcam: angle-weighted pseudo-normals with a maximin repair for constraint 1.
#include <ddfcam/ddf/pseudo_normals.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ddfcam::ddf {
namespace {

/// Point of segment [a, b] nearest to the origin.
Vec3 nearestOnSegment(const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  if (dd == 0.0) return a;
  return a + std::clamp(-a.dot(d) / dd, 0.0, 1.0) * d;
}

/// Projection of the origin onto the plane of (a, b, c) if it falls inside the triangle.
std::optional<Vec3> nearestInsideTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  if (nn <= 1e-24) return std::nullopt;
  const Vec3 x = n * (a.dot(n) / nn);
  if ((b - a).cross(x - a).dot(n) < 0.0 || (c - b).cross(x - b).dot(n) < 0.0 ||
      (a - c).cross(x - c).dot(n) < 0.0)
    return std::nullopt;
  return x;
}

double margin(std::span<const Vec3> normals, const Vec3& u) {
  double m = std::numeric_limits<double>::infinity();
  for (const Vec3& n : normals) m = std::min(m, n.dot(u));
  return m;
}

struct Fans {
  std::vector<Vec3> weighted;                  // sum of angle x unit normal per vertex
  std::vector<std::vector<Vec3>> faceNormals;  // unit normals of incident faces per vertex
};

Fans collectFans(const SupportMesh& mesh) {
  Fans fans;
  fans.weighted.assign(mesh.n_vertices(), Vec3::Zero());
  fans.faceNormals.resize(mesh.n_vertices());
  for (const auto fh : mesh.faces()) {
    std::array<int, 3> idx;
    std::array<Vec3, 3> p;
    int k = 0;
    for (const auto vh : mesh.fv_range(fh)) {
      idx[k] = vh.idx();
      p[k++] = toEigen(mesh.point(vh));
    }
    const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
    const double longest = std::max(
        {(p[1] - p[0]).squaredNorm(), (p[2] - p[1]).squaredNorm(), (p[0] - p[2]).squaredNorm()});
    if (!(n.norm() > 1e-12 * longest)) continue;  // degenerate: no front side to respect
    const Vec3 unit = n.normalized();
    for (int i = 0; i < 3; ++i) {
      const Vec3 e1 = p[(i + 1) % 3] - p[i], e2 = p[(i + 2) % 3] - p[i];
      const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
      fans.weighted[idx[i]] += angle * unit;
      fans.faceNormals[idx[i]].push_back(unit);
    }
  }
  return fans;
}

}  // namespace

std::optional<std::pair<Vec3, double>> maximinDirection(std::span<const Vec3> normals) {
  if (normals.empty()) return std::nullopt;
  Vec3 best = normals[0];
  double bestMargin = -std::numeric_limits<double>::infinity();
  auto consider = [&](const Vec3& x) {
    const double norm = x.norm();
    if (!(norm > 1e-12)) return;
    const Vec3 u = x / norm;
    const double m = margin(normals, u);
    if (m > bestMargin) bestMargin = m, best = u;
  };
  const std::size_t k = normals.size();
  for (std::size_t i = 0; i < k; ++i) {
    consider(normals[i]);
    for (std::size_t j = i + 1; j < k; ++j) {
      consider(nearestOnSegment(normals[i], normals[j]));
      for (std::size_t l = j + 1; l < k; ++l)
        if (auto x = nearestInsideTriangle(normals[i], normals[j], normals[l])) consider(*x);
    }
  }
  if (!std::isfinite(bestMargin)) {  // every candidate at the origin: fall back to any normal
    best = normals[0];
    bestMargin = margin(normals, best);
  }
  return std::make_pair(best, bestMargin);
}

PseudoNormalResult pseudoNormals(const SupportMesh& mesh, const PseudoNormalParams& params) {
  const Fans fans = collectFans(mesh);
  PseudoNormalResult out;
  out.normals.resize(mesh.n_vertices());
  for (int v = 0; v < static_cast<int>(mesh.n_vertices()); ++v) {
    const auto& normals = fans.faceNormals[v];
    const double len = fans.weighted[v].norm();
    Vec3 dir = len > 0.0 ? Vec3(fans.weighted[v] / len) : Vec3::UnitZ();
    if (normals.empty()) {
      out.normals[v] = dir;
      continue;
    }
    const double current = margin(normals, dir);
    if (current > params.minFrontCosine) {
      out.normals[v] = dir;
      continue;
    }
    const auto [star, bestMargin] = *maximinDirection(normals);
    if (bestMargin <= 0.0) {
      out.infeasibleVertices.push_back(v);
      out.normals[v] = dir;
      continue;
    }
    // Along (1 - t) dir + t star the margin of the normalised vector is at least the linear
    // interpolation of the end margins, so this t reaches the target.
    const double target = std::min(params.minFrontCosine, bestMargin);
    const double t = bestMargin > current ? (target - current) / (bestMargin - current) : 1.0;
    const double tc = std::clamp(t, 0.0, 1.0);
    out.normals[v] = ((1.0 - tc) * dir + tc * star).normalized();
    out.repairedVertices.push_back(v);
  }
  return out;
}

}  // namespace ddfcam::ddf
