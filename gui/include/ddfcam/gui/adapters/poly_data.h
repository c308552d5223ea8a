// SPDX-License-Identifier: MIT
// ddfcam gui adapters: core geometry values -> vtkPolyData. Conversion only, no geometry logic.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Core>

#include <vector>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace ddfcam::gui {

/// @brief Shaded-surface polydata of @p mesh: points (mm, part frame), triangle cells and
/// per-point normals (vtkPolyDataNormals, feature edges split at 40 degrees so creases stay
/// sharp). An empty mesh gives an empty polydata.
vtkSmartPointer<vtkPolyData> toSurfacePolyData(const ddf::TriangleMesh& mesh);

/// @brief Wireframe polydata of @p mesh: its points and one line cell per distinct undirected
/// edge (shared edges drawn once).
vtkSmartPointer<vtkPolyData> toWireframePolyData(const ddf::TriangleMesh& mesh);

/// @brief Line-segment polydata: segment s runs from from[s] to to[s] (mm, part frame), e.g.
/// the arrays of ddf::StubbleLines. Each segment becomes one two-point line cell.
/// @throws InvalidInput if the arrays differ in length.
vtkSmartPointer<vtkPolyData> toSegmentPolyData(const std::vector<Eigen::Vector3d>& from,
                                               const std::vector<Eigen::Vector3d>& to);

}  // namespace ddfcam::gui
