// SPDX-License-Identifier: MIT
// ddfcam gui adapters: sign-free line glyphs of a line field and point markers -> vtkPolyData.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/flow/line_field.h>

#include <Eigen/Core>

#include <vector>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace ddfcam::gui {

/// @brief Options of lineGlyphs().
struct LineGlyphParams {
  /// Raster steps between glyph points along i and k; 0 picks glyphStride(ddf, targetCount)
  /// (default 0).
  int stride = 0;
  /// Rough number of glyphs the automatic stride aims at (default 2500).
  int targetCount = 2500;
  /// Glyph length / (stride * mean raster spacing), so neighbouring glyphs do not touch
  /// (default 0.8).
  double lengthFactor = 0.8;
  /// Lift of the glyph centre along the surface normal (tool side) / mean raster spacing, so
  /// the glyphs are not hidden in the shaded surface (default 0.3).
  double liftFactor = 0.3;
};

/// @brief Glyphs of a line field at a subsample of the raster points.
struct LineGlyphs {
  std::vector<int> entries;           ///< #G index of each glyph's raster point copy (field layout)
  std::vector<ddf::Vec3> centres;     ///< #G glyph centres (lifted surface points), mm, part frame
  std::vector<ddf::Vec3> directions;  ///< #G unit directions (sign as stored in the field)
  double lengthMm = 0.0;              ///< length of every glyph, mm
  int stride = 1;                     ///< the stride used, raster steps
};

/// @brief Mean raster spacing of @p ddf: mean support edge length / (m - 1), mm.
double meanRasterSpacingMm(const ddf::DisplacementField& ddf);

/// @brief The smallest stride s >= 1 for which F * (n/s + 1)(n/s + 2)/2 <= @p targetCount
/// (n = m - 1), or n if none is.
int glyphStride(const ddf::DisplacementField& ddf, int targetCount);

/// @brief Raster points where glyphs go: every stored copy (f, i, k) with i and k multiples of
/// @p stride, faces in order and Raster order within a face, each distinct raster point
/// (RasterTopology::id) only at its first such copy. @return their indices in the field
/// layout (f * pointsPerFace + Raster::index(i, k)).
/// @throws InvalidInput if stride < 1.
std::vector<int> glyphSamplePoints(const ddf::DisplacementField& ddf, int stride);

/// @brief Glyphs of @p field at glyphSamplePoints(): a centre at the raster point's surface
/// point lifted by liftFactor * spacing along the surface normal (planning::surfaceNormal) and
/// the unit direction of the field there; undefined (zero) entries get no glyph.
/// @throws InvalidInput if the field size does not match the DDF or a parameter is not
/// positive (stride < 0, targetCount < 1, lengthFactor <= 0, liftFactor < 0).
LineGlyphs lineGlyphs(const ddf::DisplacementField& ddf, const planning::LineField& field,
                      const LineGlyphParams& params = {});

/// @brief Sign-free glyph polydata: one two-point line cell per glyph, from centre - L/2 d to
/// centre + L/2 d (centred on the point, no arrow head), mm, part frame; cell g is glyph g.
vtkSmartPointer<vtkPolyData> toLineGlyphPolyData(const LineGlyphs& glyphs);

/// @brief Marker polydata: one vertex cell per point (mm, part frame), drawn with
/// OverlayStyle::pointSize.
vtkSmartPointer<vtkPolyData> toPointPolyData(const std::vector<Eigen::Vector3d>& points);

}  // namespace ddfcam::gui
