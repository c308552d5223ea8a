// SPDX-License-Identifier: MIT
// ddfcam: coverage of a part by a result: flagged area, and the raster points a tool path
// touches (a raised copy of the desired surface cut along the path).
#include "error_region.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/coverage.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace ddfcam::planning {
namespace {

// @p goal with every height raised so that the surface moves by @p reachMm along its unit
// normal n (dh = reach / (v . n)), capped at the crust top h = 1. A stubble grazing the surface
// (v . n below a thousandth of |v|) is raised by reach / |v| instead of a huge step.
ddf::DisplacementField raisedCopy(const ddf::DisplacementField& goal, double reachMm) {
  ddf::DisplacementField raised = goal;
  const std::vector<ddf::Vec3> normals = rasterPointNormals(goal);
  const int n = goal.raster().steps();
  for (int f = 0; f < goal.faceCount(); ++f) {
    std::size_t l = static_cast<std::size_t>(f) * goal.pointsPerFace();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l) {
        float& h = raised.allHeights()[l];
        if (!std::isfinite(h)) continue;
        const ddf::Vec3 v = goal.vectorAt(f, goal.rasterBary(i, k));
        const double along = std::max(v.dot(normals[l]), 1e-3 * v.norm());
        if (!(along > 0.0)) continue;
        h = static_cast<float>(std::min(1.0, static_cast<double>(h) + reachMm / along));
      }
  }
  return raised;
}

}  // namespace

Coverage maskCoverage(const ddf::DisplacementField& ddf, std::span<const std::uint8_t> covered,
                      std::span<const int> faces) {
  detail::checkFieldSize(ddf, covered.size(), "maskCoverage: mask");
  const std::vector<int> region = detail::regionFaces(ddf, faces, "maskCoverage");
  const std::vector<double> areas = rasterPointAreas(ddf);
  Coverage out;
  for (int f : region) {
    const std::size_t base = static_cast<std::size_t>(f) * ddf.pointsPerFace();
    for (std::size_t l = base; l < base + ddf.pointsPerFace(); ++l) {
      out.totalAreaMm2 += areas[l];
      if (covered[l] != 0) out.coveredAreaMm2 += areas[l];
    }
  }
  return out;
}

PathCoverage pathCoverage(const ddf::DisplacementField& goal, const Tool& tool,
                          const ToolPath& path, const PathCoverageParams& params) {
  if (!(params.reachMm > 0.0) || !std::isfinite(params.reachMm))
    throw InvalidInput("pathCoverage: reachMm must be finite and > 0, got " +
                       std::to_string(params.reachMm));
  ddf::DisplacementField witness = raisedCopy(goal, params.reachMm);
  const std::vector<float> before = witness.allHeights();
  PathSimulationParams simulation;
  simulation.depthBuffer = params.depthBuffer;
  simulation.progress = params.progress;
  simulatePath(witness, tool, path, simulation);
  PathCoverage out;
  out.touched.assign(before.size(), 0);
  const std::vector<float>& after = witness.allHeights();
  for (std::size_t l = 0; l < before.size(); ++l) out.touched[l] = after[l] < before[l] ? 1 : 0;
  out.coverage = maskCoverage(goal, out.touched);
  return out;
}

}  // namespace ddfcam::planning
