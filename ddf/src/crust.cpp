// SPDX-License-Identifier: MIT
// ddfcam: closed-form unique-projection crust heights h0 (sec. 4.3).
#include <ddfcam/ddf/crust.h>

#include <tbb/parallel_for.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace ddfcam::ddf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Smallest positive root of a h^2 + b h + c with c > 0 (+inf if none). The
/// cancellation-free form keeps both roots accurate when a is tiny relative to b and c.
double smallestPositiveRoot(double a, double b, double c) {
  if (a == 0.0) return b < 0.0 ? -c / b : kInf;
  double disc = b * b - 4.0 * a * c;
  // A double root (e.g. stubbles meeting in one point) must not be lost to rounding.
  if (disc < 0.0 && disc >= -1e-12 * (b * b + std::abs(4.0 * a * c))) disc = 0.0;
  if (disc < 0.0) return kInf;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) return kInf;
  double best = kInf;
  for (double r : {q / a, c / q})
    if (r > 0.0) best = std::min(best, r);
  return best;
}

}  // namespace

CrustHeights crustHeights(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& v1,
                          const Vec3& v2, const Vec3& v3) {
  const Vec3 dp12 = p2 - p1, dp13 = p3 - p1;
  const Vec3 dv12 = v2 - v1, dv13 = v3 - v1;
  // e12(h) x e13(h) = n0 + h n1 + h^2 n2.
  const Vec3 n0 = dp12.cross(dp13);
  const Vec3 n1 = dp12.cross(dv13) + dv12.cross(dp13);
  const Vec3 n2 = dv12.cross(dv13);
  CrustHeights out;
  for (const Vec3* v : {&v1, &v2, &v3}) {
    const double c = v->dot(n0), b = v->dot(n1), a = v->dot(n2);
    if (!(c > 0.0)) return {0.0, 0.0};  // constraint 1 violated: no unique crust at all
    out.positive = std::min(out.positive, smallestPositiveRoot(a, b, c));
    out.negative = std::min(out.negative, smallestPositiveRoot(a, -b, c));
  }
  return out;
}

CrustHeights crustHeights(const DisplacementField& ddf, int face) {
  const auto& fv = ddf.faceVertices(face);
  return crustHeights(ddf.position(fv[0]), ddf.position(fv[1]), ddf.position(fv[2]),
                      ddf.vector(fv[0]), ddf.vector(fv[1]), ddf.vector(fv[2]));
}

std::vector<CrustHeights> allCrustHeights(const DisplacementField& ddf) {
  std::vector<CrustHeights> out(ddf.faceCount());
  tbb::parallel_for(0, ddf.faceCount(), [&](int f) { out[f] = crustHeights(ddf, f); });
  return out;
}

namespace {

struct CellHash {
  std::size_t operator()(const std::array<long long, 3>& c) const {
    return static_cast<std::size_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
  }
};

}  // namespace

std::vector<int> coincidentVertexClasses(const DisplacementField& ddf, double toleranceMm) {
  double tol = toleranceMm;
  if (!(tol > 0.0)) {
    Eigen::AlignedBox3d box;
    for (int v = 0; v < ddf.vertexCount(); ++v) box.extend(ddf.position(v));
    tol = ddf.vertexCount() > 0 ? 1e-9 * box.diagonal().norm() : 1.0;
    if (!(tol > 0.0)) tol = 1e-300;  // all vertices at one point
  }
  // Cells as large as the tolerance: a coincident partner lies in one of the 27 cells around.
  std::unordered_map<std::array<long long, 3>, std::vector<int>, CellHash> grid;
  std::vector<int> cls(ddf.vertexCount());
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    const Vec3& p = ddf.position(v);
    const std::array<long long, 3> c = {static_cast<long long>(std::floor(p.x() / tol)),
                                        static_cast<long long>(std::floor(p.y() / tol)),
                                        static_cast<long long>(std::floor(p.z() / tol))};
    cls[v] = v;
    for (int d = 0; d < 27 && cls[v] == v; ++d) {
      const auto it = grid.find({c[0] + d % 3 - 1, c[1] + d / 3 % 3 - 1, c[2] + d / 9 - 1});
      if (it == grid.end()) continue;
      for (int u : it->second)
        if ((ddf.position(u) - p).norm() <= tol) {
          cls[v] = u;
          break;
        }
    }
    if (cls[v] == v) grid[c].push_back(v);
  }
  return cls;
}

}  // namespace ddfcam::ddf
