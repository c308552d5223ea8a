// SPDX-License-Identifier: MIT
// ddfcam-cli demo: the built-in batch job (resources/jobs/demo_job.json) on the demo part.
#include "arguments.h"
#include "command_run.h"
#include "commands.h"
#include "job_spec.h"

#include <filesystem>

namespace ddfcam::cli {
namespace {

constexpr const char* kDescription =
    "Runs the built-in batch job (resources/jobs/demo_job.json, see docs/batch_jobs.md) on the\n"
    "built-in demo part (a 40 x 30 mm free-form patch with 0.2 mm stock): the whole part as one\n"
    "region, lines along y 2 mm apart, a ball-end tool of radius 5 mm placed along them every\n"
    "1.5 mm, the part raised by a 0.02 mm stock allowance and ground (swept volumes), the error\n"
    "map against the surface before the raise. Writes into DIR: demo.ddfproj (opens in the\n"
    "workbench), demo_paths.csv, demo_paths.apt, demo_paths.ngc (5-axis A/C), demo_error_map.vtp,\n"
    "demo_report.json, and demo.png when a display and the workbench are available.";

Arguments options() {
  Arguments args("demo", "demo [--out DIR] [--no-timings]", kDescription);
  args.option("--out", "DIR", "output directory, created if needed")->default_str("ddfcam-demo");
  args.flag("--no-timings", "leave the \"timings\" object out of the report");
  return args;
}

std::string help() {
  return options().help();
}

int runDemo(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  args.expectPositionals(0, "no positional arguments");
  const std::filesystem::path dir = std::filesystem::absolute(*args.value("out"));
  const JobSpec spec = parseJobSpec(builtinDemoJob(), "demo_job.json", dir, dir);
  return runJobAndSummarize(spec, !args.has("no-timings"));
}

}  // namespace

const Command kDemoCommand{"demo", "run the built-in batch job on the demo part", &help, &runDemo};

}  // namespace ddfcam::cli
