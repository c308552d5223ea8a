// SPDX-License-Identifier: MIT
// ddfcam gui: the export options (checks, settings) and the export itself; formats live in io/.
#include <ddfcam/gui/path_export_dialog.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/console_dock.h>
#include <ddfcam/gui/project_actions.h>
#include <ddfcam/io/programs/machine_file.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/io/project/project_loader.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/planning/placement/cl_program_builder.h>

#include <QDir>
#include <QFileInfo>
#include <QSettings>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>

namespace ddfcam::gui {

namespace {

bool dialectBelongs(PathExportFormat format, PathExportDialect dialect) {
  const bool apt = dialect == PathExportDialect::AptStandard || dialect == PathExportDialect::AptNx;
  if (format == PathExportFormat::Apt) return apt;
  if (format == PathExportFormat::GCode) return !apt;
  return true;  // CSV has no dialect; any value is ignored
}

QString unitKey(LengthUnit unit) {
  return QString::fromUtf8(unitSymbol(unit).data(), static_cast<int>(unitSymbol(unit).size()));
}

bool isCutter(planning::ToolKind kind) {
  return kind == planning::ToolKind::BallEnd || kind == planning::ToolKind::FlatEnd ||
         kind == planning::ToolKind::TorusCutter;
}

QString quoted(const std::string& name) {
  return "'" + QString::fromStdString(name) + "'";
}

// The problem of one chosen path for the chosen format, or empty.
QString pathProblem(const planning::Project& project, const planning::ToolPath& path,
                    const PathExportOptions& o) {
  if (path.tool < 0 || path.tool >= static_cast<int>(project.tools.size()))
    return QObject::tr("Path %1 refers to tool %2, which the project does not have.")
        .arg(quoted(path.name))
        .arg(path.tool + 1);
  const planning::Tool& tool = project.tools[static_cast<std::size_t>(path.tool)];
  if (o.format != PathExportFormat::GCode) return {};
  if (!isCutter(tool.kind))
    return QObject::tr(
               "G-code is written for cutters (ball-end, flat-end, torus); path %1 uses "
               "%2, which is not one. Export it as CSV or APT.")
        .arg(quoted(path.name), quoted(tool.name));
  if (o.dialect != PathExportDialect::GCode3Axis || !o.machineFile.isEmpty()) return {};
  const ddf::Vec3 spindle = planning::spindleAxisInToolFrame(tool.kind);
  for (std::size_t i = 0; i < path.poses.size(); ++i) {
    const ddf::Vec3 axis = (path.poses[i].pose.linear() * spindle).normalized();
    const double tiltDeg = std::acos(std::clamp(axis.z(), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    if (tiltDeg > 1e-6)
      return QObject::tr(
                 "3-axis G-code needs a vertical tool; path %1 tilts it by %2 degrees "
                 "at pose %3. Choose a 5-axis machine.")
          .arg(quoted(path.name))
          .arg(tiltDeg, 0, 'f', 1)
          .arg(i + 1);
  }
  return {};
}

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(path.toStdU16String());
}

QString fromPath(const std::filesystem::path& path) {
  return QString::fromStdU16String(path.u16string());
}

// Files of the programs: the chosen file for a single program, else one per program named
// after it (as the CSV writer names its files), made unique.
std::vector<std::filesystem::path> exportFiles(const std::vector<planning::NamedProgram>& programs,
                                               const QString& filePath) {
  std::vector<std::filesystem::path> files;
  if (programs.size() == 1) return {toPath(filePath)};
  std::set<std::filesystem::path> used;
  for (const auto& named : programs) {
    std::filesystem::path file = io::toolPathCsvFileFor(toPath(filePath), named.name);
    for (int n = 2; used.count(file) > 0; ++n)
      file = io::toolPathCsvFileFor(toPath(filePath), named.name + "_" + std::to_string(n));
    used.insert(file);
    files.push_back(file);
  }
  return files;
}

io::PathWriteParams writeParams(const PathExportOptions& o) {
  io::PathWriteParams params;
  params.format = o.format == PathExportFormat::Csv   ? io::PathFormat::Csv
                  : o.format == PathExportFormat::Apt ? io::PathFormat::Apt
                                                      : io::PathFormat::GCode;
  params.csv.decimals = o.coordinateDecimals;
  params.csv.unit = o.unit;
  params.apt.coordinateDecimals = o.coordinateDecimals;
  params.apt.vectorDecimals = o.vectorDecimals;
  params.apt.unit = o.unit;
  params.apt.feedUnitFirst = o.dialect == PathExportDialect::AptNx;
  params.gcode.unit = o.unit;
  params.gcode.decimals = o.coordinateDecimals;
  params.gcode.mode = o.dialect == PathExportDialect::GCode3Axis
                          ? io::GCodeWriteParams::Mode::ThreeAxis
                          : io::GCodeWriteParams::Mode::FiveAxis;
  params.gcode.kinematics.pair = o.dialect == PathExportDialect::GCode5AxisBC
                                     ? planning::RotaryPair::BC
                                     : planning::RotaryPair::AC;
  if (o.format == PathExportFormat::GCode && !o.machineFile.isEmpty())
    io::applyMachine(io::readMachineFile(toPath(o.machineFile)), params.gcode);
  return params;
}

// The problem with the machine file of G-code options, or empty.
QString machineProblem(const PathExportOptions& o) {
  if (o.format != PathExportFormat::GCode || o.machineFile.isEmpty()) return {};
  try {
    io::readMachineFile(toPath(o.machineFile));
  } catch (const std::exception& e) {
    return QObject::tr("The machine file cannot be used: %1").arg(QString::fromUtf8(e.what()));
  }
  return {};
}

}  // namespace

QString pathExportProblem(const planning::Project& project, const PathExportOptions& o) {
  if (project.paths.empty()) return QObject::tr("The project has no tool paths to export.");
  if (o.paths.empty()) return QObject::tr("Choose at least one path.");
  std::size_t poses = 0;
  for (int index : o.paths) {
    if (index < 0 || index >= static_cast<int>(project.paths.size()))
      return QObject::tr("There is no path %1 in the project.").arg(index + 1);
    const auto& path = project.paths[static_cast<std::size_t>(index)];
    poses += path.poses.size();
    if (const QString problem = pathProblem(project, path, o); !problem.isEmpty()) return problem;
  }
  if (poses == 0) return QObject::tr("The chosen paths have no poses.");
  if (const QString problem = machineProblem(o); !problem.isEmpty()) return problem;
  if (o.filePath.isEmpty()) return QObject::tr("Choose the file to write.");
  const QFileInfo info(o.filePath);
  if (!info.absoluteDir().exists())
    return QObject::tr("The folder %1 does not exist.").arg(info.absolutePath());
  if (info.isDir()) return QObject::tr("%1 is a folder; choose a file name.").arg(o.filePath);
  return {};
}

QStringList exportPaths(const planning::Project& project, const PathExportOptions& options) {
  const PathExportOptions o = normalisedExportOptions(options);
  if (const QString problem = pathExportProblem(project, o); !problem.isEmpty())
    throw InvalidInput(problem.toStdString());
  planning::ExportSelection selection;
  selection.pointKind = o.point;
  selection.perRegion = o.grouping == PathExportGrouping::FilePerRegion;
  selection.paths = o.paths;
  const std::vector<planning::NamedProgram> programs =
      planning::programsForExport(project, selection);
  const std::vector<std::filesystem::path> files = exportFiles(programs, o.filePath);
  const io::PathWriteParams params = writeParams(o);
  QStringList written;
  for (std::size_t i = 0; i < programs.size(); ++i) {
    const planning::ClProgram& program = programs[i].program;
    // programsForExport numbers tools from 1 (project index + 1).
    const auto& tool = project.tools.at(static_cast<std::size_t>(program.toolNumber - 1));
    try {
      io::writePathFile(program, tool, files[i], params);
    } catch (...) {
      std::throw_with_nested(
          IoError("cannot export '" + programs[i].name + "' to '" + files[i].string() + "'"));
    }
    written << fromPath(files[i]);
  }
  return written;
}

QString exportMachineName(const PathExportOptions& o) {
  if (o.format != PathExportFormat::GCode || o.machineFile.isEmpty()) return {};
  try {
    const io::MachineSetup m = io::readMachineFile(toPath(o.machineFile));
    const bool ac = m.kinematics.pair == planning::RotaryPair::AC;
    return QObject::tr("%1: %2/C, %3 deg to %4 deg, X Y Z as %5")
        .arg(QString::fromStdString(m.name), ac ? "A" : "B")
        .arg(m.kinematics.tiltMinDeg)
        .arg(m.kinematics.tiltMaxDeg)
        .arg(m.tcpPositions ? QObject::tr("tool tip (TCP)") : QObject::tr("machine positions"));
  } catch (const std::exception&) {
    return {};
  }
}

std::pair<int, int> coordinateDecimalsRange(PathExportFormat format) {
  switch (format) {
    case PathExportFormat::Csv:
      return {0, 17};
    case PathExportFormat::Apt:
      return {4, 6};
    case PathExportFormat::GCode:
      break;
  }
  return {3, 6};
}

QString pathExportSuffix(PathExportFormat format) {
  const io::PathFormat written = format == PathExportFormat::Csv   ? io::PathFormat::Csv
                                 : format == PathExportFormat::Apt ? io::PathFormat::Apt
                                                                   : io::PathFormat::GCode;
  return QString::fromStdString(io::pathFileExtensions(written).front()).remove(0, 1);
}

QString exportFileStem(const std::string& partName) {
  if (partName.empty()) return QStringLiteral("paths");
  // Only the suffix of a file a part is opened from goes; any other dot belongs to the name.
  const std::filesystem::path name(partName);
  const std::string stem = io::canOpenAsProject(name) ? name.stem().string() : partName;
  return QString::fromStdString(stem.empty() ? partName : stem).replace(' ', '_');
}

PathExportOptions normalisedExportOptions(PathExportOptions o) {
  if (!dialectBelongs(o.format, o.dialect))
    o.dialect = o.format == PathExportFormat::Apt ? PathExportDialect::AptStandard
                                                  : PathExportDialect::GCode5AxisAC;
  const auto [low, high] = coordinateDecimalsRange(o.format);
  o.coordinateDecimals = std::clamp(o.coordinateDecimals, low, high);
  o.vectorDecimals = std::clamp(o.vectorDecimals, 6, 9);
  // APT's GOTO and G-code's programmed point are the tool reference (tip, centre).
  if (o.format != PathExportFormat::Csv) o.point = planning::ClPointKind::ToolReference;
  if (o.unit == LengthUnit::Metre) o.unit = LengthUnit::Millimetre;
  return o;
}

QStringList exportPathsInteractively(const planning::Project& project,
                                     const WorkbenchDialogs& dialogs, QSettings& settings,
                                     ConsoleDock* console) {
  PathExportOptions initial = loadExportOptions(settings);
  for (std::size_t i = 0; i < project.paths.size(); ++i) initial.paths.push_back(int(i));
  const QString folder = settings.value("pathExport/folder", QDir::homePath()).toString();
  initial.filePath = QDir(folder).filePath(exportFileStem(project.partName) + "." +
                                           pathExportSuffix(initial.format));
  const auto chosen = dialogs.exportPaths ? dialogs.exportPaths(project, initial) : initial;
  if (!chosen) return {};
  QStringList written;
  const bool ok = runUserAction(dialogs.error, QObject::tr("Export tool paths"),
                                [&] { written = exportPaths(project, *chosen); });
  if (!ok) return {};
  saveExportOptions(settings, *chosen);
  settings.setValue("pathExport/folder", QFileInfo(chosen->filePath).absolutePath());
  if (console)
    for (const QString& file : written)
      console->appendMessage(LogLevel::Info, QObject::tr("Exported tool paths to %1").arg(file));
  return written;
}

PathExportOptions loadExportOptions(QSettings& settings) {
  PathExportOptions o;
  settings.beginGroup("pathExport");
  o.format = static_cast<PathExportFormat>(settings.value("format", int(o.format)).toInt());
  o.dialect = static_cast<PathExportDialect>(settings.value("dialect", int(o.dialect)).toInt());
  o.coordinateDecimals = settings.value("coordinateDecimals", o.coordinateDecimals).toInt();
  o.vectorDecimals = settings.value("vectorDecimals", o.vectorDecimals).toInt();
  o.unit = settings.value("unit").toString() == "in" ? LengthUnit::Inch : LengthUnit::Millimetre;
  o.point = settings.value("point").toString() == "tool" ? planning::ClPointKind::ToolReference
                                                         : planning::ClPointKind::Contact;
  o.grouping = settings.value("perRegion", false).toBool() ? PathExportGrouping::FilePerRegion
                                                           : PathExportGrouping::OneFile;
  o.machineFile = settings.value("machineFile").toString();
  settings.endGroup();
  // Settings written by another version may hold values outside the enums.
  if (o.format < PathExportFormat::Csv || o.format > PathExportFormat::GCode)
    o.format = PathExportFormat::Csv;
  if (o.dialect < PathExportDialect::AptStandard || o.dialect > PathExportDialect::GCode5AxisBC)
    o.dialect = PathExportDialect::AptStandard;
  return normalisedExportOptions(o);
}

void saveExportOptions(QSettings& settings, const PathExportOptions& o) {
  settings.beginGroup("pathExport");
  settings.setValue("format", int(o.format));
  settings.setValue("dialect", int(o.dialect));
  settings.setValue("coordinateDecimals", o.coordinateDecimals);
  settings.setValue("vectorDecimals", o.vectorDecimals);
  settings.setValue("unit", unitKey(o.unit));
  settings.setValue("point", o.point == planning::ClPointKind::ToolReference ? "tool" : "contact");
  settings.setValue("perRegion", o.grouping == PathExportGrouping::FilePerRegion);
  settings.setValue("machineFile", o.machineFile);
  settings.endGroup();
}

}  // namespace ddfcam::gui
