// SPDX-License-Identifier: MIT
// ddfcam: the non-adaptive surface mesh of a DDF (fig. 7.1a) and its support mesh.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <vector>

namespace ddfcam::ddf {

/// @brief The represented surface triangulated along the raster lattice, with the raster point
/// of every mesh vertex (to display per-point fields on it).
struct RasterMesh {
  /// One vertex q = g + h v per distinct raster point that has a copy (shared edge and vertex
  /// points welded), mm, part frame; (m-1)^2 triangles per support face, in face order,
  /// oriented like their support face.
  TriangleMesh mesh;
  /// #V raster point of each mesh vertex (the identity unless a support vertex has no face).
  std::vector<PointId> vertexPoint;
};

/// @brief Connects the surface points q of every support face's raster along its lattice
/// (dissertation fig. 7.1a). Shared points take the position of their copy in the lowest-index
/// face, so faces meet without cracks even where the copies' heights disagree.
/// @param ddf any DDF; triangle t of face f is mesh.triangles[f (m-1)^2 + t].
/// @throws nothing beyond std::bad_alloc.
RasterMesh extractRasterMesh(const DisplacementField& ddf);

/// @brief The support mesh S as a TriangleMesh: the support vertices (mm) and one triangle
/// (p1, p2, p3) per face, face order kept.
TriangleMesh extractSupportMesh(const DisplacementField& ddf);

}  // namespace ddfcam::ddf
