// SPDX-License-Identifier: MIT
// ddfcam: fitting support offsets and vector lengths so that the crust holds a stock allowance.
#include "stock_crust_plan.h"

#include "deformation_stage.h"

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/stock_crust.h>
#include <ddfcam/error.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace ddfcam::ddf {
namespace {

constexpr int kCorrectionPasses = 6;
constexpr int kStalePasses = 2;  // correction passes without a gain that end them
// A refilled raster point may move this far from the converted surface point, mm.
constexpr double kDriftMm = 1e-4;

void checkParams(const StockCrustParams& p) {
  if (!(p.stockMm > 0.0) || !std::isfinite(p.stockMm))
    throw InvalidInput("fitCrustToStock: the stock allowance must be > 0 mm, got " +
                       std::to_string(p.stockMm));
  if (!(p.marginFraction >= 0.0) || !std::isfinite(p.marginFraction))
    throw InvalidInput("fitCrustToStock: marginFraction must be >= 0, got " +
                       std::to_string(p.marginFraction));
  if (!(p.safety > 0.0 && p.safety <= 1.0) || p.maxRounds < 1)
    throw InvalidInput("fitCrustToStock: need safety in (0, 1] and maxRounds >= 1");
  if (p.smoothingPasses < 0)
    throw InvalidInput("fitCrustToStock: smoothingPasses must be >= 0, got " +
                       std::to_string(p.smoothingPasses));
  if (!(p.maxAngleDeg > 0.0 && p.maxAngleDeg < 90.0))
    throw InvalidInput("fitCrustToStock: maxAngleDeg must be in (0, 90), got " +
                       std::to_string(p.maxAngleDeg));
  if (!(p.foldRepairAngleDeg >= p.maxAngleDeg && p.foldRepairAngleDeg < 90.0))
    throw InvalidInput("fitCrustToStock: foldRepairAngleDeg must be in [maxAngleDeg, 90), got " +
                       std::to_string(p.foldRepairAngleDeg));
}

// The old surface point of every raster point, expressed on the stubble of the new field (the
// height of its projection onto the stubble line), for points the fill does not reach.
void presetHeights(const DisplacementField& old, DisplacementField& out) {
  tbb::parallel_for(0, out.faceCount(), [&](int f) {
    auto heights = out.heights(f);
    for (int k = 0; k <= out.raster().steps(); ++k)
      for (int i = 0; i < out.raster().rowLength(k); ++i) {
        const Vec3 bary = out.rasterBary(i, k);
        const Vec3 v = out.vectorAt(f, bary);
        const double h =
            (old.surfacePoint(f, i, k) - out.basePoint(f, bary)).dot(v) / v.squaredNorm();
        heights[out.raster().index(i, k)] = static_cast<float>(std::clamp(h, -1.0, 1.0));
      }
  });
  out.synchronizeShared(SharedPolicy::Canonical);
}

// Faces with a raster point that the refill left further off the input than the converted
// surface point was: a stubble that misses the input keeps the preset height, which lies off
// the converted point by its distance from the new stubble line (or more where the height was
// clamped to the crust). A point that missed in the converted field too may move by as much.
std::vector<int> driftedFaces(const DisplacementField& old, const DisplacementField& out,
                              const FillReport& report, const detail::TriangleBvh& bvh) {
  std::vector<char> bad(out.faceCount(), 0);
  const std::size_t per = out.pointsPerFace();
  tbb::parallel_for(0, out.faceCount(), [&](int f) {
    for (int k = 0; k <= out.raster().steps() && !bad[f]; ++k)
      for (int i = 0; i < out.raster().rowLength(k); ++i) {
        if (!report.missingMask[f * per + out.raster().index(i, k)]) continue;
        const double was = bvh.distance(old.surfacePoint(f, i, k));
        if (bvh.distance(out.surfacePoint(f, i, k)) > was + kDriftMm) {
          bad[f] = 1;
          break;
        }
      }
  });
  std::vector<int> faces;
  for (int f = 0; f < out.faceCount(); ++f)
    if (bad[f]) faces.push_back(f);
  return faces;
}

// The vertices of drifted faces first keep their converted direction (the stubble line of a
// converted vector with a longer interval meets the input where the converted one did), then,
// drifting again, their converted vector. False when nothing was left to revert.
bool revertDrifted(const DisplacementField& ddf, const std::vector<int>& drifted,
                   detail::CrustPlan& plan) {
  std::vector<char> turnBack(ddf.vertexCount(), 0);
  bool moved = false;
  for (int f : drifted)
    for (int v : ddf.faceVertices(f)) {
      const int c = plan.vertexClass[v];
      if (plan.d[v] != plan.d0[v]) {
        turnBack[c] = 1;
      } else if (plan.s[v] > 0.0) {
        plan.s[v] = 0.0;
      } else {
        continue;
      }
      moved = true;
      plan.changed[v] = 1;
    }
  for (int v = 0; v < ddf.vertexCount(); ++v)
    if (turnBack[plan.vertexClass[v]]) plan.d[v] = plan.d0[v], plan.changed[v] = 1;
  return moved;
}

DisplacementField fitAndFill(const DisplacementField& ddf, const TriangleMesh& input,
                             const detail::TriangleBvh& bvh, detail::CrustPlan& plan,
                             const StockCrustParams& params) {
  // A face whose refill drifts goes back to the converted support and vectors (s = 0 on its
  // vertices), where the preset height is the converted one exactly; the neighbours that
  // share those vertices may then drift in turn, hence the rounds.
  for (int round = 0;; ++round) {
    detail::equalizeTargets(plan);
    detail::resolveConflicts(ddf, plan, params.maxRounds, params.progress);
    DisplacementField out = detail::buildField(ddf, plan);
    presetHeights(ddf, out);
    const CrustHash hash(out, crustHashParamsFor(out));
    FillParams fill;
    fill.progress = params.progress;
    const FillReport report = fillFromMesh(out, hash, input, fill);
    const std::vector<int> drifted = driftedFaces(ddf, out, report, bvh);
    if (!revertDrifted(ddf, drifted, plan) || round >= params.maxRounds)
      return out;  // drifts the converted field had
  }
}

// Vertices of faces whose reach is short get a higher target; false when none can.
bool raiseShortVertices(const DisplacementField& fitted, detail::CrustPlan& plan, double reachMm) {
  const std::vector<double> above = detail::reachAbovePerPoint(fitted);
  const std::size_t per = fitted.pointsPerFace();
  std::vector<double> deficit(fitted.vertexCount(), 0.0);
  for (std::size_t at = 0; at < above.size(); ++at) {
    if (above[at] >= reachMm * (1.0 - 1e-3)) continue;
    for (int v : fitted.faceVertices(static_cast<int>(at / per)))
      deficit[v] = std::max(deficit[v], reachMm - above[at]);
  }
  bool raised = false;
  for (int v = 0; v < fitted.vertexCount(); ++v) {
    if (deficit[v] == 0.0 || plan.s[v] == 0.0 || plan.hiT[v] >= plan.capTop[v]) continue;
    const double before = plan.hiT[v];
    detail::setTarget(plan, v, reachMm, before + 1.1 * deficit[v] / plan.cosN[v]);
    raised |= plan.hiT[v] > before;
  }
  return raised;
}

std::string mm(double value) {
  std::ostringstream s;
  s.precision(3);
  s << value;
  return s.str();
}

// A meeting of crusts that pulled the limit's face back: its own, or that of a face sharing a
// vertex with it, as the partner face and the text naming the pair.
std::string meetingOf(const detail::CrustPlan& plan, const DisplacementField& fitted,
                      StockLimit& limit) {
  const auto& fv = fitted.faceVertices(limit.face);
  const int own = plan.facePartner[limit.face];
  if (own >= 0) {
    limit.otherFace = own;
    return "its crust would meet the crust of support face " + std::to_string(own);
  }
  for (int v : fv) {
    if (plan.s[v] >= 1.0) continue;
    for (int f : fitted.topology().vertexFaces(v))
      if (plan.facePartner[f] >= 0) {
        limit.otherFace = plan.facePartner[f];
        return "its vertex " + std::to_string(v) + " is shared with support face " +
               std::to_string(f) + ", whose crust would meet the crust of support face " +
               std::to_string(limit.otherFace);
      }
  }
  return {};
}

// Why the crust of the limit's face stays short, as the end of the refusal; sets the cause.
std::string limitCause(const detail::CrustPlan& plan, const DisplacementField& fitted,
                       const TriangleMesh& input, double reachMm, StockLimit& limit) {
  const auto& fv = fitted.faceVertices(limit.face);
  const double inf = std::numeric_limits<double>::infinity();
  // A smooth concave region shows in the curvature fit over the allowance, a sharp concave
  // crease (which that fit smooths away) in the turn of the input's triangles across an edge.
  const double radius = std::min(concaveRadiusNear(input, limit.point, 0.5 * reachMm),
                                 detail::creaseRadiusNear(input, limit.point, reachMm));
  limit.concaveRadiusMm = inf;
  if (radius <= reachMm) {
    limit.concaveRadiusMm = radius;
    return "the surface is concave there with radius " + mm(radius) + " mm (within " + mm(reachMm) +
           " mm of the point)";
  }
  bool capped = false, folded = false;
  double cap = inf, cosN = 1.0;
  for (int v : fv) {
    folded |= plan.shrunkByFace[v] && plan.s[v] < 1.0;
    capped |= plan.hiT[v] >= plan.capTop[v] * (1.0 - 1e-9);
    cap = std::min(cap, plan.capTop[v]);
    cosN = std::min(cosN, plan.cosN[v]);
  }
  const std::string meeting = meetingOf(plan, fitted, limit);
  if (!meeting.empty())
    return meeting + " (a neighbouring sheet across a gap, or the other side of a thin wall)";
  if (folded) return "the crust of the moved support would fold there (crust height below 1)";
  if (capped)
    return "the support's crust cannot reach further out there (" + mm(cap) +
           " mm from the support, the vector " + mm(std::acos(cosN) * 180.0 / M_PI) +
           " degrees off the surface normal) although the input is not concave within " +
           mm(reachMm) + " mm; a finer support may hold it";
  return "the crust could not be lengthened enough there in the correction passes";
}

StockLimit describeLimit(const detail::CrustPlan& plan, const DisplacementField& fitted,
                         const TriangleMesh& input, const StockCrustParams& params,
                         const CrustReach& reach) {
  StockLimit limit;
  limit.face = reach.minAboveFace;
  limit.point = reach.minAbovePoint;
  limit.largestAllowanceMm = reach.minAboveMm;
  const double reachMm = params.stockMm * (1.0 + params.marginFraction);
  const std::string cause = limitCause(plan, fitted, input, reachMm, limit);
  std::ostringstream s;
  s << "a stock of " << mm(params.stockMm) << " mm does not fit at (" << mm(limit.point.x()) << ", "
    << mm(limit.point.y()) << ", " << mm(limit.point.z()) << ") mm (support face " << limit.face
    << "): " << cause << "; the largest stock the crust holds everywhere is "
    << mm(limit.largestAllowanceMm) << " mm";
  limit.message = s.str();
  return limit;
}

// One fit with the directions @p params asks for; @p ddf is left unchanged.
StockFit fitOnce(const DisplacementField& ddf, const TriangleMesh& input,
                 const detail::TriangleBvh& bvh, const StockCrustParams& params,
                 DisplacementField& fitted) {
  const double reachMm = params.stockMm * (1.0 + params.marginFraction);
  detail::CrustPlan plan = detail::makeCrustPlan(ddf, params);
  for (int v = 0; v < ddf.vertexCount(); ++v) detail::setTarget(plan, v, reachMm);
  DisplacementField current = fitAndFill(ddf, input, bvh, plan, params);
  StockFit fit;
  fit.requestedMm = params.stockMm;
  fit.reach = crustReach(current);
  fitted = current;
  detail::CrustPlan kept = plan;
  // A longer top can fold a face that then pulls its vertices back further than the pass
  // raised them, so the pass with the largest smallest reach is kept, and the passes stop
  // when the last ones did not raise it (a concave limit, which no pass moves).
  for (int pass = 0, stale = 0; pass < kCorrectionPasses && stale < kStalePasses; ++pass) {
    if (!raiseShortVertices(current, plan, reachMm)) break;
    current = fitAndFill(ddf, input, bvh, plan, params);
    const CrustReach reach = crustReach(current);
    ++stale;
    if (reach.minAboveMm > fit.reach.minAboveMm)
      fit.reach = reach, fitted = current, kept = plan, stale = 0;
  }
  fit.holds = fit.reach.minAboveMm >= params.stockMm;
  if (!fit.holds) fit.limit = describeLimit(kept, fitted, input, params, fit.reach);
  return fit;
}

}  // namespace

StockFit fitCrustToStock(DisplacementField& ddf, const TriangleMesh& input,
                         const StockCrustParams& params) {
  checkParams(params);
  StockFit fit;
  fit.requestedMm = params.stockMm;
  const double reachMm = params.stockMm * (1.0 + params.marginFraction);
  fit.reach = crustReach(ddf);
  if (fit.reach.minAboveMm >= reachMm || ddf.faceCount() == 0) {
    fit.holds = fit.reach.minAboveMm >= params.stockMm;
    return fit;
  }
  const detail::TriangleBvh bvh(input);
  DisplacementField fitted = ddf;
  fit = fitOnce(ddf, input, bvh, params, fitted);
  // The chosen directions are not better everywhere yet (a rotated stubble of a coarse face
  // may miss the input, or fold the moved crust, and the fold repair judges the crust by the
  // tops it expects, not by those the fit sets); where they do not hold the allowance the
  // chosen directions without the repair and then the converted ones are tried too, and the
  // larger smallest reach is kept.
  const auto tryAlso = [&](const StockCrustParams& other) {
    DisplacementField field = ddf;
    const StockFit next = fitOnce(ddf, input, bvh, other, field);
    if (next.reach.minAboveMm > fit.reach.minAboveMm) fit = next, fitted = std::move(field);
  };
  StockCrustParams fallback = params;
  if (!fit.holds && params.chooseDirections && params.repairFolds) {
    fallback.repairFolds = false;
    tryAlso(fallback);
  }
  if (!fit.holds && params.chooseDirections) {
    fallback.chooseDirections = false;
    tryAlso(fallback);
  }
  ddf = std::move(fitted);
  return fit;
}

}  // namespace ddfcam::ddf
