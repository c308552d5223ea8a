// SPDX-License-Identifier: MIT
// ddfcam-cli run: the path file exports and the report of a job.
#pragma once

#include "job_runner.h"
#include "job_spec.h"

#include <string>

namespace ddfcam::cli {

/// @brief Writes the paths of @p result as @p spec says (one file, or one per path with
/// perRegion) and adds the files to result.written.
/// @throws InvalidInput from the writers; IoError if a file cannot be written.
void writePathExport(const ExportSpec& spec, JobResult& result);

/// @brief The report JSON: part, regions, tools, paths, simulation, error statistics, the
/// files written (relative to the report's directory) and notes; with @p timings also a
/// "timings" object (the only part that differs between two runs of the same job).
std::string jobReport(const JobSpec& spec, const JobResult& result, bool timings);

}  // namespace ddfcam::cli
