// SPDX-License-Identifier: MIT
// ddfcam: per-vertex crust intervals of the stock crust fit (private to stock_crust*.cpp).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/stock_crust.h>

#include <algorithm>
#include <vector>

namespace ddfcam::ddf::detail {

/// Per vertex: the crust interval [lo, hi] of offsets along a unit direction from the
/// converted support point p, blended by s from the converted interval [-len0, len0] along the
/// converted direction d0 (s = 0) to the target [loT, hiT] along the chosen direction d (s = 1);
/// the bottom by min(s, sBelow).
struct CrustPlan {
  std::vector<Vec3> p, d0, d;
  std::vector<double> len0;    // converted vector length, mm
  std::vector<double> sigma;   // offset of the represented surface at the vertex, mm
  std::vector<double> cosN;    // smallest d . n at the vertex over its faces
  std::vector<double> capTop;  // safety x h0+ of the unmoved support with unit vectors, mm
  std::vector<double> capBot;  // safety x h0- of the same, mm
  std::vector<double> hiT, loT, s;
  std::vector<double> sBelow;      // the same blend for the bottom: pulled back first on a conflict
  std::vector<char> shrunkByFace;  // pulled back for the crust heights of a face
  std::vector<int> facePartner;    // per face: a face whose crust met its crust, or -1
  std::vector<int> vertexClass;    // coincident-vertex classes (smallest index)
  std::vector<double> faceThreshold;  // crust height each fitted face must keep
  std::vector<char> changed;          // moved since the last conflict round

  double lo(int v) const { return -len0[v] + std::min(s[v], sBelow[v]) * (loT[v] + len0[v]); }
  double hi(int v) const { return len0[v] + s[v] * (hiT[v] - len0[v]); }
  Vec3 direction(int v) const {
    if (s[v] == 0.0) return d0[v];  // exactly the converted vector
    return ((1.0 - s[v]) * d0[v] + s[v] * d[v]).normalized();
  }
  Vec3 position(int v) const { return p[v] + 0.5 * (lo(v) + hi(v)) * direction(v); }
  Vec3 vector(int v) const { return 0.5 * (hi(v) - lo(v)) * direction(v); }
};

/// The plan of @p ddf: directions, converted lengths, surface offsets, caps; s = 1.
CrustPlan makeCrustPlan(const DisplacementField& ddf, const StockCrustParams& params);

/// Sets plan.d: the corner-angle weighted mean of the raster normals at each vertex class,
/// smoothed with the neighbours' directions (params.smoothingPasses passes), each step blended
/// back towards d0 as far as needed to keep d . n > 0.2 (or d0's value) on every incident support
/// face and d within params.maxAngleDeg of every incident raster corner normal (or no further off
/// than d0); then re-chosen near folds for a reach of @p reachMm (see fitCrustToStock), within
/// params.foldRepairAngleDeg.
void chooseDirections(const DisplacementField& ddf, CrustPlan& plan, const StockCrustParams& params,
                      double reachMm);

/// Sets the target interval of vertex @p v for a reach of @p reachMm above, with the top at
/// least @p hiTop (and at most capTop), the bottom mirrored where capBot allows.
void setTarget(CrustPlan& plan, int v, double reachMm, double hiTop = 0.0);

/// Makes coincident vertices share one interval (after setTarget calls).
void equalizeTargets(CrustPlan& plan);

/// Pulls back the vertices of faces whose fitted crust heights are below their threshold until
/// none is; faces with all three vertices at s = 0 are the converted ones and are skipped.
void settleFaces(const DisplacementField& ddf, CrustPlan& plan, int maxRounds);

/// The converted field with the plan's support positions and vectors (heights 0).
DisplacementField buildField(const DisplacementField& ddf, const CrustPlan& plan);

/// Non-adjacent conflict rounds with settle passes in between, until no conflict is left
/// that involves a vertex with s > 0. Returns the number of rounds.
int resolveConflicts(const DisplacementField& ddf, CrustPlan& plan, int maxRounds,
                     const ProgressCallback& progress);

/// Radius of the tightest concave crease of @p mesh within @p withinMm of @p point, mm (+inf
/// where none): per interior edge whose two triangles turn towards their front side by the
/// angle a, 1.5 times the sum of their centroids' distances from the edge line over a (the
/// width of the two half facets over their turn: a faceted cylinder of radius r gives about
/// r sin(pi/N) / (pi/N) where the triangles span a facet, a sharp crease of two triangles of
/// height t about 2 t / pi x their turn's ratio to 90 degrees).
double creaseRadiusNear(const TriangleMesh& mesh, const Vec3& point, double withinMm);

/// Reach above per stored raster point of @p ddf, mm (as crustReach).
std::vector<double> reachAbovePerPoint(const DisplacementField& ddf);

}  // namespace ddfcam::ddf::detail
