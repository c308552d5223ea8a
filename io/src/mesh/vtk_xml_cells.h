// SPDX-License-Identifier: MIT
// ddfcam: triangulating VTK cells (surface cells directly, 3D cells by their boundary faces).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

namespace ddfcam::io::detail {

/// @brief Collects the triangles of VTK cells with the cell each came from.
class CellTriangulator {
 public:
  /// @brief Adds one cell of VTK type @p type with global node indices @p nodes; @p cell is its
  /// global cell index (for cell data). Returns false if the node count does not fit the type.
  bool addCell(int type, std::span<const int> nodes, std::int64_t cell);
  /// @brief Fan of a polygon (PolyData Polys, VTK_POLYGON).
  void addPolygon(std::span<const int> nodes, std::int64_t cell);
  /// @brief Triangles of a strip with alternating orientation (PolyData Strips).
  void addStrip(std::span<const int> nodes, std::int64_t cell);
  /// @brief Appends the faces of 3D cells used by exactly one cell (call once, at the end).
  void addBoundaryFaces();

  std::vector<std::array<int, 3>> triangles;  ///< global vertex indices
  std::vector<std::int64_t> cellOfTriangle;   ///< global cell index per triangle
  int lineCells = 0;
  int vertexCells = 0;
  int otherCells = 0;
  std::map<int, int> unsupportedTypes;  ///< VTK type -> count

 private:
  struct Face {
    std::array<int, 4> nodes;  // outward order; nodes[3] = -1 for a triangle
    std::int64_t cell;
  };
  void addSolid(int type, std::span<const int> nodes, std::int64_t cell);
  std::vector<Face> faces_;
};

}  // namespace ddfcam::io::detail
