// SPDX-License-Identifier: MIT
// ddfcam: a CAD model as a welded, outward-oriented triangle mesh with one face index per triangle.
#include "cad_model_impl.h"

#include <ddfcam/error.h>

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace ddfcam::io {
namespace {

// Rounds of re-meshing a face whose chord error exceeds the request; each halves its interior
// deflection (1/64 of the request at most).
constexpr int kRefinementRounds = 6;
// Rounds of splitting thin triangles; each halves the longest edges (1/256 at most).

/// Merges points closer than a tolerance: a hash grid of cell = tolerance, searching the 27
/// neighbouring cells, so that points straddling a cell border still meet.
class PointWelder {
 public:
  explicit PointWelder(double tolerance) : tolerance_(tolerance) {}

  int add(const Eigen::Vector3d& p, std::vector<Eigen::Vector3d>& points) {
    const std::array<std::int64_t, 3> cell = cellOf(p);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(key({cell[0] + dx, cell[1] + dy, cell[2] + dz}));
          if (it == cells_.end()) continue;
          for (const int index : it->second)
            if ((points[index] - p).norm() <= tolerance_) return index;
        }
    points.push_back(p);
    cells_[key(cell)].push_back(static_cast<int>(points.size()) - 1);
    return static_cast<int>(points.size()) - 1;
  }

 private:
  std::array<std::int64_t, 3> cellOf(const Eigen::Vector3d& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / tolerance_)),
            static_cast<std::int64_t>(std::floor(p.y() / tolerance_)),
            static_cast<std::int64_t>(std::floor(p.z() / tolerance_))};
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    const auto mix = [](std::int64_t v) {
      return static_cast<std::uint64_t>(v) * 0x9E3779B97F4A7C15ull;
    };
    return mix(c[0]) ^ (mix(c[1]) >> 21) ^ (mix(c[2]) << 21) ^ static_cast<std::uint64_t>(c[2]);
  }

  double tolerance_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

detail::FacePatch patchOf(const TopoDS_Face& face) {
  detail::FacePatch patch;
  TopLoc_Location location;
  const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
  if (triangulation.IsNull()) return patch;
  const gp_Trsf transform = location.Transformation();
  for (int n = 1; n <= triangulation->NbNodes(); ++n) {
    const gp_Pnt p = triangulation->Node(n).Transformed(transform);
    patch.points.emplace_back(p.X(), p.Y(), p.Z());
    if (triangulation->HasUVNodes())
      patch.uv.emplace_back(triangulation->UVNode(n).X(), triangulation->UVNode(n).Y());
  }
  // A reversed face's surface normal points inwards: its triangles are flipped.
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  for (int t = 1; t <= triangulation->NbTriangles(); ++t) {
    int a, b, c;
    triangulation->Triangle(t).Get(a, b, c);
    if (reversed) std::swap(b, c);
    patch.triangles.push_back({a - 1, b - 1, c - 1});
  }
  return patch;
}

void appendFace(const detail::FacePatch& patch, int faceIndex, PointWelder& welder,
                CadTessellation& out) {
  std::vector<int> nodeIndex(patch.points.size());
  for (std::size_t n = 0; n < patch.points.size(); ++n)
    nodeIndex[n] = welder.add(patch.points[n], out.mesh.vertices);
  for (const auto& t : patch.triangles) {
    const std::array<int, 3> tri = {nodeIndex[t[0]], nodeIndex[t[1]], nodeIndex[t[2]]};
    // Poles and degenerate edges collapse to one vertex in the weld.
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
    out.mesh.triangles.push_back(tri);
    out.faceOfTriangle.push_back(faceIndex);
  }
}

IMeshTools_Parameters meshParameters(const CadTessellationParams& params) {
  IMeshTools_Parameters mesh;
  mesh.Deflection = params.chordDeflectionMm;
  mesh.Angle = params.angularDeflectionRad;
  mesh.InParallel = true;
  return mesh;
}

/// Re-meshes the faces whose measured chord error exceeds the requested deflection with a
/// finer interior deflection. The boundary deflection stays, so BRepMesh reuses the edges'
/// nodes, which the neighbouring faces share: the weld stays closed.
void refineChordError(const std::vector<TopoDS_Face>& faces, const CadTessellationParams& params,
                      CadTessellation& out) {
  const double target = params.chordDeflectionMm;
  std::vector<double> interior(faces.size(), target);
  std::vector<double> error(faces.size(), 0.0);
  std::vector<bool> refined(faces.size(), false);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    error[i] = detail::triangulationChordErrorMm(faces[i], target);
    reportProgress(params.progress, 0.5 * static_cast<double>(i + 1) / faces.size());
  }
  out.initialChordErrorMm = *std::max_element(error.begin(), error.end());
  for (int round = 0; round < kRefinementRounds; ++round) {
    bool any = false;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      if (error[i] <= target) continue;
      any = true;
      refined[i] = true;
      // Halving (rather than the error ratio) keeps faces whose overshoot is local from
      // multiplying their triangles everywhere.
      interior[i] *= 0.5;
      IMeshTools_Parameters mesh = meshParameters(params);
      mesh.DeflectionInterior = interior[i];
      mesh.InParallel = false;
      // Without this BRepMesh raises a face's deflection to its edges'.
      mesh.ForceFaceDeflection = true;
      // BRepMesh keeps a triangulation made with the same boundary deflection.
      BRepTools::Clean(faces[i]);
      BRepMesh_IncrementalMesh(faces[i], mesh);
      error[i] = detail::triangulationChordErrorMm(faces[i], target);
    }
    reportProgress(params.progress, 0.5 + 0.4 * (round + 1) / kRefinementRounds);
    if (!any) break;
  }
  for (std::size_t i = 0; i < faces.size(); ++i)
    if (refined[i]) out.refinedFaces.push_back(static_cast<int>(i));
  out.chordErrorMm = *std::max_element(error.begin(), error.end());
}

}  // namespace

CadTessellation tessellateCadModel(const CadModel& model, const CadTessellationParams& params) {
  if (!(params.chordDeflectionMm > 0.0) || !(params.angularDeflectionRad > 0.0))
    throw InvalidInput("CAD tessellation: chord and angular deflection must be positive");
  const CadModel::Impl& impl = model.impl();
  const auto& bounds = impl.boundsMm;
  const double diagonal = (bounds[1] - bounds[0]).norm();
  const double weld =
      params.weldToleranceMm > 0 ? params.weldToleranceMm : std::max(1e-7 * diagonal, 1e-12);
  CadTessellation out;
  try {
    reportProgress(params.progress, 0.0);
    // The mesh is stored in the faces; a copy keeps a shared model's faces untouched (and an
    // earlier, finer triangulation from being reused for a coarser request).
    BRepBuilderAPI_Copy copier(impl.shape, false, false);
    const TopoDS_Shape copy = copier.Shape();
    BRepMesh_IncrementalMesh mesher(copy, meshParameters(params));
    std::vector<TopoDS_Face> faces;
    for (int i = 1; i <= impl.faceMap.Extent(); ++i) {
      TopoDS_Face face = TopoDS::Face(copier.ModifiedShape(impl.faceMap(i)));
      // ModifiedShape keeps the orientation of the face as it sits in the original map.
      face.Orientation(impl.faceMap(i).Orientation());
      faces.push_back(face);
    }
    refineChordError(faces, params, out);
    PointWelder welder(weld);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      detail::FacePatch patch = patchOf(faces[i]);
      appendFace(patch, static_cast<int>(i), welder, out);
    }
    reportProgress(params.progress, 1.0);
  } catch (const Standard_Failure& failure) {
    throw IoError(std::string("CAD tessellation failed in OpenCASCADE (") +
                  failure.GetMessageString() + ")");
  }
  if (out.mesh.triangles.empty()) throw IoError("CAD tessellation produced no triangles");
  return out;
}

}  // namespace ddfcam::io
