// SPDX-License-Identifier: MIT
// ddfcam-cli run: the path files of a job (CSV, APT/CLDATA, G-code) from the project's paths.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/planning/placement/cl_program_builder.h>

#include "job_exports.h"

#include <set>

namespace ddfcam::cli {

namespace {

/// The writer options of @p spec.
io::PathWriteParams writeParams(const ExportSpec& spec) {
  io::PathWriteParams params;
  const LengthUnit unit = spec.inches ? LengthUnit::Inch : LengthUnit::Millimetre;
  switch (spec.format) {
    case ExportFormat::Csv:
      params.format = io::PathFormat::Csv;
      params.csv = {.decimals = spec.decimals, .unit = unit};
      break;
    case ExportFormat::Apt:
      params.format = io::PathFormat::Apt;
      params.apt.coordinateDecimals = spec.decimals;
      params.apt.vectorDecimals = spec.vectorDecimals;
      params.apt.unit = unit;
      params.apt.feedUnitFirst = spec.dialect == "nx";
      break;
    case ExportFormat::Gcode:
      params.format = io::PathFormat::GCode;
      params.gcode.mode = spec.dialect == "3axis" ? io::GCodeWriteParams::Mode::ThreeAxis
                                                  : io::GCodeWriteParams::Mode::FiveAxis;
      params.gcode.kinematics.pair =
          spec.dialect == "5axis-bc" ? planning::RotaryPair::BC : planning::RotaryPair::AC;
      params.gcode.unit = unit;
      params.gcode.decimals = spec.decimals;
      break;
  }
  return params;
}

}  // namespace

void writePathExport(const ExportSpec& spec, JobResult& result) {
  planning::ExportSelection selection;
  selection.pointKind =
      spec.toolPoint ? planning::ClPointKind::ToolReference : planning::ClPointKind::Contact;
  selection.perRegion = spec.perRegion;
  const std::vector<planning::NamedProgram> programs =
      planning::programsForExport(result.project, selection);
  if (programs.empty()) throw InvalidInput("there is no path to export");
  std::set<std::filesystem::path> used;
  for (const planning::NamedProgram& named : programs) {
    const std::filesystem::path file =
        programs.size() == 1 ? spec.file : io::toolPathCsvFileFor(spec.file, named.name);
    if (!used.insert(file).second)
      throw InvalidInput("two programs would be written to " + file.filename().string());
    // programsForExport numbers the tools from 1 in project order.
    const auto tool = static_cast<std::size_t>(named.program.toolNumber - 1);
    if (tool >= result.project.tools.size())
      throw InvalidInput("program '" + named.name + "' names no project tool");
    io::writePathFile(named.program, result.project.tools[tool], file, writeParams(spec));
    result.written.push_back(file);
  }
}

}  // namespace ddfcam::cli
