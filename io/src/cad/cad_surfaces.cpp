// SPDX-License-Identifier: MIT
// ddfcam: exact-surface queries on a CAD model: closest points and principal curvatures.
#include "cad_model_impl.h"

#include <ddfcam/error.h>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace ddfcam::io {
namespace {

Eigen::Vector3d toEigen(const gp_XYZ& p) {
  return {p.X(), p.Y(), p.Z()};
}
gp_Pnt toPnt(const Eigen::Vector3d& p) {
  return gp_Pnt(p.x(), p.y(), p.z());
}

struct FaceEntry {
  TopoDS_Face face;
  Handle(Geom_Surface) surface;
  Eigen::Vector3d boxMin = Eigen::Vector3d::Zero();
  Eigen::Vector3d boxMax = Eigen::Vector3d::Zero();
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;  ///< the face's parameter box
  bool reversed = false;
  std::unique_ptr<GeomAPI_ProjectPointOnSurf> projector;
  std::unique_ptr<BRepTopAdaptor_FClass2d> classifier;

  double boxDistance(const Eigen::Vector3d& p) const {
    return (p.cwiseMax(boxMin).cwiseMin(boxMax) - p).norm();
  }
};

/// The parameter box the surface feet are searched in: the face's box widened by a share of
/// its span (within the surface's own bounds where it is not periodic). Extrema drops a foot
/// more than 1e-9 outside its box, and a point on a face border often has its foot there by
/// rounding (on sliced_cylinder.step's bottom circle: a fifth of its cylinders' raster points at
/// m = 5 had no foot). Widening cannot hide a closer point: a foot outside the face is
/// classified as such and only bounds the face's distance from below.
std::array<double, 4> searchBox(const FaceEntry& entry) {
  constexpr double kShare = 0.05;
  double su0, su1, sv0, sv1;
  entry.surface->Bounds(su0, su1, sv0, sv1);
  const double du = kShare * (entry.u1 - entry.u0), dv = kShare * (entry.v1 - entry.v0);
  std::array<double, 4> box = {entry.u0 - du, entry.u1 + du, entry.v0 - dv, entry.v1 + dv};
  if (!entry.surface->IsUPeriodic()) {
    box[0] = std::max(box[0], su0);
    box[1] = std::min(box[1], su1);
  }
  if (!entry.surface->IsVPeriodic()) {
    box[2] = std::max(box[2], sv0);
    box[3] = std::min(box[3], sv1);
  }
  return box;
}

}  // namespace

struct CadSurfaceQuery::Impl {
  std::vector<FaceEntry> faces;
  double toleranceMm = 1e-7;

  /// The foot of @p p on the face's surface, if the surface projection succeeds.
  std::optional<std::pair<double, double>> footUv(const FaceEntry& entry,
                                                  const Eigen::Vector3d& p) const {
    entry.projector->Perform(toPnt(p));
    if (!entry.projector->IsDone() || entry.projector->NbPoints() == 0) return std::nullopt;
    double u = 0, v = 0;
    entry.projector->LowerDistanceParameters(u, v);
    return std::make_pair(u, v);
  }

  /// The foot of @p p on one face's surface: its distance bounds the trimmed face's distance
  /// from below; when the foot lies inside the face it is the face's closest point.
  struct Foot {
    CadProjection projection;
    bool inside = false;
  };
  std::optional<Foot> surfaceFoot(int index, const Eigen::Vector3d& p) const {
    const FaceEntry& entry = faces[index];
    const auto uv = footUv(entry, p);
    if (!uv) return std::nullopt;
    const Eigen::Vector3d foot = toEigen(entry.surface->Value(uv->first, uv->second).XYZ());
    const TopAbs_State state = entry.classifier->Perform(gp_Pnt2d(uv->first, uv->second));
    return Foot{{foot, (foot - p).norm(), index}, state == TopAbs_IN || state == TopAbs_ON};
  }

  /// The closest point of one trimmed face by the general, boundary-aware distance.
  std::optional<CadProjection> trimmedFace(int index, const Eigen::Vector3d& p) const {
    const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(toPnt(p));
    BRepExtrema_DistShapeShape distance(vertex, faces[index].face);
    if (!distance.IsDone() || distance.NbSolution() == 0) return std::nullopt;
    const Eigen::Vector3d foot = toEigen(distance.PointOnShape2(1).XYZ());
    return CadProjection{foot, distance.Value(), index};
  }
};

CadSurfaceQuery::CadSurfaceQuery(const CadModel& model) : impl_(std::make_unique<Impl>()) {
  const CadModel::Impl& source = model.impl();
  const auto& bounds = source.boundsMm;
  const double slack = 1e-6 * std::max((bounds[1] - bounds[0]).norm(), 1.0);
  impl_->toleranceMm = 1e-9 * std::max((bounds[1] - bounds[0]).norm(), 1.0);
  for (int i = 1; i <= source.faceMap.Extent(); ++i) {
    FaceEntry entry;
    entry.face = TopoDS::Face(source.faceMap(i));
    entry.surface = BRep_Tool::Surface(entry.face);
    entry.reversed = entry.face.Orientation() == TopAbs_REVERSED;
    // The plain box (control points, surface bounds) encloses the face; the optimal one may
    // cut a curved patch short, which would make the prefilter skip the true closest face.
    Bnd_Box box;
    BRepBndLib::Add(entry.face, box, false);
    box.Enlarge(slack);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    entry.boxMin = {x0, y0, z0};
    entry.boxMax = {x1, y1, z1};
    BRepTools::UVBounds(entry.face, entry.u0, entry.u1, entry.v0, entry.v1);
    const auto [u0, u1, v0, v1] = searchBox(entry);
    entry.projector = std::make_unique<GeomAPI_ProjectPointOnSurf>();
    entry.projector->Init(entry.surface, u0, u1, v0, v1);
    entry.classifier =
        std::make_unique<BRepTopAdaptor_FClass2d>(entry.face, BRep_Tool::Tolerance(entry.face));
    impl_->faces.push_back(std::move(entry));
  }
}

CadSurfaceQuery::~CadSurfaceQuery() = default;
CadSurfaceQuery::CadSurfaceQuery(CadSurfaceQuery&&) noexcept = default;
CadSurfaceQuery& CadSurfaceQuery::operator=(CadSurfaceQuery&&) noexcept = default;

std::optional<CadProjection> CadSurfaceQuery::project(const Eigen::Vector3d& pointMm,
                                                      double maxDistanceMm) const {
  const auto& faces = impl_->faces;
  std::vector<std::pair<double, int>> order;
  order.reserve(faces.size());
  for (int i = 0; i < static_cast<int>(faces.size()); ++i) {
    const double d = faces[i].boxDistance(pointMm);
    if (d <= maxDistanceMm) order.emplace_back(d, i);
  }
  std::sort(order.begin(), order.end());
  // Pass 1: surface feet, cheap; a foot inside its face is a candidate, one outside only a lower
  // bound. Pass 2: the boundary-aware distance, only for faces whose bound beats the best.
  std::optional<CadProjection> best;
  std::vector<std::pair<double, int>> outside;
  for (const auto& [boxDistance, index] : order) {
    if (best && boxDistance > best->distanceMm) break;  // no closer point in the rest
    try {
      const auto foot = impl_->surfaceFoot(index, pointMm);
      if (!foot) {
        outside.emplace_back(boxDistance, index);
      } else if (foot->inside) {
        if (!best || foot->projection.distanceMm < best->distanceMm) best = foot->projection;
      } else {
        outside.emplace_back(foot->projection.distanceMm, index);
      }
    } catch (const Standard_Failure&) {
      outside.emplace_back(boxDistance, index);
    }
  }
  std::sort(outside.begin(), outside.end());
  for (const auto& [bound, index] : outside) {
    if (best && bound >= best->distanceMm) break;
    try {
      const auto candidate = impl_->trimmedFace(index, pointMm);
      if (candidate && (!best || candidate->distanceMm < best->distanceMm)) best = candidate;
    } catch (const Standard_Failure&) {
      // A face whose distance fails numerically is skipped; the others still answer.
    }
  }
  if (best && best->distanceMm > maxDistanceMm) return std::nullopt;
  return best;
}

std::optional<CadCurvature> CadSurfaceQuery::curvature(int face,
                                                       const Eigen::Vector3d& pointMm) const {
  if (face < 0 || face >= static_cast<int>(impl_->faces.size()))
    throw InvalidInput("CAD curvature: face " + std::to_string(face) + " out of range [0, " +
                       std::to_string(impl_->faces.size()) + ")");
  const FaceEntry& entry = impl_->faces[face];
  try {
    const auto uv = impl_->footUv(entry, pointMm);
    if (!uv) return std::nullopt;
    GeomLProp_SLProps props(entry.surface, uv->first, uv->second, 2, impl_->toleranceMm);
    if (!props.IsNormalDefined() || !props.IsCurvatureDefined()) return std::nullopt;
    // OpenCASCADE's curvature is II / I along the surface normal du x dv, negative on a sphere
    // seen from outside; ours is positive there and taken w.r.t. the outward (face) normal.
    const double sign = entry.reversed ? 1.0 : -1.0;
    CadCurvature out;
    out.normal = toEigen(props.Normal().XYZ()) * (entry.reversed ? -1.0 : 1.0);
    out.pointMm = toEigen(props.Value().XYZ());
    double a = sign * props.MaxCurvature(), b = sign * props.MinCurvature();
    out.umbilic = props.IsUmbilic();
    gp_Dir dirMax, dirMin;
    if (!out.umbilic) props.CurvatureDirections(dirMax, dirMin);
    Eigen::Vector3d da = out.umbilic ? Eigen::Vector3d::Zero() : toEigen(dirMax.XYZ());
    Eigen::Vector3d db = out.umbilic ? Eigen::Vector3d::Zero() : toEigen(dirMin.XYZ());
    if (a < b) {
      std::swap(a, b);
      std::swap(da, db);
    }
    out.k1 = a;
    out.k2 = b;
    out.dir1 = da;
    out.dir2 = db;
    return out;
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

}  // namespace ddfcam::io
