// SPDX-License-Identifier: MIT
// ddfcam: triangulating VTK cells (surface cells directly, 3D cells by their boundary faces).
#include "vtk_xml_cells.h"

#include <algorithm>

namespace ddfcam::io::detail {
namespace {

// VTK cell type numbers (vtkCellType.h).
enum VtkType : int {
  kVertex = 1,
  kPolyVertex = 2,
  kLine = 3,
  kPolyLine = 4,
  kTriangle = 5,
  kStrip = 6,
  kPolygon = 7,
  kPixel = 8,
  kQuad = 9,
  kTetra = 10,
  kVoxel = 11,
  kHexahedron = 12,
  kWedge = 13,
  kPyramid = 14,
  kQuadraticEdge = 21,
  kQuadraticTriangle = 22,
  kQuadraticQuad = 23,
  kQuadraticTetra = 24,
  kQuadraticHexahedron = 25,
  kQuadraticWedge = 26,
  kQuadraticPyramid = 27,
  kBiquadraticQuad = 28,
  kTriquadraticHexahedron = 29,
  kCubicLine = 35
};

using FaceList = std::vector<std::array<int, 4>>;

// Faces in local node numbers, counter-clockwise seen from outside (VTK's orientation of a
// positive cell: the base of a tetra/pyramid has its normal towards the apex, the first
// triangle of a wedge faces away from the second, hexahedron nodes 0-3 face towards 4-7).
const FaceList kTetraFaces = {{0, 1, 3, -1}, {1, 2, 3, -1}, {2, 0, 3, -1}, {0, 2, 1, -1}};
const FaceList kHexFaces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                            {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
const FaceList kWedgeFaces = {
    {0, 1, 2, -1}, {3, 5, 4, -1}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
const FaceList kPyramidFaces = {
    {0, 3, 2, 1}, {0, 1, 4, -1}, {1, 2, 4, -1}, {2, 3, 4, -1}, {3, 0, 4, -1}};

// Minimal node count of each surface or solid type (higher-order cells use their corners).
int cornerCount(int type) {
  switch (type) {
    case kTriangle:
    case kQuadraticTriangle:
      return 3;
    case kPixel:
    case kQuad:
    case kTetra:
    case kQuadraticQuad:
    case kBiquadraticQuad:
    case kQuadraticTetra:
      return 4;
    case kPyramid:
    case kQuadraticPyramid:
      return 5;
    case kWedge:
    case kQuadraticWedge:
      return 6;
    case kVoxel:
    case kHexahedron:
    case kQuadraticHexahedron:
    case kTriquadraticHexahedron:
      return 8;
    default:
      return 0;
  }
}

int fullCount(int type) {
  switch (type) {
    case kQuadraticTriangle:
      return 6;
    case kQuadraticQuad:
      return 8;
    case kBiquadraticQuad:
      return 9;
    case kQuadraticTetra:
      return 10;
    case kQuadraticPyramid:
      return 13;
    case kQuadraticWedge:
      return 15;
    case kQuadraticHexahedron:
      return 20;
    case kTriquadraticHexahedron:
      return 27;
    default:
      return cornerCount(type);
  }
}

}  // namespace

void CellTriangulator::addPolygon(std::span<const int> nodes, std::int64_t cell) {
  for (std::size_t i = 1; i + 1 < nodes.size(); ++i) {
    triangles.push_back({nodes[0], nodes[i], nodes[i + 1]});
    cellOfTriangle.push_back(cell);
  }
}

void CellTriangulator::addStrip(std::span<const int> nodes, std::int64_t cell) {
  for (std::size_t i = 0; i + 2 < nodes.size(); ++i) {
    if (i % 2 == 0)
      triangles.push_back({nodes[i], nodes[i + 1], nodes[i + 2]});
    else
      triangles.push_back({nodes[i + 1], nodes[i], nodes[i + 2]});
    cellOfTriangle.push_back(cell);
  }
}

void CellTriangulator::addSolid(int type, std::span<const int> nodes, std::int64_t cell) {
  std::array<int, 8> n{};
  if (type == kVoxel) {
    constexpr std::array<int, 8> kVoxelToHex = {0, 1, 3, 2, 4, 5, 7, 6};
    for (int i = 0; i < 8; ++i) n[i] = nodes[kVoxelToHex[i]];
  } else {
    std::copy_n(nodes.begin(), cornerCount(type), n.begin());
  }
  const FaceList* faces = &kHexFaces;
  if (type == kTetra || type == kQuadraticTetra) faces = &kTetraFaces;
  if (type == kWedge || type == kQuadraticWedge) faces = &kWedgeFaces;
  if (type == kPyramid || type == kQuadraticPyramid) faces = &kPyramidFaces;
  for (const auto& f : *faces)
    faces_.push_back({{n[f[0]], n[f[1]], n[f[2]], f[3] < 0 ? -1 : n[f[3]]}, cell});
}

bool CellTriangulator::addCell(int type, std::span<const int> nodes, std::int64_t cell) {
  const auto size = static_cast<int>(nodes.size());
  switch (type) {
    case kVertex:
    case kPolyVertex:
      ++vertexCells;
      return true;
    case kLine:
    case kPolyLine:
    case kQuadraticEdge:
    case kCubicLine:
      ++lineCells;
      return true;
    case kPolygon:
      if (size < 3) return false;
      addPolygon(nodes, cell);
      return true;
    case kStrip:
      if (size < 3) return false;
      addStrip(nodes, cell);
      return true;
    default:
      break;
  }
  const int corners = cornerCount(type);
  if (corners == 0) {
    ++otherCells;
    ++unsupportedTypes[type];
    return true;
  }
  if (size != fullCount(type)) return false;
  if (type == kTriangle || type == kQuadraticTriangle) {
    addPolygon(nodes.first(3), cell);
  } else if (type == kQuad || type == kQuadraticQuad || type == kBiquadraticQuad) {
    addPolygon(nodes.first(4), cell);
  } else if (type == kPixel) {
    const std::array<int, 4> quad = {nodes[0], nodes[1], nodes[3], nodes[2]};
    addPolygon(quad, cell);
  } else {
    addSolid(type, nodes, cell);
  }
  return true;
}

void CellTriangulator::addBoundaryFaces() {
  // Sort faces by their node sets; a set that occurs once is on the boundary.
  std::vector<std::pair<std::array<int, 4>, std::size_t>> keys(faces_.size());
  for (std::size_t i = 0; i < faces_.size(); ++i) {
    auto key = faces_[i].nodes;
    std::sort(key.begin(), key.end());
    keys[i] = {key, i};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::size_t> boundary;
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j].first == keys[i].first) ++j;
    if (j == i + 1) boundary.push_back(keys[i].second);
    i = j;
  }
  std::sort(boundary.begin(), boundary.end());  // keep the cells' order
  for (const std::size_t i : boundary) {
    const Face& f = faces_[i];
    addPolygon(std::span<const int>(f.nodes.data(), f.nodes[3] < 0 ? 3 : 4), f.cell);
  }
  faces_.clear();
}

}  // namespace ddfcam::io::detail
