// SPDX-License-Identifier: MIT
// ddfcam-cli run: the stages in order with their timings; simulation and error map.
#include "job_runner.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/model/field_freshness.h>
#include <ddfcam/planning/model/simulation_states.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/workpiece.h>
#include <ddfcam/planning/tools/tool.h>

#include "job_inputs.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

namespace ddfcam::cli {

namespace {

using Clock = std::chrono::steady_clock;

/// Runs @p work as stage @p name: times it, prints "stage name: S s (summary)" on stderr and
/// nests any failure under "stage <name>".
void stage(JobResult& result, const std::string& name, const std::function<std::string()>& work) {
  const Clock::time_point start = Clock::now();
  std::string summary;
  try {
    summary = work();
  } catch (const Cancelled&) {
    throw;
  } catch (const std::exception&) {
    std::throw_with_nested(Error("stage " + name));
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  result.timings.push_back({name, seconds});
  std::fprintf(stderr, "ddfcam-cli run: %-13s %7.3f s  %s\n", name.c_str(), seconds,
               summary.c_str());
}

/// "0.02" for 0.02: the number as the workbench prints it (QString::number, 6 digits).
std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void setHeights(planning::Project& project, const std::vector<float>& heights,
                const std::string& state) {
  ddf::DisplacementField& part = *project.part;
  const std::size_t perFace = part.pointsPerFace();
  for (int f = 0; f < part.faceCount(); ++f) {
    const auto h = part.heights(f);
    std::copy_n(heights.begin() + static_cast<std::ptrdiff_t>(f * perFace), perFace, h.begin());
  }
  project.states.push_back({state, heights});
}

std::string planRegions(const JobSpec& spec, JobResult& result,
                        const planning::CurvatureField& curvature) {
  planning::Project& project = result.project;
  for (std::size_t j = 0; j < spec.regions.size(); ++j) {
    const std::string what = "regions[" + std::to_string(j) + "]";
    for (const int r : selectRegions(project.regions, spec.regions[j], what)) {
      try {
        result.paths.push_back(planRegion(project, curvature, r, spec.regions[j], spec.placement));
      } catch (const Cancelled&) {
        throw;
      } catch (const std::exception&) {
        std::throw_with_nested(Error(what + ": region '" + project.regions[r].name + "'"));
      }
    }
  }
  std::size_t poses = 0, lines = 0;
  for (const planning::ToolPath& p : project.paths) poses += p.poses.size();
  for (const RegionPathInfo& p : result.paths) lines += static_cast<std::size_t>(p.lines);
  return std::to_string(project.paths.size()) + " paths, " + std::to_string(lines) + " lines, " +
         std::to_string(poses) + " poses";
}

}  // namespace

std::vector<planning::GrindingReport> simulateJob(planning::Project& project,
                                                  const SimulationSpec& spec) {
  if (spec.allowanceMm) {
    if (!planning::designState(project.states))
      project.states.push_back({planning::kDesignStateName, project.part->allHeights()});
    const std::vector<float> raised =
        planning::workpieceWithAllowance(*project.part, *spec.allowanceMm).allHeights();
    setHeights(project, raised, planning::allowanceStateName(*spec.allowanceMm));
  }
  std::vector<planning::GrindingReport> reports;
  for (const planning::ToolPath& path : project.paths) {
    const planning::Tool& tool = project.tools.at(static_cast<std::size_t>(path.tool));
    ddf::DisplacementField part = *project.part;
    reports.push_back(
        planning::simulateGrinding(part, planning::toolMeshes(tool), path, spec.grinding));
    setHeights(project, part.allHeights(), planning::afterPathStateName(path.name));
  }
  return reports;
}

planning::ErrorStatistics errorMapJob(planning::Project& project, const ErrorMapSpec& spec) {
  const auto& states = project.states;
  if (states.empty()) throw InvalidInput("the project has no state to compare with");
  const planning::SimulationState* design = planning::designState(states);
  const std::vector<float> desired = design ? design->heights : states[0].heights;
  planning::ScalarField field = planning::deviationMap(*project.part, desired);
  field.name = "deviation";
  planning::markComputedFrom(field, *project.part);
  const planning::ErrorStatistics stats =
      planning::errorStatistics(field, *project.part, spec.band);
  project.fields.push_back(std::move(field));
  return stats;
}

JobResult runJobStages(const JobSpec& spec) {
  JobResult result;
  planning::Project& project = result.project;
  stage(result, "load", [&] {
    project = loadJobProject(spec);
    return project.partName + ": " + std::to_string(project.part->faceCount()) +
           " faces, m = " + std::to_string(project.part->raster().m);
  });
  planning::CurvatureField curvature;
  stage(result, "curvature", [&] {
    curvature = planning::computeCurvature(*project.part, planning::partCurvatureParams(project));
    return std::to_string(curvature.kMax.size()) + " raster points";
  });
  stage(result, "segmentation", [&] {
    project.regions = segmentJobPart(*project.part, curvature, spec.segmentation);
    return std::to_string(project.regions.size()) + " regions";
  });
  stage(result, "paths", [&] { return planRegions(spec, result, curvature); });
  if (spec.simulation.enabled)
    stage(result, "simulation", [&] {
      result.grinding = simulateJob(project, spec.simulation);
      double volume = 0;
      for (const auto& g : result.grinding) volume += g.removedVolumeMm3;
      return std::to_string(result.grinding.size()) + " paths ground, " + shortNumber(volume) +
             " mm^3 removed";
    });
  if (spec.errorMap.enabled)
    stage(result, "error map", [&] {
      result.errors = errorMapJob(project, spec.errorMap);
      return "max " + shortNumber(result.errors->maxMm) + " mm, min " +
             shortNumber(result.errors->minMm) + " mm, " +
             shortNumber(result.errors->inTolerancePercent) + " % in tolerance";
    });
  return result;
}

JobResult runJob(const JobSpec& spec, const JobOutputOptions& options) {
  JobResult result = runJobStages(spec);
  const Clock::time_point start = Clock::now();
  writeJobOutputs(spec, result, options);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::fprintf(stderr, "ddfcam-cli run: %-13s %7.3f s  %zu files\n", "outputs", seconds,
               result.written.size());
  return result;
}

}  // namespace ddfcam::cli
