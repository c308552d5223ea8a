// SPDX-License-Identifier: MIT
// ddfcam gui: File > Export tool paths: the options (format, dialect, precision, units, point,
// which paths, file), their checks, the dialog that gathers them and the write itself.
#pragma once

#include <ddfcam/planning/placement/cl_program.h>

#include <QDialog>
#include <QString>
#include <QStringList>

#include <functional>
#include <utility>
#include <vector>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSettings;
class QSpinBox;

namespace ddfcam::planning {
struct Project;
}

namespace ddfcam::gui {

class ConsoleDock;
struct WorkbenchDialogs;

/// @brief File format of an export.
enum class PathExportFormat {
  Csv,   ///< one row per point (io/tool_path_csv.h)
  Apt,   ///< APT / CLDATA source (io/apt_writer.h)
  GCode  ///< RS-274 G-code (io/gcode_writer.h)
};

/// @brief Dialect of the format: APT's feed record or the G-code machine.
enum class PathExportDialect {
  AptStandard,   ///< APT FEDRAT/f,MMPM (the standard order)
  AptNx,         ///< NX CLSF FEDRAT/MMPM,f (unit first)
  GCode3Axis,    ///< 3-axis mill: vertical tool, X Y Z only
  GCode5AxisAC,  ///< table-table 5-axis machine with A (about x) and C (about z)
  GCode5AxisBC   ///< table-table 5-axis machine with B (about y) and C (about z)
};

/// @brief How the chosen paths are spread over files.
enum class PathExportGrouping {
  OneFile,       ///< every chosen path in one program, one file
  FilePerRegion  ///< one program and file per region (files named "<base>_<region>.<ext>")
};

/// @brief Everything the export dialog asks. Defaults: CSV in mm, 6 decimals, contact
/// points, one file.
struct PathExportOptions {
  PathExportFormat format = PathExportFormat::Csv;  ///< file format (default CSV)
  /// Dialect; must belong to the format (default AptStandard, used when APT is chosen).
  PathExportDialect dialect = PathExportDialect::AptStandard;
  /// Digits after the point of coordinates: CSV 0..17, APT 4..6, G-code 3..6 (default 6).
  int coordinateDecimals = 6;
  /// Digits after the point of unit vectors: APT 6..9; CSV uses coordinateDecimals (default 7).
  int vectorDecimals = 7;
  LengthUnit unit = LengthUnit::Millimetre;  ///< mm or inch (default mm)
  /// Point the positions give: contact or tool reference; APT and G-code always write the tool
  /// reference (the CL point / programmed point). Default Contact.
  planning::ClPointKind point = planning::ClPointKind::Contact;
  PathExportGrouping grouping = PathExportGrouping::OneFile;  ///< files (default one)
  std::vector<int> paths;  ///< indices into Project::paths to write, ascending (default none)
  QString filePath;        ///< the file (OneFile) or the base of the region files
  /// G-code: a machine file (io/machine_file.h: rotary axes, directions, pivot, limits,
  /// solution, TCP) that replaces the dialect's generic table; empty: the dialect (default).
  QString machineFile;
};

/// @brief One line describing the machine file of G-code @p options (name, rotary axes, tilt
/// limits, how X Y Z are written); empty when there is none or it cannot be read.
QString exportMachineName(const PathExportOptions& options);

/// @brief Range of PathExportOptions::coordinateDecimals for @p format (low, high): CSV 0..17,
/// APT 4..6, G-code 3..6.
std::pair<int, int> coordinateDecimalsRange(PathExportFormat format);

/// @brief Preferred file suffix of @p format without the dot (io::pathFileExtensions()):
/// "csv", "apt" or "ngc".
QString pathExportSuffix(PathExportFormat format);

/// @brief File stem File > Export tool paths suggests for a part named @p partName: the name
/// without the suffix of the file it was opened from (io::canOpenAsProject(), so
/// "blade_mm.stl" gives "blade_mm", not "blade_mm.stl.csv"), blanks as '_'; "paths" for an
/// unnamed part.
QString exportFileStem(const std::string& partName);

/// @brief Makes @p options consistent with its format: a dialect of the format, decimals in the
/// format's range, the tool reference point for APT and G-code. Values already valid stay.
PathExportOptions normalisedExportOptions(PathExportOptions options);

/// @brief What is wrong with @p options for @p project, as one sentence for the dialog (e.g.
/// "3-axis G-code needs a vertical tool; path 'pass 2' tilts it by 35.0 degrees."); empty if
/// the export can run.
QString pathExportProblem(const planning::Project& project, const PathExportOptions& options);

/// @brief Writes the chosen paths of @p project as @p options say (programs from
/// planning::programsForExport, files by io::writePathFile): one file at options.filePath when
/// there is one program, else one per program named as io::toolPathCsvFileFor() names them
/// ("<stem>_<program name>.<ext>"; a project whose chosen paths use several tools gives one
/// program per tool even in one file mode).
/// @return the files written, in order.
/// @throws InvalidInput for options pathExportProblem() rejects; IoError if a file cannot be
/// written.
QStringList exportPaths(const planning::Project& project, const PathExportOptions& options);

/// @brief Reads the last export choices from @p settings (group "pathExport"); the file and
/// the paths are not remembered.
PathExportOptions loadExportOptions(QSettings& settings);
/// @brief Stores @p options' choices in @p settings for the next export.
void saveExportOptions(QSettings& settings, const PathExportOptions& options);

/// @brief File > Export tool paths: asks @p dialogs.exportPaths (starting from the choices
/// last stored in @p settings, all paths checked, the file named after the part), writes the
/// files through runUserAction (errors to dialogs.error), stores the choices and lists the
/// files in @p console (may be null).
/// @return the files written; empty if cancelled or failed.
QStringList exportPathsInteractively(const planning::Project& project,
                                     const WorkbenchDialogs& dialogs, QSettings& settings,
                                     ConsoleDock* console);

/// @brief The modal dialog of File > Export tool paths. Shows one problem at a time under the
/// options (pathExportProblem) and enables OK only when there is none.
class PathExportDialog : public QDialog {
  Q_OBJECT

 public:
  /// @param project the project whose paths are offered; must outlive the dialog.
  /// @param initial the options shown first (every path is checked if initial.paths is empty).
  PathExportDialog(const planning::Project& project, const PathExportOptions& initial,
                   QWidget* parent = nullptr);

  /// @brief The options as the widgets show them now.
  PathExportOptions options() const;
  /// @brief The problem shown under the options; empty when OK is enabled.
  QString problem() const;

 private:
  void buildForm(const PathExportOptions& initial);
  void fillPaths(const PathExportOptions& initial);
  void connectSignals();
  void fillDialects(PathExportFormat format);
  void showOptions(const PathExportOptions& options);
  void refresh();
  void browse();
  void browseMachine();

  const planning::Project& project_;
  QComboBox* format_ = nullptr;
  QComboBox* dialect_ = nullptr;
  QSpinBox* coordinateDecimals_ = nullptr;
  QSpinBox* vectorDecimals_ = nullptr;
  QComboBox* unit_ = nullptr;
  QComboBox* point_ = nullptr;
  QComboBox* grouping_ = nullptr;
  QListWidget* paths_ = nullptr;
  QLineEdit* file_ = nullptr;
  QLineEdit* machineFile_ = nullptr;
  QPushButton* machineBrowse_ = nullptr;
  QLabel* machineName_ = nullptr;
  QLabel* problem_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
  bool updating_ = false;
};

}  // namespace ddfcam::gui
