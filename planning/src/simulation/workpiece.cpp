// SPDX-License-Identifier: MIT
// ddfcam: workpiece DDFs for grinding simulation and the volume between two height fields.
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/raster_normal.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/column_volume.h>
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

double volumeBetween(const ddf::DisplacementField& field, const std::vector<float>& before,
                     const std::vector<float>& after) {
  if (before.size() != field.allHeights().size() || after.size() != before.size())
    throw InvalidInput("volumeBetween: height arrays of " + std::to_string(before.size()) +
                       " and " + std::to_string(after.size()) + " values for a field of " +
                       std::to_string(field.allHeights().size()) + " heights");
  const int n = field.raster().steps();
  double volume = 0.0;
  for (int f = 0; f < field.faceCount(); ++f) {
    const FaceColumnVolume terms(field, f);
    const std::size_t base = static_cast<std::size_t>(f) * field.pointsPerFace();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        const std::size_t at = base + field.raster().index(i, k);
        if (before[at] != after[at]) volume += terms.column(i, k, before[at], after[at]);
      }
  }
  return volume;
}

}  // namespace ddfcam::planning
