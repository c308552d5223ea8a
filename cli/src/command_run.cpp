// SPDX-License-Identifier: MIT
// ddfcam-cli run: a whole batch job (JSON) headless, from the part to the path files.
#include <ddfcam/error.h>

#include "arguments.h"
#include "command_run.h"
#include "commands.h"
#include "job_runner.h"
#include "job_spec.h"

#include <chrono>
#include <cstdio>

namespace ddfcam::cli {

namespace {

constexpr const char* kDescription =
    "Runs the batch job JOB.json headless: loads the part (a file or \"demo\"), computes the\n"
    "curvature, segments the part into regions, plans every region (flow field, seeding or\n"
    "spacing refinement, tool placement), simulates the grinding, computes the error map and\n"
    "writes the project (.ddfproj, opens in the workbench), the path files (CSV, APT, G-code),\n"
    "the error map (.vtp), a report (JSON) and, with a display, screenshots rendered by the\n"
    "workbench. One line per stage with its time goes to stderr. Relative input paths in the job\n"
    "resolve against the job file's directory; outputs too unless --out is given. The job file\n"
    "format is described in docs/batch_jobs.md.";

Arguments options() {
  Arguments args("run", "run JOB.json [--out DIR] [--no-timings]", kDescription);
  args.positional("JOB.json", "batch job file (JSON)");
  args.option("--out", "DIR", "directory of the outputs, created if needed");
  args.flag("--no-timings",
            "leave the \"timings\" object out of the report (byte-identical reports)");
  return args;
}

std::string help() {
  return options().help();
}

int runRun(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  args.expectPositionals(1, "a job file (JSON)");
  std::optional<std::filesystem::path> out;
  if (const auto dir = args.value("out")) out = std::filesystem::absolute(*dir);
  const JobSpec spec = readJobSpec(args.positionals()[0], out);
  return runJobAndSummarize(spec, !args.has("no-timings"));
}

}  // namespace

int runJobAndSummarize(const JobSpec& spec, bool timings) {
  const auto start = std::chrono::steady_clock::now();
  JobOutputOptions options;
  options.timings = timings;
  std::error_code ec;
  options.cliExecutable = std::filesystem::read_symlink("/proc/self/exe", ec);
  const JobResult result = runJob(spec, options);
  std::size_t poses = 0;
  for (const planning::ToolPath& p : result.project.paths) poses += p.poses.size();
  std::printf("job: %s, %zu regions, %zu paths, %zu poses\n", result.project.partName.c_str(),
              result.project.regions.size(), result.project.paths.size(), poses);
  if (result.errors)
    std::printf("error map: max %.4g mm, min %.4g mm, %.3g %% in tolerance\n", result.errors->maxMm,
                result.errors->minMm, result.errors->inTolerancePercent);
  for (const std::filesystem::path& f : result.written) std::printf("wrote %s\n", f.c_str());
  for (const std::string& n : result.notes) std::printf("note: %s\n", n.c_str());
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  std::printf("done in %.2f s\n", elapsed.count());
  return 0;
}

const Command kRunCommand{"run", "run a batch job (JSON): plan, simulate, export", &help, &runRun};

}  // namespace ddfcam::cli
