// SPDX-License-Identifier: MIT
// ddfcam: the planning of one region's lines from its RegionPlan (sec. 8.1-8.4).
#include <ddfcam/planning/pipeline/region_planning.h>

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/evenly_spaced_streamlines.h>
#include <ddfcam/planning/lines/line_ordering.h>
#include <ddfcam/planning/lines/scallop_spacing.h>
#include <ddfcam/planning/lines/streamline_continuous.h>
#include <ddfcam/planning/lines/streamline_fairing.h>
#include <ddfcam/planning/lines/streamline_raster_walk.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace ddfcam::planning {

std::vector<Streamline> traceLinesThrough(const ddf::DisplacementField& part,
                                          const LineField& field,
                                          const std::vector<ddf::SurfaceLocation>& seeds,
                                          StreamlineMethod method, const StreamlineParams& trace,
                                          const ProgressCallback& progress) {
  std::optional<ddf::CrustHash> hash;
  if (method == StreamlineMethod::Continuous) hash.emplace(part);
  ContinuousStreamlineParams continuous;
  continuous.crustHash = hash ? &*hash : nullptr;
  std::vector<Streamline> lines;
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    reportProgress(progress, static_cast<double>(s) / static_cast<double>(seeds.size()));
    lines.push_back(traceStreamlineWith(method, part, field, seeds[s], trace, {}, continuous));
  }
  return lines;
}

namespace {

bool inMask(const std::vector<std::uint8_t>& mask, int face) {
  return mask.empty() || mask[static_cast<std::size_t>(face)] != 0;
}

double boxDiagonal(const ddf::DisplacementField& part) {
  Eigen::AlignedBox3d box;
  for (int v = 0; v < part.vertexCount(); ++v) box.extend(part.position(v));
  return box.isEmpty() ? 1.0 : box.diagonal().norm();
}

// Scallop spacing of the points where the field is defined: elsewhere no line runs, so the
// plane value there must not set the smallest spacing.
std::vector<float> definedScallopSpacing(const ddf::DisplacementField& part,
                                         const CurvatureField& curvature, const LineField& field,
                                         double radiusMm, double scallopMm) {
  std::vector<float> spacing = scallopSpacingField(part, curvature, field, radiusMm, scallopMm);
  for (std::size_t i = 0; i < spacing.size(); ++i)
    if (!(field[i].squaredNorm() > 0)) spacing[i] = std::numeric_limits<float>::quiet_NaN();
  return spacing;
}

std::string formatMm(double mm) {
  std::ostringstream out;
  out.precision(4);
  out << mm << " mm";
  return out.str();
}

std::vector<Streamline> traceFamily(const ddf::DisplacementField& part, const RegionFields& fields,
                                    const std::vector<std::uint8_t>& mask, double spacingMm,
                                    const RegionLinesParams& params, StreamlineParams trace) {
  const ddf::SurfaceLocation seed =
      params.seed ? *params.seed : centralSeed(part, fields.field, mask);
  if (params.tracing == StreamlineMethod::Rk4) {
    trace.progress = params.progress;
    return seedAlongTransverse(part, fields.field, fields.transverse, seed, spacingMm, trace);
  }
  const Streamline transverse = traceStreamline(part, fields.transverse, seed, trace);
  return traceLinesThrough(part, fields.field, seedsAlong(part, transverse, spacingMm),
                           params.tracing, trace, params.progress);
}

std::vector<Streamline> refined(const ddf::DisplacementField& part, std::vector<Streamline> lines,
                                const RegionLinesParams& params) {
  if (params.smoothHalfWindow > 0) lines = smoothOnSurface(part, lines, params.smoothHalfWindow);
  if (params.fair)
    for (std::size_t l = 0; l < lines.size(); ++l) {
      reportProgress(params.progress, static_cast<double>(l) / static_cast<double>(lines.size()));
      lines[l] = fairStreamline(part, lines[l]);
    }
  for (Streamline& line : lines) dropRepeatedPoints(line);
  std::erase_if(lines, [](const Streamline& l) { return l.points.size() < 2; });
  return lines;
}

}  // namespace

std::vector<std::uint8_t> regionFaceMask(const ddf::DisplacementField& part, const Region& region) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(part.faceCount()), 0);
  for (const int f : region.faces)
    if (f >= 0 && f < part.faceCount()) mask[static_cast<std::size_t>(f)] = 1;
  return mask;
}

RegionFields regionFields(const ddf::DisplacementField& part, const CurvatureField& curvature,
                          const RegionPlan& plan, const std::vector<std::uint8_t>& faceMask,
                          const ProgressCallback& progress) {
  FlowFieldParams params;
  params.source = plan.flowSource;
  params.fixedDirection = plan.fixedDirection;
  params.smoothing = plan.smoothField;
  params.smoothnessWeight = plan.smoothnessWeight;
  params.faceMask = faceMask;
  params.strokes = plan.strokes;
  params.progress = [&](double f) { return !progress || progress(0.8 * f); };
  RegionFields out;
  out.field = flowField(part, curvature, params);
  // flowField sets the region's boundary points at their copies on outside faces too.
  const std::size_t perFace = part.raster().pointCount();
  for (int f = 0; f < part.faceCount(); ++f)
    if (!inMask(faceMask, f))
      std::fill_n(out.field.begin() + static_cast<std::ptrdiff_t>(f * perFace), perFace,
                  ddf::Vec3::Zero());
  reportProgress(progress, 0.8);
  out.transverse = transverseField(part, out.field);
  out.singularities = findSingularities(part, out.field);
  reportProgress(progress, 1.0);
  return out;
}

LineSpacing regionSpacing(const ddf::DisplacementField& part, const CurvatureField& curvature,
                          const RegionFields& fields, const RegionPlan& plan, const Tool& tool) {
  LineSpacing out;
  out.minMm = out.maxMm = plan.spacingMm;
  if (plan.spacingMode != SpacingMode::ScallopTolerance) return out;
  const std::optional<double> radius = effectiveCrossFeedRadiusMm(tool);
  if (!radius) {
    out.note =
        "scallop height not applied: a straight roll has no curved profile across the "
        "feed, so the plan's fixed spacing " +
        formatMm(plan.spacingMm) + " is used";
    return out;
  }
  std::vector<float> spacing =
      definedScallopSpacing(part, curvature, fields.field, *radius, plan.scallopToleranceMm);
  const std::optional<double> smallest = smallestFiniteSpacing(spacing);
  if (!smallest)
    throw InvalidInput("the ball of radius " + formatMm(*radius) +
                       " gouges every concave point of the region, so no scallop spacing "
                       "exists; choose a smaller ball or a fixed spacing");
  out.fromScallop = true;
  out.minMm = std::max(*smallest, kMinScallopSpacingMm);
  out.maxMm = out.minMm;
  std::size_t defined = 0, gouging = 0;
  for (std::size_t i = 0; i < spacing.size(); ++i) {
    if (!(fields.field[i].squaredNorm() > 0)) continue;
    ++defined;
    if (std::isfinite(spacing[i]))
      out.maxMm = std::max<double>(out.maxMm, spacing[i]);
    else
      ++gouging;
  }
  out.gougingFraction = defined ? static_cast<double>(gouging) / static_cast<double>(defined) : 0;
  out.separationAt = spacingFunction(part, std::move(spacing), out.minMm);
  out.note = "scallop height " + formatMm(plan.scallopToleranceMm) + " with a ball of radius " +
             formatMm(*radius) + ": spacing " + formatMm(out.minMm) + " to " + formatMm(out.maxMm) +
             " by the curvature across the feed";
  return out;
}

std::vector<Streamline> planRegionLines(const ddf::DisplacementField& part,
                                        const RegionFields& fields,
                                        const std::vector<std::uint8_t>& faceMask,
                                        const LineSpacing& spacing,
                                        const RegionLinesParams& params) {
  StreamlineParams trace;
  trace.faceMask = faceMask;
  trace.maxLengthMm =
      params.maxLineLengthMm > 0.0 ? params.maxLineLengthMm : 4.0 * boxDiagonal(part);
  std::vector<Streamline> lines;
  if (params.seeding == LineSeeding::Coverage) {
    EvenSpacingParams even;
    even.separationMm = spacing.minMm;
    even.separationAt = spacing.separationAt;
    even.faceMask = faceMask;
    even.trace = trace;
    even.progress = params.progress;
    lines = evenlySpacedStreamlines(part, fields.field, even);
  } else {
    if (spacing.separationAt)
      throw InvalidInput(
          "a spacing that varies over the region needs coverage seeding, not a "
          "family along one transverse line");
    lines = traceFamily(part, fields, faceMask, spacing.minMm, params, trace);
  }
  lines = refined(part, std::move(lines), params);
  reportProgress(params.progress, 1.0);
  if (lines.empty()) throw InvalidInput("no line with two points could be traced in the region");
  return lines;
}

ddf::SurfaceLocation centralSeed(const ddf::DisplacementField& part, const LineField& field,
                                 const std::vector<std::uint8_t>& faceMask) {
  const int n = part.raster().steps();
  const std::size_t perFace = part.raster().pointCount();
  ddf::Vec3 centroid = ddf::Vec3::Zero();
  std::size_t count = 0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; inMask(faceMask, f) && k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++count) centroid += part.surfacePoint(f, i, k);
  centroid /= static_cast<double>(std::max<std::size_t>(count, 1));
  double best = std::numeric_limits<double>::infinity();
  ddf::SurfaceLocation seed;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; inMask(faceMask, f) && k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const std::size_t at = f * perFace + part.raster().index(i, k);
        const ddf::Vec3 p = part.surfacePoint(f, i, k);
        if (!(field[at].squaredNorm() > 0) || (p - centroid).squaredNorm() >= best) continue;
        best = (p - centroid).squaredNorm();
        seed = {f, part.rasterBary(i, k), part.heights(f)[part.raster().index(i, k)], p};
      }
  if (seed.face < 0) throw InvalidInput("the flow field is undefined everywhere in the region");
  return seed;
}

LinkingParams linkingParamsOf(const RegionPlan& plan, LinkingParams base) {
  base.order = plan.linking;
  base.feedSign = plan.feedSign;
  return base;
}

RegionPath regionToolPath(const ddf::DisplacementField& part, std::vector<Streamline> lines,
                          const RegionPlan& plan, const Tool& tool, int toolIndex, bool link,
                          const StreamlinePathParams& placement) {
  RegionPath out;
  if (link && lines.size() > 1)
    out.linked = orderLinesForCutting(part, lines, linkingParamsOf(plan));
  for (const Streamline& line : lines) out.cuttingLengthMm += line.lengthMm;
  out.placed = toolPathFromStreamlinesDetailed(part, lines, tool, toolIndex, placement);
  // The path keeps the lines as traced and ordered, so smoothing and fairing it later (in the
  // workbench, or in a project a batch job wrote) start from them, not from the placed poses.
  out.placed.path.rawLines = lines;
  if (out.linked) out.placed.path.linkedIdleMm = out.linked->idleLengthMm;
  out.lines = std::move(lines);
  return out;
}

}  // namespace ddfcam::planning
