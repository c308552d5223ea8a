// SPDX-License-Identifier: MIT
// ddfcam: the curvature of a converted part taken from the mesh it was converted from.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/analysis/curvature.h>

namespace ddfcam::planning {

/// @brief Principal curvatures and directions at every raster point of @p part (CurvatureField
/// layout and tool-side sign convention) from quadric fits at the vertices of @p design, the
/// mesh @p part was converted from.
///
/// Why: a reduced support's heights follow the flat triangles of the input, so the raster
/// differences see zero inside them and spikes at their edges, while the vertex fits on the
/// support see a coarse support only. Here @p design is welded as a DDF support of its own
/// and computeVertexCurvature() fits its vertices (split at creases and, with
/// params.faceLabels, between labels); every raster point takes the fitted tensors of the three
/// corners of the design triangle nearest to it (MeshDistance), blended by the barycentric
/// coordinates of its foot point, projected onto the plane of the part's raster normal there.
/// With labels (one per part face), every design triangle gets the label most raster points
/// nearest to it carry (triangles no point reached take a neighbour's), so a fit does not mix
/// a cylinder with the torus it runs into tangentially. A face with a raster point further
/// than params.designDistanceMm from @p design (e.g. cut below it) gets the raster differences
/// of computeCurvature() there instead (none when m < 4: zero, flagged umbilic).
/// @param part the part, mm.
/// @param design its input triangles, mm, part frame, oriented as the part's vectors.
/// @throws InvalidInput if the part or @p design has no faces, or params.faceLabels is neither
/// empty nor one label per part face; Cancelled through params.progress.
CurvatureField computeDesignCurvature(const ddf::DisplacementField& part,
                                      const ddf::TriangleMesh& design,
                                      const CurvatureParams& params = {});

}  // namespace ddfcam::planning
