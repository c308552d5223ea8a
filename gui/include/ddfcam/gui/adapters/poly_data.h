// SPDX-License-Identifier: MIT
// ddfcam gui adapters: core geometry values -> vtkPolyData. Conversion only, no geometry logic.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Core>

#include <span>
#include <vector>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace ddfcam::gui {

/// Point-data int array of surface polydata: the mesh vertex each point copies (feature-edge
/// splitting duplicates points, so point ids and mesh vertex ids differ).
inline constexpr const char* kVertexArrayName = "vertex";
/// Cell-data int array of surface polydata: the support face of each triangle.
inline constexpr const char* kFaceArrayName = "face";

/// @brief Shaded-surface polydata of @p mesh: points (mm, part frame), triangle cells (cell c
/// is mesh.triangles[c]) and per-point normals (vtkPolyDataNormals, feature edges split at 40
/// degrees so creases stay sharp, which appends duplicates of the points on them). Point data
/// kVertexArrayName gives the mesh vertex of every point. An empty mesh gives an empty
/// polydata.
vtkSmartPointer<vtkPolyData> toSurfacePolyData(const ddf::TriangleMesh& mesh);

/// @brief As toSurfacePolyData(mesh), plus cell data kFaceArrayName: triangleFace[c], the
/// support face of triangle c (e.g. ddf::AdaptiveTriangulation::triangleFace).
/// @throws InvalidInput if triangleFace.size() != mesh.triangles.size().
vtkSmartPointer<vtkPolyData> toSurfacePolyData(const ddf::TriangleMesh& mesh,
                                               std::span<const int> triangleFace);

/// @brief Wireframe polydata of @p mesh: its points and one line cell per distinct undirected
/// edge (shared edges drawn once).
vtkSmartPointer<vtkPolyData> toWireframePolyData(const ddf::TriangleMesh& mesh);

/// @brief Line-segment polydata: segment s runs from from[s] to to[s] (mm, part frame), e.g.
/// the arrays of ddf::StubbleLines. Each segment becomes one two-point line cell.
/// @throws InvalidInput if the arrays differ in length.
vtkSmartPointer<vtkPolyData> toSegmentPolyData(const std::vector<Eigen::Vector3d>& from,
                                               const std::vector<Eigen::Vector3d>& to);

/// Cell-data int array of toPolylinePolyData(): the index of the input poly-line of each cell.
inline constexpr const char* kPolylineArrayName = "polyline";

/// @brief Poly-line polydata, e.g. of tool paths: one poly-line cell per input poly-line with at
/// least two points (shorter ones are skipped), its points in order (mm, part frame), and cell
/// data kPolylineArrayName giving the input index of each cell. Points are not shared between
/// poly-lines: the polydata has the sum of the kept poly-lines' point counts.
vtkSmartPointer<vtkPolyData> toPolylinePolyData(
    const std::vector<std::vector<Eigen::Vector3d>>& polylines);

/// @brief Arrow glyphs drawn as lines: for each i, a shaft from points[i] to tip = points[i] +
/// lengthMm * directions[i] / |directions[i]| and two head strokes from the tip back at 25
/// degrees to the shaft, each a quarter of the length long, in a plane containing the shaft. 4
/// points and 3 two-point line cells per arrow (mm, part frame).
/// @param points #N arrow bases, mm, part frame
/// @param directions #N arrow directions (any non-zero length; only the direction is used)
/// @param lengthMm arrow length, mm, > 0
/// @throws InvalidInput if the arrays differ in length, lengthMm is not positive and finite, or
/// a direction is zero or not finite (naming its index).
vtkSmartPointer<vtkPolyData> toGlyphPolyData(const std::vector<Eigen::Vector3d>& points,
                                             const std::vector<Eigen::Vector3d>& directions,
                                             double lengthMm);

}  // namespace ddfcam::gui
