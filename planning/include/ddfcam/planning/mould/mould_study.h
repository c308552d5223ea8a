// SPDX-License-Identifier: MIT
// ddfcam: the mould-planning part of a project: mould and formed surfaces, their alignment,
// the comparison and the springback compensation history (dissertation ch. 9).
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/inspection/surface_comparison.h>
#include <ddfcam/planning/mould/springback_compensation.h>

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief A scalar field a forming simulation wrote on its mesh (e.g. thickness, plastic strain).
struct MeshField {
  std::string name;           ///< array name in the file, e.g. "thickness"
  std::string unit;           ///< unit if known, else empty
  bool perCell = false;       ///< one value per triangle (true) or per vertex (false)
  std::vector<float> values;  ///< #V or #T values (vector arrays keep their magnitude)
  bool operator==(const MeshField&) const = default;
};

/// @brief A surface loaded from a file, with the fields the file carried.
struct LoadedSurface {
  std::string name;               ///< shown in lists, e.g. the file name
  std::string sourcePath;         ///< file it came from; empty for generated surfaces
  ddf::TriangleMesh mesh;         ///< mm, mould frame (alignment applied)
  std::vector<MeshField> fields;  ///< per-vertex or per-triangle scalars of the file
};

/// @brief How the formed surface was brought into the mould's frame.
enum class AlignmentMethod {
  None,        ///< as positioned in its file
  PointPairs,  ///< rigid transform from picked point pairs (at least three)
  BestFit      ///< iterative closest point; hides global springback (the user was warned)
};

/// @brief The alignment applied to the formed surface.
struct SurfaceAlignmentRecord {
  AlignmentMethod method = AlignmentMethod::None;  ///< default None
  /// Rigid transform file frame -> mould frame, row-major 4x4 (identity by default).
  std::array<double, 16> transform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double rmsMm = 0.0;  ///< RMS residual of the pairs or of the best fit, mm
  /// Picked pairs (formed point in its file frame, mould point), mm; PointPairs only.
  std::vector<std::array<Eigen::Vector3d, 2>> pointPairs;
};

/// @brief Mould planning state of a project.
struct MouldStudy {
  LoadedSurface mould;                      ///< mould or target surface (the reference frame)
  std::optional<LoadedSurface> formed;      ///< deformed (formed) surface, aligned
  SurfaceAlignmentRecord alignment;         ///< how formed was aligned
  ComparisonParams comparison;              ///< resolution, band, sequence settings (no progress)
  std::optional<SurfaceComparison> result;  ///< last comparison of formed with mould
  std::optional<CompensationHistory> compensation;  ///< springback compensation, if started
};

/// @brief Checks sizes and indices of @p study (meshes, fields, result and history layouts).
/// @throws InvalidInput naming the first offending item.
void validateMouldStudy(const MouldStudy& study);

/// @brief Exact equality of two studies (every value bit-identical, NaN equals NaN).
bool mouldStudiesEqual(const MouldStudy& a, const MouldStudy& b);

/// @brief Bitwise equality of two meshes (vertex coordinates and triangle index triples).
bool triangleMeshesEqual(const ddf::TriangleMesh& a, const ddf::TriangleMesh& b);

/// @brief Bitwise equality of two DDFs: positions, vectors, face vertex order, resolution and
/// heights (NaN equals NaN with the same payload; 0.0 and -0.0 differ).
bool displacementFieldsEqual(const ddf::DisplacementField& a, const ddf::DisplacementField& b);

/// @brief Checks the layout of a comparison result: at least one stage, every stage with the
/// face count, resolution and height count of stage 0, and deformedPoints, deviation and
/// deviationVectors sized like stages[0].ddf.allHeights(); face lists ascending and in range.
/// @throws InvalidInput naming the first offending item.
void validateSurfaceComparison(const SurfaceComparison& comparison);

}  // namespace ddfcam::planning
