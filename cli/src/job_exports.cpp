// SPDX-License-Identifier: MIT
// ddfcam-cli run: the files of a job: project, path exports, error map, screenshots, report.
#include <ddfcam/error.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/io/results/vtp_writer.h>

#include "error_map_vtp.h"
#include "job_exports.h"
#include "job_runner.h"

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace ddfcam::cli {

namespace {

void writeErrorMap(const JobSpec& spec, JobResult& result) {
  if (!spec.errorMap.enabled || !spec.errorMap.vtp) return;
  const planning::ScalarField* deviation = nullptr;
  for (const planning::ScalarField& f : result.project.fields)
    if (f.name == "deviation") deviation = &f;
  if (!deviation) return;
  io::VtpPointData data;
  const ddf::TriangleMesh mesh =
      errorMapMesh(*result.project.part, *deviation, spec.errorMap.band, data);
  io::writeVtp(mesh, data, *spec.errorMap.vtp);
  result.written.push_back(*spec.errorMap.vtp);
}

std::string quoted(const std::filesystem::path& p) {
  std::string out = "'";
  for (const char c : p.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// The workbench renders each screenshot of the saved project (ddfcam --screenshot), so the
/// pictures come from the same adapters as the GUI.
void writeScreenshots(const JobSpec& spec, JobResult& result, const JobOutputOptions& options) {
  if (spec.screenshots.empty()) return;
  const char* display = std::getenv("DISPLAY");
  const std::filesystem::path workbench = options.cliExecutable.parent_path() / "ddfcam";
  if (!display || !*display) {
    result.notes.push_back("screenshots skipped: no display");
    return;
  }
  if (options.cliExecutable.empty() || !std::filesystem::exists(workbench)) {
    result.notes.push_back("screenshots skipped: no workbench executable next to ddfcam-cli");
    return;
  }
  // The error map, when there is one, is what a screenshot of a job is for.
  const bool deviation = std::ranges::any_of(
      result.project.fields, [](const planning::ScalarField& f) { return f.name == "deviation"; });
  char band[160];
  std::snprintf(band, sizeof band, " --field deviation --band %.17g,%.17g ",
                spec.errorMap.band.lowerMm, spec.errorMap.band.upperMm);
  for (const std::filesystem::path& png : spec.screenshots) {
    const std::string command = quoted(workbench) + " --screenshot " + quoted(png) +
                                (deviation ? band : " ") + quoted(spec.project) +
                                " > /dev/null 2>&1 < /dev/null";
    const int status = std::system(command.c_str());
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !std::filesystem::exists(png))
      throw IoError("the workbench could not render the screenshot " + png.string());
    result.written.push_back(png);
  }
}

}  // namespace

void writeJobOutputs(const JobSpec& spec, JobResult& result, const JobOutputOptions& options) {
  std::error_code ec;
  std::filesystem::create_directories(spec.project.parent_path(), ec);
  if (ec)
    throw IoError("cannot create the output directory " + spec.project.parent_path().string() +
                  ": " + ec.message());
  io::writeProject(result.project, spec.project);
  result.written.push_back(spec.project);
  for (std::size_t e = 0; e < spec.exports.size(); ++e) {
    try {
      writePathExport(spec.exports[e], result);
    } catch (const std::exception&) {
      std::throw_with_nested(
          Error("exports[" + std::to_string(e) + "]: " + spec.exports[e].file.filename().string()));
    }
  }
  writeErrorMap(spec, result);
  writeScreenshots(spec, result, options);
  if (!spec.report) return;
  result.written.push_back(*spec.report);
  const std::string text = jobReport(spec, result, options.timings);
  std::ofstream out(*spec.report, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw IoError("cannot write the report " + spec.report->string());
}

}  // namespace ddfcam::cli
