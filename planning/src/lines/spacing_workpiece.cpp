// SPDX-License-Identifier: MIT
// ddfcam: the simulated workpiece of refineSpacing(): stock, incremental cuts, region error.
#include "spacing_workpiece.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/placement/path_sampling.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace ddfcam::planning::spacing {

ddf::DisplacementField raisedStock(const ddf::DisplacementField& goal, double allowanceMm) {
  // A unit height step's deviation is v . n at every copy, with the normal deviationMap uses.
  ddf::DisplacementField step = goal;
  for (float& h : step.allHeights()) h += 1.0f;
  const std::vector<float> vn = deviationMap(step, goal.allHeights()).values;
  ddf::DisplacementField stock = goal;
  std::vector<float>& heights = stock.allHeights();
  for (std::size_t i = 0; i < heights.size(); ++i) {
    if (!std::isfinite(heights[i])) continue;
    if (!(vn[i] > 0.0f)) {
      throw InvalidInput("refineSpacing: the displacement vector at stored height " +
                         std::to_string(i) + " is not on the tool side of the goal normal");
    }
    heights[i] += static_cast<float>(allowanceMm / vn[i]);
    if (heights[i] > 1.0f) {
      throw InvalidInput("refineSpacing: a stock allowance of " + std::to_string(allowanceMm) +
                         " mm leaves the crust at face " +
                         std::to_string(i / goal.pointsPerFace()));
    }
  }
  return stock;
}

FieldExtremes fieldExtremes(const std::vector<float>& values) {
  FieldExtremes out{-std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity(), 0, false};
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double e = values[i];
    if (!std::isfinite(e)) continue;
    out.any = true;
    if (e > out.maxMm) {
      out.maxMm = e;
      out.worst = i;
    }
    out.minMm = std::min(out.minMm, e);
  }
  return out;
}

std::vector<float> regionDeviation(const ddf::DisplacementField& work,
                                   const ddf::DisplacementField& goal,
                                   const std::vector<std::uint8_t>& faceMask) {
  std::vector<float> values = deviationMap(work, goal.allHeights()).values;
  if (faceMask.empty()) return values;
  const std::size_t per = goal.pointsPerFace();
  for (int f = 0; f < goal.faceCount(); ++f) {
    if (faceMask[f]) continue;
    std::fill_n(values.begin() + static_cast<std::ptrdiff_t>(f * per), per,
                std::numeric_limits<float>::quiet_NaN());
  }
  return values;
}

ddf::SurfaceLocation rasterLocation(const ddf::DisplacementField& goal, std::size_t index) {
  const int face = static_cast<int>(index / goal.pointsPerFace());
  const std::size_t local = index % goal.pointsPerFace();
  const ddf::Raster& raster = goal.raster();
  for (int k = 0; k < raster.m; ++k) {
    if (local >= raster.rowOffset(k) + static_cast<std::size_t>(raster.rowLength(k))) continue;
    const int i = static_cast<int>(local - raster.rowOffset(k));
    ddf::SurfaceLocation loc;
    loc.face = face;
    loc.bary = goal.rasterBary(i, k);
    loc.h = goal.heights(face)[local];
    loc.point = goal.surfacePoint(face, i, k);
    return loc;
  }
  throw InvalidInput("refineSpacing: stored height index " + std::to_string(index) +
                     " is out of range");
}

double meanRasterSpacing(const ddf::DisplacementField& goal,
                         const std::vector<std::uint8_t>& faceMask) {
  double sum = 0.0;
  int edges = 0;
  for (int f = 0; f < goal.faceCount(); ++f) {
    if (!faceMask.empty() && !faceMask[f]) continue;
    const auto& v = goal.faceVertices(f);
    for (int e = 0; e < 3; ++e) sum += (goal.position(v[e]) - goal.position(v[(e + 1) % 3])).norm();
    edges += 3;
  }
  if (edges == 0) throw InvalidInput("refineSpacing: the region has no faces");
  return sum / edges / goal.raster().steps();
}

ddf::SurfaceLocation regionCentreLocation(const ddf::DisplacementField& goal,
                                          const std::vector<std::uint8_t>& faceMask) {
  const std::size_t per = goal.pointsPerFace();
  const auto inRegion = [&](std::size_t i) {
    return (faceMask.empty() || faceMask[i / per]) && std::isfinite(goal.allHeights()[i]);
  };
  ddf::Vec3 sum = ddf::Vec3::Zero();
  std::size_t count = 0;
  for (std::size_t i = 0; i < goal.allHeights().size(); ++i) {
    if (!inRegion(i)) continue;
    sum += rasterLocation(goal, i).point;
    ++count;
  }
  if (count == 0) throw InvalidInput("refineSpacing: the region has no finite raster point");
  const ddf::Vec3 centroid = sum / static_cast<double>(count);
  std::size_t best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < goal.allHeights().size(); ++i) {
    if (!inRegion(i)) continue;
    const double d = (rasterLocation(goal, i).point - centroid).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = i;
    }
  }
  return rasterLocation(goal, best);
}

double distanceToLine(const ddf::Vec3& p, const Streamline& line) {
  double best = std::numeric_limits<double>::infinity();
  const auto& pts = line.points;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i + 1 == pts.size()) {
      best = std::min(best, (p - pts[i].point).norm());
      break;
    }
    const ddf::Vec3 a = pts[i].point, ab = pts[i + 1].point - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (p - (a + t * ab)).norm());
  }
  return best;
}

ToolPath placeLines(const ddf::DisplacementField& goal, const std::vector<Streamline>& lines,
                    const Tool& tool, int toolIndex, const StreamlinePathParams& pathParams,
                    double feedToleranceMm) {
  PathSamplingParams sampling;
  sampling.toleranceMm = feedToleranceMm;
  sampling.name = pathParams.name;
  sampling.feedMmPerMin = pathParams.feedMmPerMin;
  // The feed cusp rule keeps the error map honest; stubbles need not be met one by one.
  sampling.rasterSpacingFactor = 4.0;
  PlacementParams placement;
  placement.depthMm = pathParams.depthMm;
  return placeAlongPath(goal, lines, tool, toolIndex, placement, sampling);
}

void cutLines(ddf::DisplacementField& work, const ddf::DisplacementField& goal,
              const std::vector<Streamline>& lines, const Tool& tool, int toolIndex,
              const StreamlinePathParams& pathParams, const ddf::DepthBufferParams& depthBuffer,
              double feedToleranceMm) {
  std::vector<Streamline> usable;
  for (const Streamline& line : lines)
    if (line.points.size() >= 2) usable.push_back(line);
  if (usable.empty()) return;
  const ToolPath path = placeLines(goal, usable, tool, toolIndex, pathParams, feedToleranceMm);
  GrindingSimulationParams simulation;
  simulation.depthBuffer = depthBuffer;
  // Only the removed material matters here; the checks are the simulation panel's business.
  simulation.checkVConvexity = false;
  simulation.checkCollisions = false;
  simulateGrinding(work, toolMeshes(tool), path, simulation);
}

}  // namespace ddfcam::planning::spacing
