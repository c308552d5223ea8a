// SPDX-License-Identifier: MIT
// ddfcam-cli run: the stages of a batch job (the workbench panels' library calls, headless)
// and the files they write.
#pragma once

#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>

#include "job_spec.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief Wall time of one stage.
struct StageTiming {
  std::string stage;     ///< e.g. "load", "segmentation", "simulation"
  double seconds = 0.0;  ///< wall time, s
};

/// @brief What the job made for one region job.
struct RegionPathInfo {
  int region = -1;        ///< index into Project::regions
  int path = -1;          ///< index into Project::paths
  int lines = 0;          ///< streamlines placed
  double lengthMm = 0.0;  ///< summed streamline length, mm
};

/// @brief The result of runJob(): the project and what each stage reported.
struct JobResult {
  planning::Project project;                        ///< part, regions, tools, paths, states, fields
  std::vector<StageTiming> timings;                 ///< per stage, in order
  std::vector<RegionPathInfo> paths;                ///< one per path of the project, in order
  std::vector<planning::GrindingReport> grinding;   ///< one per simulated path
  std::optional<planning::ErrorStatistics> errors;  ///< error map statistics
  std::vector<std::filesystem::path> written;       ///< files written, in order
  std::vector<std::string> notes;                   ///< e.g. "screenshots skipped: no display"
};

/// @brief Runs the planning stages of @p spec (load, curvature, segmentation, flow field and
/// lines per region, placement, simulation, error map) with the library calls and parameter
/// structs of the workbench panels, printing one line per stage on stderr.
/// @throws ddfcam::Error from the stages, with the stage named.
JobResult runJobStages(const JobSpec& spec);

/// @brief Options of writeJobOutputs().
struct JobOutputOptions {
  bool timings = true;  ///< write the "timings" object into the report (default true)
  /// The ddfcam-cli executable; the workbench `ddfcam` next to it renders the screenshots.
  std::filesystem::path cliExecutable;
};

/// @brief Writes the project, the path exports, the error map .vtp, the screenshots and the
/// report of @p result (adds each file to result.written).
/// @throws IoError if a file cannot be written; InvalidInput from the writers.
void writeJobOutputs(const JobSpec& spec, JobResult& result, const JobOutputOptions& options);

/// @brief runJobStages() then writeJobOutputs().
JobResult runJob(const JobSpec& spec, const JobOutputOptions& options);

}  // namespace ddfcam::cli
