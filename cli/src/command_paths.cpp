// SPDX-License-Identifier: MIT
// ddfcam-cli paths: converts a tool-path file between formats (CSV, APT/CLDATA, G-code).
#include <ddfcam/error.h>
#include <ddfcam/io/programs/apt_writer.h>
#include <ddfcam/io/programs/machine_file.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/planning/placement/cutter_tool.h>

#include "arguments.h"
#include "commands.h"
#include "plan_tool.h"
#include "simulate_import.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

namespace ddfcam::cli {
namespace {

constexpr const char* kDescription =
    "Converts a tool-path file: reads IN (a CSV as written by 'ddfcam-cli plan' or a plain\n"
    "x,y,z[,i,j,k] table, APT/CLDATA such as NX CLSF or Pro/CLfile, ROS toolpath YAML or a\n"
    "FANUC .ls program; the format is detected from the extension and the content) and writes\n"
    "OUT as CSV, APT/CLDATA or G-code. Prints the reader's warnings on stderr and one summary\n"
    "line: points, paths, unit and bounds (mm) of the program read.";

/// --tool, --radius, --corner-radius in their own group: the cutter G-code needs.
void addToolOptions(Arguments& args) {
  const std::string group =
      "tool (G-code needs a cutter; default: IN's CUTTER record; APT: "
      "written as CUTTER)";
  args.option("--tool", "KIND",
              "ball_end, flat_end or torus (= torus_cutter) for G-code; any\n"
              "kind of 'ddfcam-cli plan' for APT")
      ->group(group);
  args.option("--radius", "MM", "tool radius (default 5)")->check(positiveNumber())->group(group);
  args.option("--corner-radius", "MM", "torus corner radius (default radius / 4)")
      ->check(positiveNumber())
      ->group(group);
}

Arguments options() {
  Arguments args("paths", "paths IN -o OUT [options]", kDescription);
  args.positional("IN", "input path file");
  args.option("-o,--output", "FILE", "the converted file (required)");
  args.option("--format", "csv|apt|gcode",
              "output format (default from OUT's extension: .csv, .apt/.cls/\n"
              ".cl/.ncl/.aptsource, .ngc/.nc/.gcode; else csv)");
  args.option("--units", "mm|in",
              "unit of OUT (default IN's unit; metres become mm for APT and\nG-code)");
  args.option("--decimals", "N",
              "digits after the point of positions and feeds (CSV 0..17,\n"
              "default 6; APT 4..6, default 4; G-code 1..8, default 4)");
  args.option("--vector-decimals", "N", "APT: digits of tool-axis components, 6..9 (default 7)")
      ->check(integerIn(6, 9));
  args.option("--dialect", "NAME",
              "APT: standard (FEDRAT/f,MMPM, default) or nx (FEDRAT/MMPM,f);\n"
              "G-code: 3axis, 5axis-ac or 5axis-bc (table-table machine with\n"
              "the pivot at the origin; default 5axis-ac when IN has tool\n"
              "axes, else 3axis)");
  args.option("--machine", "FILE",
              "G-code for the 5-axis machine described in FILE (JSON: rotary\n"
              "axes and their directions, pivot, offsets, limits, preferred\n"
              "solution, TCP; samples in resources/machines/, format in\n"
              "docs/machines.md); replaces --dialect");
  args.option("--in-units", "mm|in|m",
              "IN's numbers are really in this unit (overrides what IN says)");
  addToolOptions(args);
  return args;
}

std::string help() {
  return options().help();
}

std::optional<LengthUnit> unitOption(const Arguments& args, const std::string& name, bool metre) {
  const std::optional<std::string> text = args.value(name);
  if (!text) return std::nullopt;
  if (*text == "mm") return LengthUnit::Millimetre;
  if (*text == "in") return LengthUnit::Inch;
  if (metre && *text == "m") return LengthUnit::Metre;
  throw UsageError("--" + name + " " + *text + ": expected " + (metre ? "mm|in|m" : "mm|in"));
}

io::PathFormat outputFormat(const Arguments& args, const std::filesystem::path& out) {
  if (const auto name = args.value("format")) {
    if (*name == "csv") return io::PathFormat::Csv;
    if (*name == "apt") return io::PathFormat::Apt;
    if (*name == "gcode") return io::PathFormat::GCode;
    throw UsageError("--format " + *name + ": expected csv|apt|gcode");
  }
  std::string ext = out.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  // .txt is ambiguous (CSV or APT): the first listed format wins, CSV.
  for (const io::PathFormat f : {io::PathFormat::Csv, io::PathFormat::Apt, io::PathFormat::GCode})
    for (const std::string& e : io::pathFileExtensions(f))
      if (e == ext) return f;
  return io::PathFormat::Csv;
}

// The dialect for @p format, checked against the names it has.
std::string dialect(const Arguments& args, io::PathFormat format, bool multiAxis) {
  const std::optional<std::string> name = args.value("dialect");
  if (format == io::PathFormat::Csv) {
    if (name) throw UsageError("--dialect: CSV has no dialect");
    return "";
  }
  if (format == io::PathFormat::Apt) {
    if (name && *name != "standard" && *name != "nx")
      throw UsageError("--dialect " + *name + ": expected standard|nx for APT");
    return name.value_or("standard");
  }
  if (name && *name != "3axis" && *name != "5axis-ac" && *name != "5axis-bc")
    throw UsageError("--dialect " + *name + ": expected 3axis|5axis-ac|5axis-bc for G-code");
  return name.value_or(multiAxis ? "5axis-ac" : "3axis");
}

// --in-units: the file's numbers taken in @p unit instead of its own: positions and feeds
// rescaled to mm from that unit.
planning::ClProgram inActualUnit(planning::ClProgram program, std::optional<LengthUnit> unit) {
  if (!unit) return program;
  const double scale = millimetresPer(*unit) / millimetresPer(program.sourceUnit);
  for (planning::ClPoint& p : program.points) {
    p.positionMm *= scale;
    p.feedMmPerMin *= scale;
  }
  program.sourceUnit = *unit;
  return program;
}

// --tool options, else the file's CUTTER record, else none.
std::optional<planning::Tool> toolOf(const Arguments& args, const planning::ClProgram& program) {
  if (args.has("tool")) return parsePlanTool(args).tool;
  for (const char* name : {"radius", "corner-radius"})
    if (args.has(name)) throw UsageError(std::string("--") + name + " needs --tool KIND");
  if (program.cutter) return planning::toolFromCutter(*program.cutter, program.toolName);
  return std::nullopt;
}

io::PathWriteParams writeParams(const Arguments& args, io::PathFormat format,
                                const planning::ClProgram& program) {
  io::PathWriteParams p;
  p.format = format;
  const std::string kind = dialect(args, format, program.multiAxis());
  LengthUnit unit = unitOption(args, "units", false).value_or(program.sourceUnit);
  if (unit == LengthUnit::Metre && format != io::PathFormat::Csv) unit = LengthUnit::Millimetre;
  if (args.has("vector-decimals") && format != io::PathFormat::Apt)
    throw UsageError("--vector-decimals applies to --format apt only");
  p.csv.unit = p.apt.unit = p.gcode.unit = unit;
  if (format == io::PathFormat::Csv)
    p.csv.decimals = args.integer("decimals", p.csv.decimals, 0, 17);
  if (format == io::PathFormat::Apt)
    p.apt.coordinateDecimals = args.integer("decimals", p.apt.coordinateDecimals, 4, 6);
  p.apt.vectorDecimals = args.integer("vector-decimals", p.apt.vectorDecimals);
  p.apt.feedUnitFirst = kind == "nx";
  if (format == io::PathFormat::GCode)
    p.gcode.decimals = args.integer("decimals", p.gcode.decimals, 1, 8);
  p.gcode.mode = kind == "3axis" ? io::GCodeWriteParams::Mode::ThreeAxis
                                 : io::GCodeWriteParams::Mode::FiveAxis;
  p.gcode.kinematics.pair =
      kind == "5axis-bc" ? planning::RotaryPair::BC : planning::RotaryPair::AC;
  if (const auto machine = args.value("machine")) {
    if (format != io::PathFormat::GCode) throw UsageError("--machine applies to G-code output");
    if (args.has("dialect")) throw UsageError("--machine replaces --dialect; give one of them");
    io::applyMachine(io::readMachineFile(*machine), p.gcode);
  }
  return p;
}

// Writes with the tool when one is known; APT without one keeps the file's CUTTER (or none).
void write(planning::ClProgram program, const std::optional<planning::Tool>& tool,
           const std::filesystem::path& out, const io::PathWriteParams& params) {
  switch (params.format) {
    case io::PathFormat::GCode:
      if (!tool)
        throw InvalidInput(
            "G-code needs a cutter: the input has no CUTTER record; give --tool "
            "ball_end|flat_end|torus --radius MM");
      break;
    case io::PathFormat::Apt:
      if (program.pointKind == planning::ClPointKind::Contact)
        throw InvalidInput(
            "APT/CLDATA needs tool reference points, and the input holds contact "
            "points: write it with 'ddfcam-cli plan --point reference', or convert "
            "it to CSV or G-code");
      if (!tool) return io::writeApt(program, out, params.apt);
      program.cutter = planning::aptCutter(*tool);
      break;
    default:
      if (!program.toolChanges.empty())
        std::fprintf(stderr,
                     "warning: %s: CSV has no tool column; the program's %zu tool changes are "
                     "not kept (write APT or G-code to keep them)\n",
                     out.string().c_str(), program.toolChanges.size());
      if (!tool) return io::writePathFile(program, planning::Tool{}, out, params);
  }
  io::writePathFile(program, *tool, out, params);
}

void printSummary(const std::filesystem::path& in, const planning::ClProgram& program,
                  io::PathFormat inFormat, const std::filesystem::path& out,
                  io::PathFormat outFormat) {
  ddf::Vec3 lo = ddf::Vec3::Constant(INFINITY), hi = ddf::Vec3::Constant(-INFINITY);
  for (const planning::ClPoint& p : program.points) {
    lo = lo.cwiseMin(p.positionMm);
    hi = hi.cwiseMax(p.positionMm);
  }
  std::printf(
      "%s (%s): %zu points, %d paths, unit %s, bounds [%.6g, %.6g] x [%.6g, %.6g] x "
      "[%.6g, %.6g] mm -> %s (%s)\n",
      in.string().c_str(), std::string(io::pathFormatName(inFormat)).c_str(), program.points.size(),
      program.pathCount(), std::string(unitSymbol(program.sourceUnit)).c_str(), lo.x(), hi.x(),
      lo.y(), hi.y(), lo.z(), hi.z(), out.string().c_str(),
      std::string(io::pathFormatName(outFormat)).c_str());
}

int runPaths(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  args.expectPositionals(1, "an input path file");
  const std::filesystem::path in = args.positionals()[0];
  const std::filesystem::path out = args.required("output");
  const io::PathFormat format = outputFormat(args, out);
  const io::PathFile read = io::readPathFile(in);
  printPathWarnings(in, read.program.warnings);
  const planning::ClProgram program =
      inActualUnit(read.program, unitOption(args, "in-units", true));
  const io::PathWriteParams params = writeParams(args, format, program);
  write(program, toolOf(args, program), out, params);
  printSummary(in, program, read.format, out, format);
  return 0;
}

}  // namespace

const Command kPathsCommand{"paths",
                            "convert tool-path files: CSV, APT/CLDATA, YAML, .ls -> "
                            "CSV, APT, G-code",
                            &help, &runPaths};

}  // namespace ddfcam::cli
