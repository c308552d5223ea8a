// SPDX-License-Identifier: MIT
// ddfcam: the OpenCASCADE side of CadModel, seen only by io/src/cad.
#pragma once

#include <ddfcam/io/cad/cad_model.h>

#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::io {

struct CadModel::Impl {
  TopoDS_Shape shape;                  ///< healed and sewn, mm
  TopTools_IndexedMapOfShape faceMap;  ///< face index + 1 -> TopoDS_Face
  std::vector<CadFace> faces;
  int solids = 0;
  int shells = 0;
  int looseFaces = 0;
  std::optional<ddfcam::LengthUnit> fileUnit;
  std::string fileUnitName;
  ddfcam::LengthUnit unit = ddfcam::LengthUnit::Millimetre;
  bool unitFromFile = false;
  std::array<Eigen::Vector3d, 2> boundsMm = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::vector<std::string> healing;
  double areaMm2 = 0.0;
  double toleranceMm = 0.0;  ///< largest edge or vertex tolerance, mm
};

namespace detail {

/// @brief Lower-case display name of an OpenCASCADE surface type ("plane", "B-spline", ...).
std::string cadSurfaceTypeName(const TopoDS_Shape& face);

/// @brief Exact bounds (min, max) of @p shape, mm; zero for an empty shape.
std::array<Eigen::Vector3d, 2> exactBounds(const TopoDS_Shape& shape);

/// @brief Heals @p shape (ShapeFix_Shape) and sews loose faces and open shells; appends what
/// changed to @p lines. Returns the result.
TopoDS_Shape healShape(const TopoDS_Shape& shape, double sewingToleranceMm,
                       std::vector<std::string>& lines);

/// @brief One face's triangles before welding: nodes in mm (part frame), their (u, v) on the
/// face's surface (empty if the triangulation has none), triangles as node indices.
struct FacePatch {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> uv;
  std::vector<std::array<int, 3>> triangles;
};

/// @brief Largest distance, mm, of the samples of @p face's triangulation (each triangle's
/// centroid and edge midpoints) from the face's exact surface, found by a local search from the
/// sample's own (u, v), and for a sample farther than @p checkMm by a global projection onto the
/// surface within the face's parameter box; 0 without a triangulation or UV nodes.
double triangulationChordErrorMm(const TopoDS_Face& face, double checkMm);

}  // namespace detail
}  // namespace ddfcam::io
