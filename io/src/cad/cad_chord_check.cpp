// SPDX-License-Identifier: MIT
// ddfcam: the measured chord error of a face's triangulation against its exact surface.
#include "cad_model_impl.h"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Extrema_GenLocateExtPS.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_Surface.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopLoc_Location.hxx>

#include <algorithm>
#include <array>
#include <cmath>

namespace ddfcam::io::detail {
namespace {

// Barycentric weights of the samples: the centroid and the three edge midpoints, where a
// triangle's chord is farthest from a smooth surface it interpolates at its corners.
constexpr std::array<std::array<double, 3>, 4> kSamples = {{
    {1.0 / 3, 1.0 / 3, 1.0 / 3},
    {0.5, 0.5, 0.0},
    {0.0, 0.5, 0.5},
    {0.5, 0.0, 0.5},
}};

}  // namespace

double triangulationChordErrorMm(const TopoDS_Face& face, double checkMm) {
  TopLoc_Location location;
  const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(face, location);
  if (mesh.IsNull() || mesh->NbTriangles() == 0) return 0.0;
  // The surface and the nodes share the face's location: measure in the surface's own frame.
  TopLoc_Location surfaceLocation;
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face, surfaceLocation);
  if (surface.IsNull() || !mesh->HasUVNodes()) return 0.0;
  const gp_Trsf toSurface = surfaceLocation.Transformation().Inverted() * location.Transformation();
  GeomAdaptor_Surface adaptor(surface);
  Extrema_GenLocateExtPS locate(adaptor);
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  GeomAPI_ProjectPointOnSurf global;
  global.Init(surface, u0, u1, v0, v1);
  double worst = 0.0;
  for (int t = 1; t <= mesh->NbTriangles(); ++t) {
    int n[3];
    mesh->Triangle(t).Get(n[0], n[1], n[2]);
    for (const auto& w : kSamples) {
      gp_XYZ p(0, 0, 0);
      gp_XY uv(0, 0);
      for (int c = 0; c < 3; ++c) {
        p += w[c] * mesh->Node(n[c]).Transformed(toSurface).XYZ();
        uv += w[c] * mesh->UVNode(n[c]).XY();
      }
      // The seed's own distance bounds the error from above; the local search (no global
      // search: the seed is the sample's own (u, v)) tightens it.
      const gp_Pnt sample(p);
      double distance = sample.Distance(surface->Value(uv.X(), uv.Y()));
      try {
        locate.Perform(sample, uv.X(), uv.Y(), true);
        if (locate.IsDone()) distance = std::min(distance, std::sqrt(locate.SquareDistance()));
      } catch (const Standard_Failure&) {
        // The upper bound stands.
      }
      // A local search can stall (at a pole, on a strongly curved patch): a sample over the
      // check gets the global foot on the surface.
      if (distance > checkMm) {
        try {
          global.Perform(sample);
          if (global.IsDone() && global.NbPoints() > 0)
            distance = std::min(distance, global.LowerDistance());
        } catch (const Standard_Failure&) {
        }
      }
      worst = std::max(worst, distance);
    }
  }
  return worst;
}

}  // namespace ddfcam::io::detail
