// SPDX-License-Identifier: MIT
// ddfcam: per-vertex crust intervals of the stock crust fit: caps from the crust heights of the
// unmoved support, pull-back for fitted crust heights and for non-adjacent crust conflicts.
#include "stock_crust_plan.h"

#include <ddfcam/ddf/crust.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/raster_normal.h>
#include <ddfcam/progress.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ddfcam::ddf::detail {
namespace {

constexpr double kPullBack = 0.7;  // factor on s per pull-back step
constexpr double kSnapToZero = 0.03;
// Crust height a fitted face keeps, in units of its vectors. The caps already keep the crust a
// safety factor inside the unmoved support's limits in mm; a margin relative to the vectors
// would grow with them (an asymmetric interval makes them long) and forbid what the caps allow.
constexpr double kFaceMargin = 1.01;

// Raster coordinates (i, k) of the corner of face f at its vertex slot c (p1, p2, p3).
std::array<int, 2> cornerOf(const DisplacementField& ddf, int c) {
  const int n = ddf.raster().steps();
  if (c == 0) return {n, 0};
  if (c == 1) return {0, 0};
  return {0, n};
}

void surfaceAtVertices(const DisplacementField& ddf, CrustPlan& plan) {
  const int nv = ddf.vertexCount();
  plan.sigma.assign(nv, 0.0);
  plan.cosN.assign(nv, 1.0);
  std::vector<char> seen(nv, 0);
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int v = ddf.faceVertices(f)[c];
      const auto [i, k] = cornerOf(ddf, c);
      const Vec3 n = rasterNormal(ddf, f, i, k);
      // The surface point along d0 seen along d: where the tangent plane there meets the line.
      if (!seen[v])
        plan.sigma[v] = ddf.height(f, i, k) * plan.len0[v] * plan.d0[v].dot(n) /
                        std::max(plan.d[v].dot(n), 0.05);
      seen[v] = 1;
      plan.cosN[v] = std::min(plan.cosN[v], plan.d[v].dot(n));
    }
  for (double& c : plan.cosN) c = std::max(c, 0.05);  // a grazing vector: reach needs 20x
}

void capsFromUnitCrust(const DisplacementField& ddf, CrustPlan& plan, double safety) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<CrustHeights> unit(ddf.faceCount());
  plan.faceThreshold.assign(ddf.faceCount(), 1.0);
  tbb::parallel_for(0, ddf.faceCount(), [&](int f) {
    const auto& fv = ddf.faceVertices(f);
    unit[f] = crustHeights(plan.p[fv[0]], plan.p[fv[1]], plan.p[fv[2]], plan.d[fv[0]],
                           plan.d[fv[1]], plan.d[fv[2]]);
    const double converted = crustHeights(ddf, f).min();
    plan.faceThreshold[f] = std::min(kFaceMargin, std::max(1.0, converted));
  });
  plan.capTop.assign(ddf.vertexCount(), inf);
  plan.capBot.assign(ddf.vertexCount(), inf);
  for (int f = 0; f < ddf.faceCount(); ++f) {
    if (unit[f].min() <= 0.0) {  // constraint 1 fails: the interval stays the converted one
      for (int v : ddf.faceVertices(f))
        plan.capTop[v] = plan.capBot[v] = std::min(plan.capTop[v], plan.len0[v]);
      continue;
    }
    for (int v : ddf.faceVertices(f)) {
      plan.capTop[v] = std::min(plan.capTop[v], safety * unit[f].positive);
      plan.capBot[v] = std::min(plan.capBot[v], safety * unit[f].negative);
    }
  }
}

// Coincident vertices must keep one vector (constraint 2): they share the smallest s.
void equalizeClasses(CrustPlan& plan) {
  const int nv = static_cast<int>(plan.s.size());
  for (int v = 0; v < nv; ++v) {
    const int c = plan.vertexClass[v];
    if (c == v) continue;
    plan.s[c] = std::min(plan.s[c], plan.s[v]);
    plan.sBelow[c] = std::min(plan.sBelow[c], plan.sBelow[v]);
    plan.hiT[c] = std::min(plan.hiT[c], plan.hiT[v]);
    plan.loT[c] = std::max(plan.loT[c], plan.loT[v]);
  }
  for (int v = 0; v < nv; ++v) {
    const int c = plan.vertexClass[v];
    plan.s[v] = plan.s[c], plan.sBelow[v] = plan.sBelow[c];
    plan.hiT[v] = plan.hiT[c], plan.loT[v] = plan.loT[c];
  }
}

void pullBack(std::vector<double>& blend, std::vector<char>& changed, int v, double factor) {
  blend[v] *= factor;
  if (blend[v] < kSnapToZero) blend[v] = 0.0;
  changed[v] = 1;
}

void pullBack(CrustPlan& plan, int v, double factor) {
  pullBack(plan.s, plan.changed, v, factor);
}

// A face whose fitted crust folds gives up its extra reach below first, then the top.
void pullBackFace(CrustPlan& plan, const std::array<int, 3>& fv, double factor) {
  bool bottomsMoved = false;
  for (int v : fv)
    bottomsMoved |= plan.s[v] > 0.0 && plan.sBelow[v] > 0.0 && plan.loT[v] < -plan.len0[v];
  for (int v : fv) {
    if (bottomsMoved) {
      if (plan.sBelow[v] > 0.0) pullBack(plan.sBelow, plan.changed, v, factor);
    } else if (plan.s[v] > 0.0) {
      pullBack(plan, v, factor);
      plan.shrunkByFace[v] = 1;
    }
  }
}

}  // namespace

CrustPlan makeCrustPlan(const DisplacementField& ddf, const StockCrustParams& params) {
  CrustPlan plan;
  const int nv = ddf.vertexCount();
  plan.p.resize(nv), plan.d0.resize(nv), plan.len0.resize(nv);
  for (int v = 0; v < nv; ++v) {
    plan.p[v] = ddf.position(v);
    plan.len0[v] = ddf.vector(v).norm();
    plan.d0[v] = ddf.vector(v) / plan.len0[v];
  }
  plan.vertexClass = coincidentVertexClasses(ddf);
  plan.d = plan.d0;
  if (params.chooseDirections)
    chooseDirections(ddf, plan, params, params.stockMm * (1.0 + params.marginFraction));
  surfaceAtVertices(ddf, plan);
  capsFromUnitCrust(ddf, plan, params.safety);
  plan.hiT = plan.len0;
  plan.loT.resize(nv);
  for (int v = 0; v < nv; ++v) plan.loT[v] = -plan.len0[v];
  plan.s.assign(nv, 1.0);
  plan.sBelow.assign(nv, 1.0);
  plan.shrunkByFace.assign(nv, 0);
  plan.facePartner.assign(ddf.faceCount(), -1);
  plan.changed.assign(nv, 1);
  return plan;
}

void equalizeTargets(CrustPlan& plan) {
  equalizeClasses(plan);
}

void setTarget(CrustPlan& plan, int v, double reachMm, double hiTop) {
  const double want = std::max(hiTop, plan.sigma[v] + reachMm / plan.cosN[v]);
  plan.hiT[v] = std::max(plan.len0[v], std::min(plan.capTop[v], want));
  const double mirrored = 2.0 * plan.sigma[v] - plan.hiT[v];
  plan.loT[v] = std::min(-plan.len0[v], std::max(-plan.capBot[v], mirrored));
  plan.changed[v] = 1;
}

void settleFaces(const DisplacementField& ddf, CrustPlan& plan, int maxRounds) {
  std::vector<char> bad(ddf.faceCount());
  for (int pass = 0;; ++pass) {
    tbb::parallel_for(0, ddf.faceCount(), [&](int f) {
      const auto& fv = ddf.faceVertices(f);
      bad[f] = 0;
      if (plan.s[fv[0]] == 0.0 && plan.s[fv[1]] == 0.0 && plan.s[fv[2]] == 0.0) return;
      const CrustHeights h =
          crustHeights(plan.position(fv[0]), plan.position(fv[1]), plan.position(fv[2]),
                       plan.vector(fv[0]), plan.vector(fv[1]), plan.vector(fv[2]));
      bad[f] = h.min() < plan.faceThreshold[f];
    });
    // After maxRounds gradual steps, bad faces fall back to the converted crust at once, which
    // ends the loop: every pass then zeroes at least one vertex.
    const double factor = pass < maxRounds ? kPullBack : 0.0;
    bool any = false;
    for (int f = 0; f < ddf.faceCount(); ++f) {
      if (!bad[f]) continue;
      any = true;
      pullBackFace(plan, ddf.faceVertices(f), factor);
    }
    if (!any) return;
    equalizeClasses(plan);
  }
}

DisplacementField buildField(const DisplacementField& ddf, const CrustPlan& plan) {
  SupportMesh mesh = ddf.support();
  std::vector<Vec3> vectors(ddf.vertexCount());
  for (const auto vh : mesh.vertices()) {
    const int v = vh.idx();
    mesh.set_point(vh, toOpenMesh(plan.position(v)));
    vectors[v] = plan.vector(v);
  }
  return DisplacementField(std::move(mesh), std::move(vectors), ddf.resolution());
}

namespace {

std::vector<int> changedFaces(const DisplacementField& ddf, const CrustPlan& plan) {
  std::vector<char> mark(ddf.faceCount(), 0);
  for (int v = 0; v < ddf.vertexCount(); ++v)
    if (plan.changed[v])
      for (int f : ddf.topology().vertexFaces(v)) mark[f] = 1;
  std::vector<int> out;
  for (int f = 0; f < ddf.faceCount(); ++f)
    if (mark[f]) out.push_back(f);
  return out;
}

// One round: conflicts among the changed faces; pulls back the vertices of each pair.
std::size_t conflictRound(const DisplacementField& ddf, CrustPlan& plan, double factor) {
  const std::vector<int> dirty = changedFaces(ddf, plan);
  std::fill(plan.changed.begin(), plan.changed.end(), 0);
  if (dirty.empty()) return 0;
  const DisplacementField field = buildField(ddf, plan);
  const CrustHash hash(field, crustHashParamsFor(field));
  const auto conflicts = findCrustConflicts(field, hash, dirty, {}, plan.vertexClass);
  std::size_t live = 0;
  for (const auto& pair : conflicts) {
    bool moved = false, bottomsMoved = false;
    for (int f : pair)
      for (int v : ddf.faceVertices(f)) {
        moved |= plan.s[v] > 0.0;
        bottomsMoved |= plan.s[v] > 0.0 && plan.sBelow[v] > 0.0 && plan.loT[v] < -plan.len0[v];
      }
    if (!moved) continue;  // the converted crusts already met here
    ++live;
    // The bottoms go first: the reach below beyond the converted one is only a bonus, and
    // bottoms meeting through a thin wall are the common conflict.
    for (int side = 0; side < 2; ++side)
      for (int v : ddf.faceVertices(pair[side])) {
        if (bottomsMoved) {
          if (plan.sBelow[v] > 0.0) pullBack(plan.sBelow, plan.changed, v, factor);
          continue;
        }
        if (plan.s[v] > 0.0) pullBack(plan, v, factor);
      }
    for (int side = 0; side < 2; ++side) plan.facePartner[pair[side]] = pair[1 - side];
  }
  equalizeClasses(plan);
  return live;
}

}  // namespace

int resolveConflicts(const DisplacementField& ddf, CrustPlan& plan, int maxRounds,
                     const ProgressCallback& progress) {
  settleFaces(ddf, plan, maxRounds);
  int round = 0;
  for (;; ++round) {
    reportProgress(progress, std::min(1.0, double(round) / maxRounds));
    const double factor = round < maxRounds ? kPullBack : 0.0;
    if (conflictRound(ddf, plan, factor) == 0) break;
    settleFaces(ddf, plan, maxRounds);
  }
  return round;
}

}  // namespace ddfcam::ddf::detail
