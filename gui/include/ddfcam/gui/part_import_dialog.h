// SPDX-License-Identifier: MIT
// ddfcam gui: the import dialog of a mesh or CAD part (unit, accuracy, support, stock) and its
// pure logic: sizes per unit, the unit suggestion, the choices it starts with, the load params.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/length_unit.h>

#include <QDialog>
#include <QString>

#include <array>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QRadioButton;

namespace ddfcam::gui {

/// @brief What is known of a part file before it is converted: its kind, the unit it states and
/// its bounding box.
struct PartImportRequest {
  QString file;                        ///< the file to import
  bool cad = false;                    ///< STEP or IGES (states its own unit)
  std::optional<LengthUnit> fileUnit;  ///< unit the CAD file states, if known
  /// Bounding box (min, max) in the file's own numbers (file units); nullopt if not read.
  std::optional<std::array<ddf::Vec3, 2>> boundsFileUnits;
  QString boundsError;  ///< why the bounds could not be read (empty if read or not tried)
};

/// @brief How the accuracy of the conversion is given.
enum class ImportAccuracy {
  Tolerance,     ///< distance between the DDF surface and the input, both ways, mm
  RasterSpacing  ///< longest raster spacing, mm
};

/// @brief The choices of the import dialog.
struct PartImportChoices {
  /// Unit of the file's numbers; std::nullopt: the unit the CAD file states ("from file").
  /// Default millimetres.
  std::optional<LengthUnit> unit = LengthUnit::Millimetre;
  ImportAccuracy accuracy = ImportAccuracy::Tolerance;  ///< default tolerance
  double toleranceMm = 0.01;     ///< used when accuracy is Tolerance, mm (default 0.01)
  double rasterSpacingMm = 0.5;  ///< used when accuracy is RasterSpacing, mm (default 0.5)
  /// Default reduced: a coarse support with long vectors (thick crust) and the same accuracy.
  ddf::SupportChoice support = ddf::SupportChoice::Reduced;
  double stockMm = 0.0;  ///< stock allowance the crust must reach, mm (default 0 = none)
};

/// @brief True for a file the import dialog is for: a mesh (.stl .obj .ply .off) or CAD file
/// (.step .stp .iges .igs), any case; false for .ddf and .ddfproj.
bool isImportablePart(const QString& file);
/// @brief True for a .step/.stp/.iges/.igs file (any case).
bool isCadFile(const QString& file);

/// @brief The request of @p file: for a mesh its bounds from io::readMesh, for a CAD file its
/// stated unit and bounds from io::readCadModel without healing (both cheap against the
/// conversion). A file that cannot be read leaves the bounds empty and says why in boundsError
/// (the import reports the error itself).
PartImportRequest readImportRequest(const QString& file);

/// @brief Size (dx, dy, dz) of @p bounds (file units) in mm when the numbers are in @p unit.
std::array<double, 3> sizeMmIn(const std::array<ddf::Vec3, 2>& bounds, LengthUnit unit);
/// @brief Bounding-box diagonal of @p bounds (file units).
double diagonalOf(const std::array<ddf::Vec3, 2>& bounds);
/// @brief "300 x 20 x 5 mm" with 3 significant digits (locale-independent).
QString sizeText(const std::array<double, 3>& sizeMm);

/// @brief What the dialog says about the unit: nothing when the size looks right, is unknown or
/// a CAD file states its unit; else a warning and likelyUnit(diagonal) as the suggestion, which
/// may itself be nullopt (too large for any unit: the dialog then just warns).
struct UnitAdvice {
  bool suspicious = false;               ///< sizeSuggestsOtherUnit(file-unit diagonal)
  std::optional<LengthUnit> suggestion;  ///< the unit to preselect
  QString message;                       ///< what the dialog says (empty if not suspicious)
};
/// @brief The advice for @p request (see UnitAdvice).
UnitAdvice unitAdvice(const PartImportRequest& request);

/// @brief The choices the dialog starts with: @p recent (the session's last choices) for the
/// accuracy, support and stock; the suggested unit when the size looks wrong, else the CAD
/// file's own (nullopt) or millimetres; the unit is never carried over from another file.
PartImportChoices initialImportChoices(const PartImportRequest& request,
                                       const PartImportChoices& recent);

/// @brief The loadPart parameters of @p choices: unit, support, tolerance or raster spacing,
/// stock. Conversion fields not chosen keep the library defaults.
io::LoadPartParams loadParamsFor(const PartImportChoices& choices);

/// @brief The modal import dialog: the file's size in each unit, the unit (a CAD file's own
/// marked "from file"), a warning and a preselected unit when the size suggests another unit,
/// accuracy as tolerance or raster spacing, the support and the stock allowance.
class PartImportDialog : public QDialog {
  Q_OBJECT

 public:
  PartImportDialog(const PartImportRequest& request, const PartImportChoices& initial,
                   QWidget* parent = nullptr);
  /// @brief The choices as the widgets show them now.
  PartImportChoices choices() const;
  /// @brief The size and advice text shown (for tests).
  QString sizeSummary() const;

 private:
  QComboBox* unit_ = nullptr;
  QRadioButton* byTolerance_ = nullptr;
  QRadioButton* bySpacing_ = nullptr;
  QDoubleSpinBox* tolerance_ = nullptr;
  QDoubleSpinBox* spacing_ = nullptr;
  QComboBox* support_ = nullptr;
  QDoubleSpinBox* stock_ = nullptr;
  QLabel* sizes_ = nullptr;
};

}  // namespace ddfcam::gui
