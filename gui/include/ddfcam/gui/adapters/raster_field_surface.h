// SPDX-License-Identifier: MIT
// ddfcam gui adapters: a display surface coloured by a per-raster-point field through a texture,
// so that a coarse (adaptive) display mesh shows the field at the raster's resolution.
#pragma once

#include <ddfcam/gui/adapters/raster_texture_atlas.h>

#include <vtkPolyData.h>  // complete type: polyData() converts the smart pointer
#include <vtkSmartPointer.h>

#include <span>
#include <utility>

class vtkLookupTable;
class vtkTexture;

namespace ddfcam::gui {

/// @brief A copy of a display surface in which every triangle has its own three points with
/// texture coordinates into a RasterTextureAtlas, and that atlas coloured by a field with one
/// value per raster point. A narrow groove or a thin out-of-tolerance band then shows even
/// where the display mesh has triangles far larger than the raster spacing.
class RasterFieldSurface {
 public:
  /// @brief Whether a part of @p faces support faces at @p steps raster steps can be shown this
  /// way (its atlas fits in a texture, RasterTextureAtlas::fits).
  static bool available(int faces, int steps);
  /// @param surface triangles with point normals (point data "Normals"), "vertex" point data
  /// and "face" cell data (the support face of each triangle), e.g. from toSurfacePolyData; it
  /// is copied, not modified.
  /// @param cornerParams 6 floats per triangle of @p surface: (i, k) of its three corners in
  /// the order of the cell's points, raster steps on the triangle's support face
  /// (ddf::TriangleParams).
  /// @param faces, steps the part's support faces and raster steps (m - 1).
  /// @throws InvalidInput if the surface is not all triangles, the sizes differ, a "face" value
  /// is out of range or the atlas does not fit.
  RasterFieldSurface(vtkPolyData* surface, std::span<const float> cornerParams, int faces,
                     int steps);
  ~RasterFieldSurface();
  RasterFieldSurface(const RasterFieldSurface&) = delete;
  RasterFieldSurface& operator=(const RasterFieldSurface&) = delete;

  /// @brief Colours the atlas: raster point p gets @p table's colour of values[p] (the table's
  /// out-of-range and NaN colours where it uses them), drawn over the parameter cell around
  /// the point (nearest sampling, see RasterTextureAtlas).
  /// @param values one per raster point, laid out like the heights (face after face, Raster
  /// order).
  /// @throws InvalidInput if @p values has another size than faces * pointsPerFace.
  void setValues(std::span<const float> values, vtkLookupTable* table);
  /// @brief The textured copy of the surface (owned).
  vtkPolyData* polyData() const { return data_; }
  /// @brief The atlas's texture, for the surface actor.
  vtkTexture* texture() const { return atlas_.texture(); }
  const RasterTextureAtlas& atlas() const { return atlas_; }

 private:
  RasterTextureAtlas atlas_;
  vtkSmartPointer<vtkPolyData> data_;
};

/// @brief Whether any of @p values lies clearly below @p lo / above @p hi (by more than 1e-6 of
/// the range: interpolation puts values that sit on an end a rounding error beyond it); NaN
/// counts as neither.
std::pair<bool, bool> valuesOutOfRange(std::span<const float> values, double lo, double hi);

}  // namespace ddfcam::gui
