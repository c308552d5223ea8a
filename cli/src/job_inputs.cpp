// SPDX-License-Identifier: MIT
// ddfcam-cli run: what a job's part, segmentation and region entries become: the project,
// the regions, and the region plans handed to the planning pipeline.
#include "job_inputs.h"

#include "unit_options.h"

#include <ddfcam/error.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/io/project/project_loader.h>
#include <ddfcam/log.h>
#include <ddfcam/planning/analysis/region_editing.h>
#include <ddfcam/planning/analysis/segmentation.h>
#include <ddfcam/planning/lines/spacing_refinement.h>
#include <ddfcam/planning/model/demo_project.h>
#include <ddfcam/planning/model/field_freshness.h>
#include <ddfcam/planning/pipeline/region_planning.h>

#include <algorithm>
#include <numeric>

namespace ddfcam::cli {

namespace {

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
  planning::ScalarField error{"refinement error", "mm", true, result.errorField, {}};
  planning::markComputedFrom(error, *project.part);
  project.fields.push_back(std::move(error));
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
  const std::vector<std::uint8_t> mask = planning::regionFaceMask(part, project.regions[region]);
  const planning::RegionFields fields = planning::regionFields(part, curvature, job.plan, mask);
  RegionPathInfo info;
  if (job.method == LineMethod::Refined) {
    info = refinedPath(project, fields.field, mask, job);
  } else {
    const planning::Tool& tool = project.tools[static_cast<std::size_t>(job.plan.tool)];
    const planning::LineSpacing spacing =
        planning::regionSpacing(part, curvature, fields, job.plan, tool);
    if (!spacing.note.empty())
      log(LogLevel::Info, "region " + std::to_string(region) + ": " + spacing.note);
    planning::RegionLinesParams lines;
    lines.seeding = job.method == LineMethod::Even ? planning::LineSeeding::Coverage
                                                   : planning::LineSeeding::Family;
    lines.tracing = job.tracing;
    planning::StreamlinePathParams params = placement;
    const char* kind = job.method == LineMethod::Even ? "coverage" : "streamline family";
    params.name = std::string(kind) + " " + std::to_string(project.paths.size() + 1);
    planning::RegionPath path = planning::regionToolPath(
        part, planning::planRegionLines(part, fields, mask, spacing, lines), job.plan, tool,
        job.plan.tool, job.link, params);
    info.lines = static_cast<int>(path.lines.size());
    info.lengthMm = path.cuttingLengthMm;
    project.paths.push_back(std::move(path.placed.path));
  }
  info.region = region;
  info.path = static_cast<int>(project.paths.size()) - 1;
  return info;
}

}  // namespace ddfcam::cli
