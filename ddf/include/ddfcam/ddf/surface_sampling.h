// SPDX-License-Identifier: MIT
// ddfcam: locating points on the represented surface and sampling per-raster-point values there.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <optional>
#include <span>
#include <vector>

namespace ddfcam::ddf {

/// @brief A point of the represented surface and where it lies in its support face.
struct SurfaceLocation {
  int face = -1;              ///< support face
  Vec3 bary = Vec3::Zero();   ///< barycentric coordinates in the face's local order, sum 1
  double h = 0.0;             ///< surface height at bary (raster interpolation), vector units
  Vec3 point = Vec3::Zero();  ///< g + h v at bary, mm, part frame

  bool operator==(const SurfaceLocation&) const = default;
};

/// @brief Value at barycentric coordinates @p bary of face @p face of a per-raster-point
/// array laid out like ddf.allHeights(): linear over the raster triangle (of the raster mesh,
/// fig. 7.1a) containing bary, so it reproduces the values at raster points exactly.
/// Coordinates slightly outside the face are clamped onto it (negative ones set to 0, the rest
/// rescaled to sum 1). Raster points whose weight is 0 do not contribute, so a NaN ("no value")
/// only spreads into the raster triangles around it.
/// @throws InvalidInput if @p values has the wrong size, @p face is out of range or @p bary is
/// not finite.
double interpolateOnFace(const DisplacementField& ddf, std::span<const float> values, int face,
                         const Vec3& bary);

/// @brief The surface location of face @p face nearest to @p p, for a point @p p on or near the
/// represented surface (e.g. a pick on a display mesh): @p p is V-projected onto the face
/// (vProject), feet outside the face are clamped onto it, and of several roots the one whose
/// height is closest to the surface height at its foot wins; the result is the surface point
/// at that foot.
/// @return std::nullopt if no V-projection exists (p far outside the face's crust).
/// @throws InvalidInput if @p face is out of range.
std::optional<SurfaceLocation> locateOnFace(const DisplacementField& ddf, int face, const Vec3& p);

/// @brief Where each vertex of a display mesh lies on the DDF, to colour it by a field.
struct SurfaceSamples {
  std::vector<int> face;   ///< #V support face of each vertex
  std::vector<Vec3> bary;  ///< #V barycentric coordinates in that face
};

/// @brief Exact samples of a raster mesh: vertex v is raster point raster.vertexPoint[v], taken
/// from its copy in the lowest-index face (the copy extractRasterMesh places the vertex at). A
/// point without any copy (a support vertex without faces) gets face -1.
/// @throws InvalidInput if a vertex names a raster point that @p ddf does not have.
SurfaceSamples sampleRasterMesh(const DisplacementField& ddf, const RasterMesh& raster);

/// @brief Samples of any mesh lying on the DDF surface (e.g. an adaptive triangulation) whose
/// triangle t belongs to support face triangleFace[t]: each vertex is located (locateOnFace)
/// on the face of the first triangle using it; a vertex that cannot be located gets the
/// centroid (1/3, 1/3, 1/3) of that face; a vertex used by no triangle gets face -1. Vertices
/// are located in parallel (TBB).
/// @throws InvalidInput if triangleFace.size() != mesh.triangles.size(), or a face or vertex
/// index is out of range (naming the triangle).
SurfaceSamples sampleMeshVertices(const DisplacementField& ddf, const TriangleMesh& mesh,
                                  std::span<const int> triangleFace);

/// @brief interpolateOnFace() at every sample: #V values; NaN for samples with face -1.
/// @throws InvalidInput if @p values has the wrong size or the sample arrays differ in size.
std::vector<float> valuesAtSamples(const DisplacementField& ddf, std::span<const float> values,
                                   const SurfaceSamples& samples);

/// @brief One value per distinct raster point (PointId order, topology().pointCount() values),
/// each taken from the point's copy in the lowest-index face: statistics then count shared
/// points once. Points without any copy get NaN.
/// @throws InvalidInput if @p values has the wrong size.
std::vector<float> valuesPerPoint(const DisplacementField& ddf, std::span<const float> values);

}  // namespace ddfcam::ddf
