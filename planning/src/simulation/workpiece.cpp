// SPDX-License-Identifier: MIT
// ddfcam: workpiece DDFs for grinding simulation and the volume between two height fields.
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/raster_normal.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/workpiece.h>

#include <cmath>
#include <sstream>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

}  // namespace

ddf::DisplacementField workpieceWithAllowance(const ddf::DisplacementField& goal,
                                              double allowanceMm) {
  ddf::DisplacementField out = goal;
  for (int f = 0; f < goal.faceCount(); ++f) {
    auto heights = out.heights(f);
    for (int k = 0; k <= goal.raster().steps(); ++k)
      for (int i = 0; i < goal.raster().rowLength(k); ++i) {
        const Vec3 v = goal.vectorAt(f, goal.rasterBary(i, k));
        const double vn = v.dot(ddf::rasterNormal(goal, f, i, k));
        float& h = heights[goal.raster().index(i, k)];
        if (!(vn > 0.0)) {
          std::ostringstream s;
          s << "workpieceWithAllowance: the vector at face " << f << " raster point (" << i << ", "
            << k << ") is tangent to the surface, so an allowance of " << allowanceMm
            << " mm cannot be applied along it";
          throw InvalidInput(s.str());
        }
        const double raised = h + allowanceMm / vn;
        if (raised > 1.0 || raised < -1.0) {
          std::ostringstream s;
          s << "workpieceWithAllowance: an allowance of " << allowanceMm << " mm leaves the crust"
            << " at face " << f << " raster point (" << i << ", " << k << "): the crust there"
            << " extends " << (1.0 - h) * vn << " mm above and " << (h + 1.0) * vn
            << " mm below the surface along the normal (" << 2.0 * vn << " mm thick); convert"
            << " the part with a stock allowance of at least " << allowanceMm << " mm"
            << " (ddfcam-cli convert --stock MM, or Stock in the import dialog) so that its crust"
            << " holds it";
          throw InvalidInput(s.str());
        }
        h = static_cast<float>(raised);
      }
  }
  out.synchronizeShared(ddf::SharedPolicy::Canonical);
  return out;
}

StockWorkpiece workpieceFromStockMesh(const ddf::DisplacementField& goal,
                                      const ddf::TriangleMesh& stock,
                                      const StockWorkpieceParams& params) {
  StockWorkpiece result{goal, 0, {}};
  const ddf::CrustHash hash(result.workpiece);
  ddf::FillReport fill = ddf::fillFromMesh(result.workpiece, hash, stock, params.fill);
  if (fill.missing > 0 && params.requireFullCoverage) {
    std::ostringstream s;
    s << "workpieceFromStockMesh: " << fill.missing << " of " << goal.allHeights().size()
      << " stubbles miss the stock mesh within the crust (the stock must lie inside the crust"
      << " of the desired surface everywhere)";
    throw InvalidInput(s.str());
  }
  result.missing = fill.missing;
  result.missingMask = std::move(fill.missingMask);
  return result;
}

}  // namespace ddfcam::planning

namespace ddfcam::planning {
namespace {

double det3(const Vec3& a, const Vec3& b, const Vec3& c) {
  return a.cross(b).dot(c);
}

// Raster sub-triangles of the face incident to (i, k): 6 inside, 3 on an edge, 1 or 2 at a corner.
int incidentTriangles(int n, int i, int k) {
  static constexpr int kRing[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  auto valid = [n](int ii, int kk) { return ii >= 0 && kk >= 0 && ii + kk <= n; };
  int count = 0;
  for (int a = 0; a < 6; ++a) {
    const int b = (a + 1) % 6;
    count += valid(i + kRing[a][0], k + kRing[a][1]) && valid(i + kRing[b][0], k + kRing[b][1]);
  }
  return count;
}

}  // namespace

double volumeBetween(const ddf::DisplacementField& field, const std::vector<float>& before,
                     const std::vector<float>& after) {
  if (before.size() != field.allHeights().size() || after.size() != before.size())
    throw InvalidInput("volumeBetween: height arrays of " + std::to_string(before.size()) +
                       " and " + std::to_string(after.size()) + " values for a field of " +
                       std::to_string(field.allHeights().size()) + " heights");
  const int n = field.raster().steps();
  // Parameter area of a raster sub-triangle is 1 / (2 n^2); each corner takes a third.
  const double nodal = 1.0 / (6.0 * n * n);
  double volume = 0.0;
  for (int f = 0; f < field.faceCount(); ++f) {
    const auto& fv = field.faceVertices(f);
    const Vec3 e1 = field.position(fv[1]) - field.position(fv[0]);
    const Vec3 e2 = field.position(fv[2]) - field.position(fv[0]);
    const Vec3 f1 = field.vector(fv[1]) - field.vector(fv[0]);
    const Vec3 f2 = field.vector(fv[2]) - field.vector(fv[0]);
    const std::size_t base = static_cast<std::size_t>(f) * field.pointsPerFace();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        const std::size_t at = base + field.raster().index(i, k);
        const double h0 = before[at], h1 = after[at];
        if (h0 == h1) continue;
        const Vec3 v = field.vectorAt(f, field.rasterBary(i, k));
        // det(e1 + h f1, e2 + h f2, v) = j0 + j1 h + j2 h^2, integrated over [h1, h0].
        const double j0 = det3(e1, e2, v), j1 = det3(f1, e2, v) + det3(e1, f2, v),
                     j2 = det3(f1, f2, v);
        const double column = j0 * (h0 - h1) + j1 * (h0 * h0 - h1 * h1) / 2.0 +
                              j2 * (h0 * h0 * h0 - h1 * h1 * h1) / 3.0;
        volume += nodal * incidentTriangles(n, i, k) * column;
      }
  }
  return volume;
}

}  // namespace ddfcam::planning
