// SPDX-License-Identifier: MIT
// ddfcam gui: File > Import tool path and dropped path files: read the file, ask how to place
// it (unit, transform, tool), place it on the part and add it as one undoable path.
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/placement/imported_path.h>
#include <ddfcam/planning/tools/tool.h>

#include <QDialog>
#include <QString>
#include <QStringList>

#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace ddfcam::planning {
struct Project;
}

namespace ddfcam::gui {

class ConsoleDock;
class Document;
struct WorkbenchDialogs;

/// @brief How an imported program is placed on the part. Defaults: the file's unit, no
/// transform, the project's first tool.
struct PathImportOptions {
  /// Unit the file's numbers are really in; the dialog starts with the unit the reader found
  /// (default mm).
  LengthUnit unit = LengthUnit::Millimetre;
  ddf::Vec3 translationMm = ddf::Vec3::Zero();  ///< program -> part translation, mm (default 0)
  /// Rotation program -> part, degrees, about the fixed x, y, z axes in that order
  /// (R = Rz * Ry * Rx), applied before the translation (default 0).
  ddf::Vec3 rotationDeg = ddf::Vec3::Zero();
  /// Index into Project::tools; -1: a new tool made from the file's CUTTER record (only when
  /// the program has one) (default 0).
  int toolIndex = 0;
  bool includeRapids = false;  ///< keep rapid moves as poses (default false)
  QString name;                ///< path name; empty: the program's part name or the file's
  /// What the file's vectors are (tool axis, approach direction, surface normal) (default
  /// Auto: decided from the part).
  planning::PathVectorMeaning vectors = planning::PathVectorMeaning::Auto;
  /// What the file's points are (contacts or tool reference points) (default Auto).
  planning::PathPointMeaning points = planning::PathPointMeaning::Auto;
};

/// @brief What the import dialog shows: the file, the program read from it and the project.
struct PathImportRequest {
  QString file;                        ///< the file read
  const planning::ClProgram& program;  ///< as read (positions in mm per program.sourceUnit)
  const planning::Project& project;    ///< offers its tools
};

/// @brief Suffixes (no dot, lower case) of the readable path formats: io::pathFileExtensions()
/// of CSV, APT, ROS YAML and FANUC .ls.
QStringList importSuffixes();
/// @brief File-dialog filter of the readable path formats ("Tool paths (*.csv *.txt ...);;All
/// files (*)").
QString pathFileFilter();
/// @brief True if @p file's suffix is one of importSuffixes() (any case) and its first 4 KiB
/// are a readable path format (io::detectPathFormat): a .txt of notes is not a path file.
/// False for a missing or unreadable file.
bool isPathFile(const QString& file);

/// @brief The program -> part map of @p options: rotation Rz * Ry * Rx (degrees), then the
/// translation (mm).
Eigen::Isometry3d importTransform(const PathImportOptions& options);

/// @brief The options the dialog starts with for @p request: the file's unit, the program's
/// cutter as a new tool when the project has no tools, else tool 0, the file's base name.
PathImportOptions initialImportOptions(const PathImportRequest& request);

/// @brief Reads @p file (io::readPathFile), asks @p dialogs.importPath for the placement,
/// places the program on the part (planning::placeProgram) and pushes one AddPathCommand (with a
/// new tool if the options ask for one). Reader and placement warnings go to @p console. Errors
/// (unreadable file, no part, placement refused) go to dialogs.error once.
/// @return true if a path was added; false if cancelled or failed.
bool importPathFile(const QString& file, Document& document, const WorkbenchDialogs& dialogs,
                    ConsoleDock* console);

/// @brief The modal dialog of an import: the file's unit as read and an override, a transform
/// (translation mm, rotation degrees), the tool, what the vectors and points are, rapids and
/// the path name.
class PathImportDialog : public QDialog {
  Q_OBJECT

 public:
  /// @param request the file, program and project; must outlive the dialog.
  PathImportDialog(const PathImportRequest& request, const PathImportOptions& initial,
                   QWidget* parent = nullptr);

  /// @brief The options as the widgets show them now.
  PathImportOptions options() const;

 private:
  QComboBox* unit_ = nullptr;
  QDoubleSpinBox* translation_[3] = {};
  QDoubleSpinBox* rotation_[3] = {};
  QComboBox* tool_ = nullptr;
  QComboBox* vectors_ = nullptr;
  QComboBox* points_ = nullptr;
  QCheckBox* rapids_ = nullptr;
  QLineEdit* name_ = nullptr;
};

}  // namespace ddfcam::gui
