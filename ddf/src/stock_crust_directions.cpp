// SPDX-License-Identifier: MIT
// ddfcam: the vector directions of the stock crust fit: the represented surface's normals,
// smoothed over the support, within constraint 1 and the angle bound.
#include <ddfcam/ddf/raster_normal.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "stock_crust_plan.h"

namespace ddfcam::ddf::detail {
namespace {

constexpr int kBlendSteps = 8;  // steps from the chosen direction back to the converted one
// Smallest cosine between a direction and the normal of an incident support face: the stubbles
// of a face must all point to its positive side (constraint 1) with room for the blend.
constexpr double kMinSupportCos = 0.2;

// Raster coordinates (i, k) of the corner of face f at its vertex slot c (p1, p2, p3).
std::array<int, 2> corner(const DisplacementField& ddf, int c) {
  const int n = ddf.raster().steps();
  if (c == 0) return {n, 0};
  if (c == 1) return {0, 0};
  return {0, n};
}

// Per vertex class: the corner-angle weighted mean of the raster normals at the vertex, and the
// normals of its incident support faces and raster corners (for the constraints).
struct VertexNormals {
  std::vector<Vec3> mean;
  std::vector<std::vector<Vec3>> support, surface;
};

VertexNormals vertexNormals(const DisplacementField& ddf, const std::vector<int>& cls) {
  const int nv = ddf.vertexCount();
  VertexNormals out{std::vector<Vec3>(nv, Vec3::Zero()), std::vector<std::vector<Vec3>>(nv),
                    std::vector<std::vector<Vec3>>(nv)};
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& fv = ddf.faceVertices(f);
    const Vec3 a = ddf.position(fv[0]), b = ddf.position(fv[1]), c = ddf.position(fv[2]);
    const Vec3 ns = (b - a).cross(c - a).normalized();
    const std::array<Vec3, 3> pts{a, b, c};
    for (int j = 0; j < 3; ++j) {
      const auto [i, k] = corner(ddf, j);
      const Vec3 n = rasterNormal(ddf, f, i, k);
      const Vec3 e1 = (pts[(j + 1) % 3] - pts[j]).normalized();
      const Vec3 e2 = (pts[(j + 2) % 3] - pts[j]).normalized();
      const double angle = std::acos(std::clamp(e1.dot(e2), -1.0, 1.0));
      const int v = cls[fv[j]];
      out.mean[v] += angle * n;
      out.support[v].push_back(ns);
      out.surface[v].push_back(n);
    }
  }
  return out;
}

double worstCos(const Vec3& d, const std::vector<Vec3>& normals) {
  double worst = 1.0;
  for (const Vec3& n : normals) worst = std::min(worst, d.dot(n));
  return worst;
}

// The direction nearest to @p want on the way back to @p d0 that keeps every incident support
// face on its positive side and is not further off the surface normals than the angle bound
// (or than d0 where d0 already is).
Vec3 admissible(const Vec3& want, const Vec3& d0, const VertexNormals& vn, int v,
                double minSurfaceCos) {
  const double surfaceBound = std::min(minSurfaceCos, worstCos(d0, vn.surface[v]));
  const double supportBound = std::min(kMinSupportCos, worstCos(d0, vn.support[v]));
  for (int step = 0; step < kBlendSteps; ++step) {
    const double t = 1.0 - double(step) / kBlendSteps;
    const Vec3 d = (t * want + (1.0 - t) * d0).normalized();
    if (worstCos(d, vn.support[v]) >= supportBound && worstCos(d, vn.surface[v]) >= surfaceBound)
      return d;
  }
  return d0;
}

std::vector<std::vector<int>> neighbourClasses(const DisplacementField& ddf,
                                               const std::vector<int>& cls) {
  std::vector<std::vector<int>> out(ddf.vertexCount());
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& fv = ddf.faceVertices(f);
    for (int j = 0; j < 3; ++j)
      for (int o = 1; o < 3; ++o) out[cls[fv[j]]].push_back(cls[fv[(j + o) % 3]]);
  }
  for (auto& list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

}  // namespace

void chooseDirections(const DisplacementField& ddf, CrustPlan& plan, double maxAngleDeg,
                      int smoothingPasses) {
  const int nv = ddf.vertexCount();
  const std::vector<int>& cls = plan.vertexClass;
  const VertexNormals vn = vertexNormals(ddf, cls);
  // The bisector of a right-angled crease is at the bound exactly: rounding must not reject it.
  const double minSurfaceCos = std::cos(maxAngleDeg * M_PI / 180.0) - 1e-9;
  const auto neighbours = neighbourClasses(ddf, cls);
  std::vector<Vec3> d(nv, Vec3::Zero());
  for (int v = 0; v < nv; ++v)
    if (cls[v] == v) {
      const double len = vn.mean[v].norm();
      d[v] =
          len > 0.0 ? admissible(vn.mean[v] / len, plan.d0[v], vn, v, minSurfaceCos) : plan.d0[v];
    }
  // Averaging with the neighbours makes the stubbles of a face more nearly parallel, so they
  // converge less on either side and the crust can be taller.
  for (int pass = 0; pass < smoothingPasses; ++pass) {
    std::vector<Vec3> next = d;
    tbb::parallel_for(0, nv, [&](int v) {
      if (cls[v] != v || neighbours[v].empty()) return;
      Vec3 sum = d[v];
      for (int o : neighbours[v]) sum += d[o] / double(neighbours[v].size());
      next[v] = admissible(sum.normalized(), plan.d0[v], vn, v, minSurfaceCos);
    });
    d.swap(next);
  }
  for (int v = 0; v < nv; ++v) plan.d[v] = d[cls[v]];
}

}  // namespace ddfcam::ddf::detail
