// SPDX-License-Identifier: MIT
// ddfcam-cli run: running a parsed job with the summary on stdout (shared with demo).
#pragma once

#include "job_spec.h"

namespace ddfcam::cli {

/// @brief Runs @p spec (runJob), prints a summary and the written files on stdout.
/// @param timings write the "timings" object into the report.
/// @returns the exit code 0. @throws ddfcam::Error from the stages and writers.
int runJobAndSummarize(const JobSpec& spec, bool timings);

}  // namespace ddfcam::cli
