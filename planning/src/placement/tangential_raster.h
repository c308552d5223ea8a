// SPDX-License-Identifier: MIT
// ddfcam: parallel-projection z-buffer rasterization onto a tangential grid (private helpers).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/placement/tangential_grid.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ddfcam::planning::detail {

/// A point in tangent-frame coordinates (u, v, w), mm.
struct Local {
  double u = 0.0, v = 0.0, w = 0.0;
};

/// Cell-centred lattice over a rectangle of the tangent plane; the box top is wTop.
struct GridBox {
  double u0 = 0.0, v0 = 0.0, du = 1.0, dv = 1.0;
  int nu = 0, nv = 0;
  double wTop = 0.0;
  int cells() const { return nu * nv; }
};

constexpr float kInf = std::numeric_limits<float>::infinity();

/// Bounding rectangle of @p pts (plus margin) split into gridSize x gridSize cells.
GridBox footprintBox(const std::vector<Local>& pts, int gridSize, double marginMm);

/// Vertices of @p mesh mapped by @p pose into @p frame coordinates.
void transformMesh(const ddf::TriangleMesh& mesh, const Eigen::Isometry3d& pose,
                   const TangentFrame& frame, std::vector<Local>& out);

/// Scanline rasterization of one triangle: visit(cell, w) for every cell centre inside the
/// (u, v) projection (closed, so neighbours both see shared edges), w linear on the triangle.
template <class Visit>
void rasterizeTriangle(const GridBox& g, const Local& a, const Local& b, const Local& c,
                       Visit&& visit) {
  const double bu = b.u - a.u, bv = b.v - a.v, cu = c.u - a.u, cv = c.v - a.v;
  const double det = bu * cv - cu * bv;
  const double scale = std::max({std::abs(bu), std::abs(bv), std::abs(cu), std::abs(cv)});
  if (!(std::abs(det) > 1e-12 * scale * scale)) return;  // edge-on: its neighbours cover it
  const double dwdu = ((b.w - a.w) * cv - (c.w - a.w) * bv) / det;
  const double dwdv = (bu * (c.w - a.w) - cu * (b.w - a.w)) / det;
  const double vmin = std::min({a.v, b.v, c.v}), vmax = std::max({a.v, b.v, c.v});
  constexpr double kEps = 1e-9;
  const int r0 = std::max(0, static_cast<int>(std::ceil((vmin - g.v0) / g.dv - 0.5 - kEps)));
  const int r1 =
      std::min(g.nv - 1, static_cast<int>(std::floor((vmax - g.v0) / g.dv - 0.5 + kEps)));
  const Local* p[3] = {&a, &b, &c};
  for (int row = r0; row <= r1; ++row) {
    const double vc = g.v0 + (row + 0.5) * g.dv;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int e = 0; e < 3; ++e) {
      const Local& s = *p[e];
      const Local& t = *p[(e + 1) % 3];
      const double lo_v = std::min(s.v, t.v), hi_v = std::max(s.v, t.v);
      if (vc < lo_v - kEps * g.dv || vc > hi_v + kEps * g.dv) continue;
      if (hi_v - lo_v <= 1e-15) {  // edge along the row
        lo = std::min({lo, s.u, t.u});
        hi = std::max({hi, s.u, t.u});
        continue;
      }
      const double x = s.u + std::clamp((vc - s.v) / (t.v - s.v), 0.0, 1.0) * (t.u - s.u);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    if (!(hi >= lo)) continue;
    const int c0 = std::max(0, static_cast<int>(std::ceil((lo - g.u0) / g.du - 0.5 - kEps)));
    const int c1 =
        std::min(g.nu - 1, static_cast<int>(std::floor((hi - g.u0) / g.du - 0.5 + kEps)));
    const double wRow = a.w + dwdv * (vc - a.v) - dwdu * a.u;
    for (int col = c0; col <= c1; ++col)
      visit(col + row * g.nu, wRow + dwdu * (g.u0 + (col + 0.5) * g.du));
  }
}

/// z-buffer of the lowest crossing: h = min over triangles per cell (h pre-filled with +inf).
/// Triangles wholly above @p cutoff are skipped: where only they cover a cell, its lowest
/// crossing lies above cutoff too, which callers treat like no tool (nothing reaches it).
void rasterizeMin(const ddf::TriangleMesh& mesh, const std::vector<Local>& local, const GridBox& g,
                  std::vector<float>& h, double cutoff = std::numeric_limits<double>::infinity());

/// Raster points of face @p f of @p ddf in @p frame coordinates, in Raster order.
void faceLocalPoints(const ddf::DisplacementField& ddf, int f, const TangentFrame& frame,
                     std::vector<Local>& out);

/// Visits every cell centre inside the raster triangles (fig. 7.1a) of face @p f: visit(cell, w).
/// @p pts must hold faceLocalPoints(f).
template <class Visit>
void rasterizeFace(const ddf::DisplacementField& ddf, const std::vector<Local>& pts,
                   const GridBox& g, Visit&& visit) {
  const ddf::Raster& r = ddf.raster();
  const int n = r.steps();
  for (int k = 0; k < n; ++k) {
    const std::size_t row = r.rowOffset(k), next = r.rowOffset(k + 1);
    for (int i = 0; i + k < n; ++i) {
      rasterizeTriangle(g, pts[row + i], pts[row + i + 1], pts[next + i], visit);
      if (i + k + 2 <= n)
        rasterizeTriangle(g, pts[row + i + 1], pts[next + i + 1], pts[next + i], visit);
    }
  }
}

/// The hull of face @p f in @p frame coordinates: its (u, v) rectangle and w range.
struct LocalBounds {
  double u0, u1, v0, v1, w0, w1;
};
LocalBounds localHullBounds(const SurfacePatchIndex& index, int f, const TangentFrame& frame);

/// Part-frame axis-aligned box around the tangent box [g.u*] x [g.v*] x [wLow, g.wTop].
Eigen::AlignedBox3d partBox(const GridBox& g, const TangentFrame& frame, double wLow);

}  // namespace ddfcam::planning::detail
