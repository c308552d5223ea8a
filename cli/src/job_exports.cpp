// SPDX-License-Identifier: MIT
// ddfcam-cli run: the files of a job: project, path exports, error map, screenshots, report.
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/io/project_file.h>
#include <ddfcam/io/vtp_writer.h>

#include "job_exports.h"
#include "job_runner.h"

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>

namespace ddfcam::cli {

namespace {

/// The produced surface along its raster lattice with the deviation of each point's copy in
/// the lowest-index face, and its tolerance class (-1 overcut, 0 in tolerance, 1 material left).
ddf::TriangleMesh errorMapMesh(const ddf::DisplacementField& produced,
                               const planning::ScalarField& deviation,
                               const planning::ToleranceBand& band, io::VtpPointData& data) {
  ddf::RasterMesh raster = ddf::extractRasterMesh(produced);
  const std::size_t perFace = produced.pointsPerFace();
  std::vector<float> values, classes;
  for (const ddf::PointId p : raster.vertexPoint) {
    int face = produced.faceCount();
    float value = std::numeric_limits<float>::quiet_NaN();
    produced.topology().forEachCopy(p, [&](ddf::PointCopy c) {
      if (c.face >= face) return;
      face = c.face;
      value = deviation.values[static_cast<std::size_t>(c.face) * perFace + c.local];
    });
    values.push_back(value);
    const planning::ToleranceClass cls = planning::classify(value, band);
    classes.push_back(std::isnan(value)                               ? value
                      : cls == planning::ToleranceClass::Overcut      ? -1.0f
                      : cls == planning::ToleranceClass::MaterialLeft ? 1.0f
                                                                      : 0.0f);
  }
  data.scalars.push_back({"deviation_mm", std::move(values)});
  data.scalars.push_back({"tolerance_class", std::move(classes)});
  return std::move(raster.mesh);
}

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
  for (const std::filesystem::path& png : spec.screenshots) {
    const std::string command = quoted(workbench) + " --screenshot " + quoted(png) + " " +
                                quoted(spec.project) + " > /dev/null 2>&1 < /dev/null";
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
