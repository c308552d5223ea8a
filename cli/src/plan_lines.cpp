// SPDX-License-Identifier: MIT
// ddfcam-cli plan: seeding and tracing the lines of a region, smoothing them on the surface.
#include "plan_lines.h"

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/line_field.h>
#include <ddfcam/planning/streamline_path.h>

#include <algorithm>
#include <limits>

namespace ddfcam::cli {

ddf::SurfaceLocation centralSeed(const ddf::DisplacementField& part,
                                 const planning::LineField& field) {
  const int n = part.raster().steps();
  const std::size_t perFace = part.raster().pointCount();
  ddf::Vec3 centroid = ddf::Vec3::Zero();
  std::size_t count = 0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++count) centroid += part.surfacePoint(f, i, k);
  centroid /= static_cast<double>(std::max<std::size_t>(count, 1));
  double best = std::numeric_limits<double>::infinity();
  ddf::SurfaceLocation seed;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        if (!(field[f * perFace + part.raster().index(i, k)].squaredNorm() > 0)) continue;
        const ddf::Vec3 p = part.surfacePoint(f, i, k);
        if ((p - centroid).squaredNorm() >= best) continue;
        best = (p - centroid).squaredNorm();
        seed = {f, part.rasterBary(i, k), part.heights(f)[part.raster().index(i, k)], p};
      }
  if (seed.face < 0) throw InvalidInput("plan: the flow field is undefined everywhere");
  return seed;
}

std::vector<planning::Streamline> planLines(
    const ddf::DisplacementField& part, const planning::LineField& field, Seeding seeding,
    planning::StreamlineMethod method, double spacingMm, double maxLengthMm,
    const ProgressCallback& progress,
    const std::function<double(const ddf::SurfaceLocation&)>& separationAt) {
  planning::StreamlineParams trace;
  trace.maxLengthMm = maxLengthMm;
  std::vector<planning::Streamline> lines;
  if (separationAt && seeding != Seeding::Even)
    throw InvalidInput("plan: a spacing that varies over the part needs even seeding");
  if (seeding == Seeding::Even) {
    planning::EvenSpacingParams params;
    params.separationMm = spacingMm;
    params.separationAt = separationAt;
    params.trace = trace;
    params.progress = progress;
    lines = planning::evenlySpacedStreamlines(part, field, params);
  } else {
    const ddf::SurfaceLocation seed = centralSeed(part, field);
    const planning::Streamline transverse =
        planning::traceStreamline(part, planning::transverseField(part, field), seed, trace);
    const std::vector<ddf::SurfaceLocation> seeds =
        planning::seedsAlong(part, transverse, spacingMm);
    for (std::size_t s = 0; s < seeds.size(); ++s) {
      reportProgress(progress, static_cast<double>(s) / seeds.size());
      lines.push_back(planning::traceStreamlineWith(method, part, field, seeds[s], trace));
    }
    reportProgress(progress, 1.0);
  }
  // Repeated points (a trace that stalls at a boundary) or a fold back onto the point before
  // (A B A) leave no feed direction for a pose there.
  const double eps = 1e-6 * spacingMm;
  for (planning::Streamline& line : lines) {
    std::vector<ddf::SurfaceLocation> kept;
    for (const ddf::SurfaceLocation& q : line.points) {
      if (!kept.empty() && (q.point - kept.back().point).norm() <= eps) continue;
      if (kept.size() >= 2 && (q.point - kept[kept.size() - 2].point).norm() <= eps) {
        kept.pop_back();
        continue;
      }
      kept.push_back(q);
    }
    line.points = std::move(kept);
    line.seedIndex = std::min(line.seedIndex, line.points.empty() ? 0 : line.points.size() - 1);
  }
  std::erase_if(lines, [](const planning::Streamline& l) { return l.points.size() < 2; });
  return lines;
}

}  // namespace ddfcam::cli
