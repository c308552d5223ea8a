// SPDX-License-Identifier: MIT
// ddfcam: CadModel accessors and the small facts shared by the CAD sources.
#include "cad_model_impl.h"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomAbs_SurfaceType.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

namespace ddfcam::io {

CadModel::CadModel() : impl_(std::make_shared<const Impl>()) {}
CadModel::~CadModel() = default;
CadModel::CadModel(const CadModel&) = default;
CadModel& CadModel::operator=(const CadModel&) = default;
CadModel::CadModel(CadModel&&) noexcept = default;
CadModel& CadModel::operator=(CadModel&&) noexcept = default;
CadModel::CadModel(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

const std::vector<CadFace>& CadModel::faces() const {
  return impl_->faces;
}
int CadModel::solidCount() const {
  return impl_->solids;
}
int CadModel::shellCount() const {
  return impl_->shells;
}
int CadModel::looseFaceCount() const {
  return impl_->looseFaces;
}
std::optional<ddfcam::LengthUnit> CadModel::fileUnit() const {
  return impl_->fileUnit;
}
const std::string& CadModel::fileUnitName() const {
  return impl_->fileUnitName;
}
ddfcam::LengthUnit CadModel::unit() const {
  return impl_->unit;
}
bool CadModel::unitFromFile() const {
  return impl_->unitFromFile;
}
std::array<Eigen::Vector3d, 2> CadModel::boundsMm() const {
  return impl_->boundsMm;
}
const std::vector<std::string>& CadModel::healing() const {
  return impl_->healing;
}
double CadModel::areaMm2() const {
  return impl_->areaMm2;
}

double CadModel::toleranceMm() const {
  return impl_->toleranceMm;
}

std::vector<std::string> CadModel::faceNames() const {
  std::vector<std::string> names;
  names.reserve(impl_->faces.size());
  for (const CadFace& face : impl_->faces) names.push_back(face.name);
  return names;
}

namespace detail {

std::string cadSurfaceTypeName(const TopoDS_Shape& face) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(face));
  if (surface.IsNull()) return "no surface";
  switch (GeomAdaptor_Surface(surface).GetType()) {
    case GeomAbs_Plane:
      return "plane";
    case GeomAbs_Cylinder:
      return "cylinder";
    case GeomAbs_Cone:
      return "cone";
    case GeomAbs_Sphere:
      return "sphere";
    case GeomAbs_Torus:
      return "torus";
    case GeomAbs_BezierSurface:
      return "Bezier";
    case GeomAbs_BSplineSurface:
      return "B-spline";
    case GeomAbs_SurfaceOfRevolution:
      return "surface of revolution";
    case GeomAbs_SurfaceOfExtrusion:
      return "surface of extrusion";
    case GeomAbs_OffsetSurface:
      return "offset surface";
    case GeomAbs_OtherSurface:
      break;
  }
  return "other surface";
}

std::array<Eigen::Vector3d, 2> exactBounds(const TopoDS_Shape& shape) {
  Bnd_Box box;
  // Without the triangulation and the shape tolerances: the box of the exact geometry. Its
  // optimisation can stop short on rational patches (0.9958 on the unit biquartic sphere), so
  // the nodes of a fine triangulation, which lie on the surfaces, extend it.
  BRepBndLib::AddOptimal(shape, box, false, false);
  if (box.IsVoid()) return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  Eigen::Vector3d lo(x0, y0, z0), hi(x1, y1, z1);
  const TopoDS_Shape copy = BRepBuilderAPI_Copy(shape, false, false).Shape();
  BRepMesh_IncrementalMesh mesher(copy, 1e-3 * (hi - lo).norm(), false, 0.2, true);
  for (TopExp_Explorer it(copy, TopAbs_FACE); it.More(); it.Next()) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) mesh =
        BRep_Tool::Triangulation(TopoDS::Face(it.Current()), location);
    if (mesh.IsNull()) continue;
    for (int n = 1; n <= mesh->NbNodes(); ++n) {
      const gp_Pnt p = mesh->Node(n).Transformed(location.Transformation());
      lo = lo.cwiseMin(Eigen::Vector3d(p.X(), p.Y(), p.Z()));
      hi = hi.cwiseMax(Eigen::Vector3d(p.X(), p.Y(), p.Z()));
    }
  }
  return {lo, hi};
}

}  // namespace detail
}  // namespace ddfcam::io
