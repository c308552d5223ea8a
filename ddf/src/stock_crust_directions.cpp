// SPDX-License-Identifier: MIT
// ddfcam: the vector directions of the stock crust fit: the represented surface's normals,
// smoothed over the support, within constraint 1 and the angle bound, re-chosen near folds.
#include <ddfcam/ddf/crust.h>
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
constexpr int kRepairPasses = 10;  // passes of the fold repair over the vertices, at most
// The fit's correction passes raise a vertex's top to about twice the reach over the vector's
// cosine with the surface normals; the cosine is taken no smaller than kMinTopCos (a grazing
// vector would make every face near it look folded, and its reach is short anyway).
constexpr double kTopReachFactor = 2.0;
constexpr double kMinTopCos = 0.3;
// Crust height the sized vectors of a face must keep: room for the tops the fit actually sets.
constexpr double kFoldRoom = 1.2;
// A candidate direction must improve a vertex's fold score by this factor to be taken.
constexpr double kRepairGain = 1.01;

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

// Whether @p d keeps every incident support face of @p v on its positive side and is not
// further off the surface normals than the angle bound (or than d0 where d0 already is).
bool isAdmissible(const Vec3& d, const Vec3& d0, const VertexNormals& vn, int v,
                  double minSurfaceCos) {
  return worstCos(d, vn.support[v]) >= std::min(kMinSupportCos, worstCos(d0, vn.support[v])) &&
         worstCos(d, vn.surface[v]) >= std::min(minSurfaceCos, worstCos(d0, vn.surface[v]));
}

// The admissible direction nearest to @p want on the way back to @p d0.
Vec3 admissible(const Vec3& want, const Vec3& d0, const VertexNormals& vn, int v,
                double minSurfaceCos) {
  for (int step = 0; step < kBlendSteps; ++step) {
    const double t = 1.0 - double(step) / kBlendSteps;
    const Vec3 d = (t * want + (1.0 - t) * d0).normalized();
    if (isAdmissible(d, d0, vn, v, minSurfaceCos)) return d;
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

// The fold score of support faces under per-class directions (see fitCrustToStock): 1 where the
// face's crust has room for the tops the fit will need, less where it would fold first.
struct FoldScore {
  const DisplacementField& ddf;
  const CrustPlan& plan;
  const VertexNormals& vn;
  const std::vector<int>& cls;
  double topMm;
  std::vector<std::vector<int>> faces;  // per class: its support faces

  double face(const std::vector<Vec3>& d, int f) const {
    const auto& fv = ddf.faceVertices(f);
    std::array<Vec3, 3> unit, top;
    double bottomMm = 0.0;
    for (int j = 0; j < 3; ++j) {
      const int c = cls[fv[j]];
      unit[j] = d[c];
      top[j] = topMm / std::max(worstCos(d[c], vn.surface[c]), kMinTopCos) * d[c];
      bottomMm = std::max(bottomMm, kFoldRoom * plan.len0[fv[j]]);
    }
    const auto& p = plan.p;
    const CrustHeights tops = crustHeights(p[fv[0]], p[fv[1]], p[fv[2]], top[0], top[1], top[2]);
    const CrustHeights units =
        crustHeights(p[fv[0]], p[fv[1]], p[fv[2]], unit[0], unit[1], unit[2]);
    return std::min({tops.positive / kFoldRoom, units.negative / bottomMm, 1.0});
  }
  double vertex(const std::vector<Vec3>& d, int c) const {
    double worst = 1.0;
    for (int f : faces[c]) worst = std::min(worst, face(d, f));
    return worst;
  }
};

// Vertices of faces that would fold try their neighbours' directions, the neighbours' mean and
// blends towards them, keeping the admissible one that best raises their smallest fold score.
void repairFolds(const FoldScore& score, const std::vector<std::vector<int>>& neighbours,
                 const std::vector<Vec3>& d0, double minSurfaceCos, std::vector<Vec3>& d) {
  const int nv = static_cast<int>(d.size());
  for (int pass = 0; pass < kRepairPasses; ++pass) {
    bool moved = false;
    for (int c = 0; c < nv; ++c) {
      if (score.cls[c] != c || neighbours[c].empty()) continue;
      double best = score.vertex(d, c);
      if (best >= 1.0) continue;
      std::vector<Vec3> targets;
      Vec3 mean = Vec3::Zero();
      for (int o : neighbours[c]) targets.push_back(d[o]), mean += d[o];
      if (mean.norm() > 0.0) targets.push_back(mean.normalized());
      const Vec3 kept = d[c];
      Vec3 chosen = kept;
      for (const Vec3& target : targets)
        for (double w : {0.25, 0.5, 0.75, 1.0}) {
          d[c] = ((1.0 - w) * kept + w * target).normalized();
          if (!isAdmissible(d[c], d0[c], score.vn, c, minSurfaceCos)) continue;
          const double now = score.vertex(d, c);
          if (now > kRepairGain * best) best = now, chosen = d[c];
        }
      d[c] = chosen;
      moved |= chosen != kept;
    }
    if (!moved) return;
  }
}

}  // namespace

void chooseDirections(const DisplacementField& ddf, CrustPlan& plan, const StockCrustParams& params,
                      double reachMm) {
  const int nv = ddf.vertexCount();
  const std::vector<int>& cls = plan.vertexClass;
  const VertexNormals vn = vertexNormals(ddf, cls);
  // The bisector of a right-angled crease is at the bound exactly: rounding must not reject it.
  const double minSurfaceCos = std::cos(params.maxAngleDeg * M_PI / 180.0) - 1e-9;
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
  for (int pass = 0; pass < params.smoothingPasses; ++pass) {
    std::vector<Vec3> next = d;
    tbb::parallel_for(0, nv, [&](int v) {
      if (cls[v] != v || neighbours[v].empty()) return;
      Vec3 sum = d[v];
      for (int o : neighbours[v]) sum += d[o] / double(neighbours[v].size());
      next[v] = admissible(sum.normalized(), plan.d0[v], vn, v, minSurfaceCos);
    });
    d.swap(next);
  }
  if (params.repairFolds) {
    FoldScore score{
        ddf, plan, vn, cls, kTopReachFactor * reachMm, std::vector<std::vector<int>>(nv)};
    for (int f = 0; f < ddf.faceCount(); ++f)
      for (int v : ddf.faceVertices(f)) score.faces[cls[v]].push_back(f);
    repairFolds(score, neighbours, plan.d0,
                std::cos(params.foldRepairAngleDeg * M_PI / 180.0) - 1e-9, d);
  }
  for (int v = 0; v < nv; ++v) plan.d[v] = d[cls[v]];
}

}  // namespace ddfcam::ddf::detail
