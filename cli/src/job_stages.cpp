// SPDX-License-Identifier: MIT
// ddfcam-cli run: loading, segmentation and the planning of one region, as the workbench's
// Part, Segmentation, Streamlines and Spacing refinement panels call the library.
#include "job_stages.h"

#include "unit_options.h"

#include <ddfcam/error.h>
#include <ddfcam/io/project_file.h>
#include <ddfcam/io/project_loader.h>
#include <ddfcam/planning/demo_project.h>
#include <ddfcam/planning/evenly_spaced_streamlines.h>
#include <ddfcam/planning/flow_field.h>
#include <ddfcam/planning/line_field.h>
#include <ddfcam/planning/line_ordering.h>
#include <ddfcam/planning/path_linking.h>
#include <ddfcam/planning/region_editing.h>
#include <ddfcam/planning/segmentation.h>
#include <ddfcam/planning/spacing_refinement.h>
#include <ddfcam/planning/streamline_path.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace ddfcam::cli {

namespace {

std::vector<std::uint8_t> faceMaskOf(const ddf::DisplacementField& part,
                                     const planning::Region& region) {
  std::vector<std::uint8_t> mask(part.faceCount(), 0);
  for (const int f : region.faces)
    if (f >= 0 && f < part.faceCount()) mask[f] = 1;
  return mask;
}

/// The flow field of @p plan on the faces of @p mask (zero elsewhere, also at the boundary
/// copies flowField sets on outside faces), as the Streamlines panel computes it.
planning::LineField regionField(const ddf::DisplacementField& part,
                                const planning::CurvatureField& curvature,
                                const planning::RegionPlan& plan,
                                const std::vector<std::uint8_t>& mask) {
  planning::FlowFieldParams params;
  params.source = plan.flowSource;
  params.fixedDirection = plan.fixedDirection;
  params.smoothing = plan.smoothField;
  params.smoothnessWeight = plan.smoothnessWeight;
  params.faceMask = mask;
  params.strokes = plan.strokes;
  planning::LineField field = planning::flowField(part, curvature, params);
  const std::size_t perFace = part.raster().pointCount();
  for (int f = 0; f < part.faceCount(); ++f)
    if (!mask[f])
      for (std::size_t p = 0; p < perFace; ++p) field[f * perFace + p] = ddf::Vec3::Zero();
  return field;
}

/// The raster point of the region with a defined field nearest to the centroid of the
/// region's raster points (the default seed of evenlySpacedStreamlines).
ddf::SurfaceLocation regionSeed(const ddf::DisplacementField& part,
                                const planning::LineField& field,
                                const std::vector<std::uint8_t>& mask) {
  const int n = part.raster().steps();
  ddf::Vec3 centroid = ddf::Vec3::Zero();
  std::size_t count = 0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; mask[f] && k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++count) centroid += part.surfacePoint(f, i, k);
  centroid /= static_cast<double>(std::max<std::size_t>(count, 1));
  double best = std::numeric_limits<double>::infinity();
  ddf::SurfaceLocation seed;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; mask[f] && k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const std::size_t at = f * part.raster().pointCount() + part.raster().index(i, k);
        const ddf::Vec3 p = part.surfacePoint(f, i, k);
        if (!(field[at].squaredNorm() > 0) || (p - centroid).squaredNorm() >= best) continue;
        best = (p - centroid).squaredNorm();
        seed = {f, part.rasterBary(i, k), part.heights(f)[part.raster().index(i, k)], p};
      }
  if (seed.face < 0) throw InvalidInput("the flow field is undefined everywhere in the region");
  return seed;
}

std::vector<planning::Streamline> traceLines(const ddf::DisplacementField& part,
                                             const planning::LineField& field,
                                             const std::vector<std::uint8_t>& mask,
                                             const RegionJob& job) {
  if (job.method == LineMethod::Even) {
    planning::EvenSpacingParams params;
    params.separationMm = job.plan.spacingMm;
    params.faceMask = mask;
    return planning::evenlySpacedStreamlines(part, field, params);
  }
  planning::StreamlineParams params;
  params.faceMask = mask;
  const ddf::SurfaceLocation seed = regionSeed(part, field, mask);
  const planning::LineField transverse = planning::transverseField(part, field);
  if (job.tracing == planning::StreamlineMethod::Rk4)
    return planning::seedAlongTransverse(part, field, transverse, seed, job.plan.spacingMm, params);
  const planning::Streamline line = planning::traceStreamline(part, transverse, seed, params);
  std::vector<planning::Streamline> lines;
  for (const ddf::SurfaceLocation& s : planning::seedsAlong(part, line, job.plan.spacingMm))
    lines.push_back(planning::traceStreamlineWith(job.tracing, part, field, s, params));
  return lines;
}

RegionPathInfo refinedPath(planning::Project& project, const planning::LineField& field,
                           const std::vector<std::uint8_t>& mask, const RegionJob& job) {
  planning::SpacingRefinementParams params;
  params.toleranceMm = job.refineToleranceMm;
  params.maxIterations = job.refineMaxIterations;
  params.toolIndex = job.plan.tool;
  const planning::SpacingRefinementResult result = planning::refineSpacing(
      *project.part, field, mask, project.tools[static_cast<std::size_t>(job.plan.tool)], params);
  RegionPathInfo info;
  info.lines = static_cast<int>(result.paths.size());
  info.lengthMm = result.totalLengthMm;
  planning::ToolPath path = result.toolPath;
  path.tool = job.plan.tool;
  project.paths.push_back(std::move(path));
  project.fields.push_back({"refinement error", "mm", true, result.errorField});
  return info;
}

}  // namespace

planning::Project loadJobProject(const JobSpec& spec) {
  planning::Project project;
  if (spec.part.demo) {
    project = planning::demoProject();
  } else {
    io::LoadPartParams params;
    params.conversion = spec.part.conversion;
    params.unit = spec.part.unit;
    io::LoadPartReport report;
    project = io::openProject(spec.part.file, params, &report);
    if (!project.part) throw InvalidInput(spec.part.file.string() + " holds no part");
    // A CAD file states its unit, so its size needs no second opinion.
    if (report.converted && !report.unitFromFile)
      warnIfOtherUnit(spec.part.file, report.fileDiagonal, params.unit,
                      "set \"units\" in the job's \"part\" object");
  }
  project.regions.clear();
  project.paths.clear();
  project.fields.clear();
  project.tools = spec.tools;
  return project;
}

std::vector<planning::Region> segmentJobPart(const ddf::DisplacementField& part,
                                             const planning::CurvatureField& curvature,
                                             const SegmentationSpec& spec) {
  switch (spec.method) {
    case SegmentationMethod::CurvatureType:
      return planning::segmentByCurvatureType(part, curvature, spec.params);
    case SegmentationMethod::ToolRadius:
      return planning::segmentByToolRadius(part, curvature, spec.toolRadiiMm, spec.params);
    case SegmentationMethod::WholePart:
      break;
  }
  std::vector<int> faces(static_cast<std::size_t>(part.faceCount()));
  std::iota(faces.begin(), faces.end(), 0);
  return planning::assignFaces({}, 0, faces, part.faceCount(), "whole part");
}

std::vector<int> selectRegions(const std::vector<planning::Region>& regions, const RegionJob& job,
                               const std::string& what) {
  const int count = static_cast<int>(regions.size());
  if (job.index) {
    if (*job.index >= count)
      throw InvalidInput(what + ": region " + std::to_string(*job.index) + " does not exist (" +
                         std::to_string(count) + " regions)");
    return {*job.index};
  }
  std::vector<int> out;
  for (int r = 0; r < count; ++r)
    if (job.name.empty() || regions[r].name == job.name) out.push_back(r);
  if (out.empty()) throw InvalidInput(what + ": no region named '" + job.name + "'");
  return out;
}

RegionPathInfo planRegion(planning::Project& project, const planning::CurvatureField& curvature,
                          int region, const RegionJob& job,
                          const planning::StreamlinePathParams& placement) {
  project.regions = planning::setRegionPlan(project.regions, region, job.plan);
  const ddf::DisplacementField& part = *project.part;
  const std::vector<std::uint8_t> mask = faceMaskOf(part, project.regions[region]);
  const planning::LineField field = regionField(part, curvature, job.plan, mask);
  RegionPathInfo info;
  if (job.method == LineMethod::Refined) {
    info = refinedPath(project, field, mask, job);
  } else {
    std::vector<planning::Streamline> lines = traceLines(part, field, mask, job);
    for (planning::Streamline& line : lines) planning::dropRepeatedPoints(line);
    std::erase_if(lines, [](const planning::Streamline& l) { return l.points.size() < 2; });
    if (lines.empty()) throw InvalidInput("no line with two points could be traced");
    if (job.link && lines.size() > 1) planning::orderLinesForCutting(part, lines, job.plan.linking);
    planning::StreamlinePathParams params = placement;
    const char* kind = job.method == LineMethod::Even ? "coverage" : "streamline family";
    params.name = std::string(kind) + " " + std::to_string(project.paths.size() + 1);
    const planning::Tool& tool = project.tools[static_cast<std::size_t>(job.plan.tool)];
    project.paths.push_back(
        planning::toolPathFromStreamlinesDetailed(part, lines, tool, job.plan.tool, params).path);
    info.lines = static_cast<int>(lines.size());
    for (const planning::Streamline& line : lines) info.lengthMm += line.lengthMm;
  }
  info.region = region;
  info.path = static_cast<int>(project.paths.size()) - 1;
  return info;
}

}  // namespace ddfcam::cli
