// SPDX-License-Identifier: MIT
// ddfcam: the reach of a DDF's crust above and below its surface, and the concave radius of a
// mesh near a point.
#include "stock_crust_plan.h"

#include <ddfcam/ddf/raster_normal.h>
#include <ddfcam/ddf/stock_crust.h>
#include <ddfcam/error.h>

#include <tbb/parallel_for.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace ddfcam::ddf {
namespace {

double median(std::vector<double> values) {
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

// Surface point of stored height @p at (face-major, Raster order).
Vec3 pointOfIndex(const DisplacementField& ddf, std::size_t at) {
  const int f = static_cast<int>(at / ddf.pointsPerFace());
  const std::size_t local = at % ddf.pointsPerFace();
  for (int k = 0; k <= ddf.raster().steps(); ++k)
    if (local < ddf.raster().rowOffset(k) + ddf.raster().rowLength(k))
      return ddf.surfacePoint(f, static_cast<int>(local - ddf.raster().rowOffset(k)), k);
  return Vec3::Zero();
}

void reachPerPoint(const DisplacementField& ddf, std::vector<double>& above,
                   std::vector<double>* below) {
  const std::size_t per = ddf.pointsPerFace();
  above.assign(per * ddf.faceCount(), 0.0);
  if (below) below->assign(above.size(), 0.0);
  tbb::parallel_for(0, ddf.faceCount(), [&](int f) {
    for (int k = 0; k <= ddf.raster().steps(); ++k)
      for (int i = 0; i < ddf.raster().rowLength(k); ++i) {
        const std::size_t at = f * per + ddf.raster().index(i, k);
        const Vec3 v = ddf.vectorAt(f, ddf.rasterBary(i, k));
        const double vn = std::max(0.0, v.dot(rasterNormal(ddf, f, i, k)));
        const double h = ddf.height(f, i, k);
        above[at] = (1.0 - h) * vn;
        if (below) (*below)[at] = (1.0 + h) * vn;
      }
  });
}

}  // namespace

std::vector<double> detail::reachAbovePerPoint(const DisplacementField& ddf) {
  std::vector<double> above;
  reachPerPoint(ddf, above, nullptr);
  return above;
}

CrustReach crustReach(const DisplacementField& ddf) {
  CrustReach reach;
  const std::size_t per = ddf.pointsPerFace();
  if (per * ddf.faceCount() == 0) return reach;
  std::vector<double> above, below;
  reachPerPoint(ddf, above, &below);
  const auto minA = std::min_element(above.begin(), above.end()) - above.begin();
  const auto minB = std::min_element(below.begin(), below.end()) - below.begin();
  reach.minAboveMm = above[minA];
  reach.minBelowMm = below[minB];
  reach.minAboveFace = static_cast<int>(minA / per);
  reach.minBelowFace = static_cast<int>(minB / per);
  reach.minAbovePoint = pointOfIndex(ddf, minA);
  reach.minBelowPoint = pointOfIndex(ddf, minB);
  reach.medianAboveMm = median(std::move(above));
  reach.medianBelowMm = median(std::move(below));
  return reach;
}

namespace {

struct Facet {
  Vec3 centroid;
  Vec3 normal;
  double distance;
};

std::vector<Facet> facetsNear(const TriangleMesh& mesh, const Vec3& point, double radius) {
  std::vector<Facet> all;
  all.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Vec3 n = (b - a).cross(c - a);
    if (!(n.norm() > 0.0)) continue;
    const Vec3 centroid = (a + b + c) / 3.0;
    all.push_back({centroid, n.normalized(), (centroid - point).norm()});
  }
  std::sort(all.begin(), all.end(),
            [](const Facet& x, const Facet& y) { return x.distance < y.distance; });
  constexpr std::size_t kMinFacets = 8, kMaxFacets = 256;
  std::size_t within = 0;
  for (int grow = 0; grow <= 6; ++grow, radius *= 2.0) {
    within = std::upper_bound(all.begin(), all.end(), radius,
                              [](double r, const Facet& f) { return r < f.distance; }) -
             all.begin();
    if (within >= kMinFacets) break;
  }
  all.resize(std::min({within, kMaxFacets, all.size()}));
  return all;
}

}  // namespace

double concaveRadiusNear(const TriangleMesh& mesh, const Vec3& point, double neighbourhoodMm) {
  if (!(neighbourhoodMm > 0.0))
    throw InvalidInput("concaveRadiusNear: the neighbourhood must be > 0 mm, got " +
                       std::to_string(neighbourhoodMm));
  const std::vector<Facet> facets = facetsNear(mesh, point, neighbourhoodMm);
  if (facets.size() < 3) return std::numeric_limits<double>::infinity();
  const Vec3 n0 = facets.front().normal;  // the nearest facet's: a mean may vanish on a tube
  const Vec3 t1 = n0.unitOrthogonal(), t2 = n0.cross(t1);
  // Least squares of the tangential normal against the tangential position, affine:
  // [n.t1, n.t2] = [x, y, 1] B with B 3 x 2; the top 2 x 2 block is the shape operator.
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 2> atb = Eigen::Matrix<double, 3, 2>::Zero();
  for (const Facet& f : facets) {
    const Vec3 d = f.centroid - point;
    const Eigen::Vector3d row(d.dot(t1), d.dot(t2), 1.0);
    ata += row * row.transpose();
    atb += row * Eigen::RowVector2d(f.normal.dot(t1), f.normal.dot(t2));
  }
  const Eigen::Matrix<double, 3, 2> b = ata.completeOrthogonalDecomposition().solve(atb);
  Eigen::Matrix2d shape = b.topRows<2>();
  shape = 0.5 * (shape + shape.transpose()).eval();
  const Eigen::Vector2d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(shape).eigenvalues();
  // Rounding leaves a flat direction (a cylinder's axis) slightly curved either way.
  const double flat = 1e-9 * std::max(eig.cwiseAbs().maxCoeff(), 1.0 / neighbourhoodMm);
  return eig(0) < -flat ? -1.0 / eig(0) : std::numeric_limits<double>::infinity();
}

double detail::creaseRadiusNear(const TriangleMesh& mesh, const Vec3& point, double withinMm) {
  // Directed edge (a, b) -> triangle; the twin (b, a) is the neighbour across it.
  std::map<std::pair<int, int>, int> edges;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int j = 0; j < 3; ++j)
      edges[{mesh.triangles[t][j], mesh.triangles[t][(j + 1) % 3]}] = static_cast<int>(t);
  const auto normalOf = [&](int t) {
    const auto& tri = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    return Vec3((b - a).cross(c - a));
  };
  const auto centroidOf = [&](int t) {
    const auto& tri = mesh.triangles[t];
    return Vec3((mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3.0);
  };
  double tightest = std::numeric_limits<double>::infinity();
  for (const auto& [edge, t] : edges) {
    const auto twin = edges.find({edge.second, edge.first});
    if (edge.first > edge.second || twin == edges.end()) continue;
    const Vec3 a = mesh.vertices[edge.first], b = mesh.vertices[edge.second];
    if (((a + b) / 2.0 - point).norm() > withinMm) continue;
    const Vec3 n1 = normalOf(t), n2 = normalOf(twin->second);
    if (!(n1.norm() > 0.0 && n2.norm() > 0.0)) continue;
    const double angle = std::acos(std::clamp(n1.normalized().dot(n2.normalized()), -1.0, 1.0));
    const Vec3 c1 = centroidOf(t), c2 = centroidOf(twin->second);
    if (angle < 1e-6 || (c2 - c1).dot(n1) <= 0.0) continue;  // flat, or convex across the edge
    // A centroid lies a third of its triangle's height off the edge; 1.5 times that is half
    // the height, the facet's middle on a faceted circle.
    const Vec3 axis = (b - a).normalized();
    const auto offEdge = [&](const Vec3& c) {
      const Vec3 d = c - a;
      return (d - d.dot(axis) * axis).norm();
    };
    tightest = std::min(tightest, 1.5 * (offEdge(c1) + offEdge(c2)) / angle);
  }
  return tightest;
}

}  // namespace ddfcam::ddf
