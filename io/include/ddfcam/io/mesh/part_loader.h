// SPDX-License-Identifier: MIT
// ddfcam: loading a part as a DDF from a .ddf file or from a mesh file (converted on the fly).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/progress.h>

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::io {

/// @brief Parameters of loadPart().
struct LoadPartParams {
  /// Conversion of mesh files (raster resolution, welding, vector directions and lengths);
  /// ignored for .ddf files. Its progress callback is replaced by @ref progress.
  /// Default: ddf::ConversionParams defaults (m = 10).
  ddf::ConversionParams conversion;
  /// Unit of the file's coordinates. std::nullopt: the unit a CAD file states, millimetres for
  /// mesh files. A given unit overrides a CAD file's own. Ignored for .ddf files (always mm).
  /// Default std::nullopt.
  std::optional<LengthUnit> unit;
  /// Progress in [0, 1] and cancellation for the whole load. Default none.
  ProgressCallback progress;
};

/// @brief What loadPart() did besides returning the field.
struct LoadPartReport {
  bool converted = false;  ///< true if the file was a mesh converted to a DDF
  int meshVertices = 0;    ///< vertices read from the mesh file (0 for .ddf)
  int meshTriangles = 0;   ///< triangles read from the mesh file (0 for .ddf)
  /// What the conversion repaired and dropped, and the check of its result against the three
  /// DDF constraints (conversion.valid()); default-constructed for .ddf files. Describe it with
  /// ddf::conversionVerdict, conversionRepairLines and conversionProblemLines.
  ddf::ConversionReport conversion;
  /// The full conversion result's extras: support labels, reduction, accuracy, stock fit.
  ddf::ConversionAccuracy accuracy;
  ddf::SupportReductionReport reduction;     ///< what the support reduction did
  std::optional<ddf::StockFit> stock;        ///< the crust fit to the requested stock
  LengthUnit unit = LengthUnit::Millimetre;  ///< unit the file was read in
  bool unitFromFile = false;                 ///< the unit is the one the file states (STEP, IGES)
  /// Bounding box of the part as read, in file units, and its diagonal: when
  /// sizeSuggestsOtherUnit(fileDiagonal) holds and no unit was given, a caller warns or asks.
  double fileDiagonal = 0.0;
  std::array<ddf::Vec3, 2> boundsMm = {ddf::Vec3::Zero(), ddf::Vec3::Zero()};  ///< bounding box, mm
  /// CAD input only: per support face its CAD face index (empty otherwise), and per CAD face a
  /// display name such as "face 12 (B-spline)".
  std::vector<int> cadFaceOfSupportFace;
  std::vector<std::string> cadFaceNames;
  /// CAD input only: what healing (ShapeFix) changed, one fact per line.
  std::vector<std::string> cadHealing;
};

/// @brief Loads @p path as a DDF: a .ddf file through readDdf; a .stl/.obj/.ply/.off mesh
/// through readMesh, scaled by millimetresPer(params.unit, default mm), and
/// ddf::convertMeshToDdf; a .step/.stp/.iges/.igs CAD model through readCadModel (in the unit
/// the file states unless params.unit overrides it), tessellated with the chord deflection of
/// cadChordDeflectionMm() and converted with its CAD face per triangle as
/// ConversionParams::inputLabels (report->cadFaceOfSupportFace maps the result back).
/// When no unit was given and the file states none the part is read as mm; the report's
/// fileDiagonal tells the caller whether sizeSuggestsOtherUnit() holds, so that the CLI warns
/// (naming --units) and the import dialog asks, each once. A .ddf file's recorded source unit
/// and CAD faces are copied into the report. A converted field that violates a DDF constraint is
/// still returned (with a warning through ddfcam::log); report->conversion says which constraint
/// fails and where.
/// @param report if not null, receives what the conversion did.
/// @throws IoError "loading <file>" with the cause nested (missing, empty or malformed file,
/// unknown extension, a CAD file without faces, a mesh the conversion rejects); Cancelled (not
/// wrapped) through params.progress.
ddf::DisplacementField loadPart(const std::filesystem::path& path,
                                const LoadPartParams& params = {},
                                LoadPartReport* report = nullptr);

/// @brief A loaded part and the triangles it was converted from.
struct LoadedPart {
  ddf::DisplacementField ddf;  ///< the part, mm
  /// The input triangles in mm: the scaled mesh file or the CAD tessellation; for a .ddf file
  /// the design mesh it stores (DdfMetadata::designMesh), else empty.
  ddf::TriangleMesh inputMesh;
};

/// @brief loadPart() that also returns the converted triangles (openProject keeps them as the
/// design mesh, so a CAD model is read and tessellated once).
/// @throws as loadPart().
LoadedPart loadPartWithInput(const std::filesystem::path& path, const LoadPartParams& params = {},
                             LoadPartReport* report = nullptr);

/// @brief Chord deflection loadPart() tessellates a CAD model with, mm: a tenth of
/// conversion.toleranceMm when that is set (the tessellation takes a tenth of the accuracy
/// budget); otherwise a tenth of the raster spacing estimate, which is
/// conversion.rasterSpacingMm when set, else that of a support edge of 1 % of the part's
/// diagonal at the conversion's resolution, 0.01 * diagonalMm / (resolution - 1). Never below
/// 1e-7 * diagonalMm.
/// @param diagonalMm bounding-box diagonal of the model, mm.
double cadChordDeflectionMm(const ddf::ConversionParams& conversion, double diagonalMm);

}  // namespace ddfcam::io
