// SPDX-License-Identifier: MIT
// ddfcam: pieces shared by the three streamline tracers (field sampling, stop rules, joining).
#include "streamline_common.h"

#include <ddfcam/ddf/v_projection.h>
#include <ddfcam/error.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace ddfcam::planning::detail {
namespace {

double snap(double x) {
  const double r = std::round(x);
  return std::abs(x - r) < 1e-9 ? r : x;
}

SurfaceJacobian jacobianFrom(const ddf::DisplacementField& ddf, int face, const Vec3& mu, double h,
                             double ha, double hc) {
  const auto& fv = ddf.faceVertices(face);
  const Vec3 v = ddf.vectorAt(face, mu);
  return {ddf.position(fv[0]) - ddf.position(fv[1]) + h * (ddf.vector(fv[0]) - ddf.vector(fv[1])) +
              ha * v,
          ddf.position(fv[2]) - ddf.position(fv[1]) + h * (ddf.vector(fv[2]) - ddf.vector(fv[1])) +
              hc * v};
}

// Feet this far outside a face still count as on it (rounding of a point on a seam).
constexpr double kInsideTolerance = 1e-12;
// Faces visited by relocate() before it settles for a clamped foot.
constexpr int kMaxRelocateHops = 8;

}  // namespace

Vec3 SurfaceJacobian::toBary(const Vec3& d) const {
  Eigen::Matrix2d gram;
  gram << ja.dot(ja), ja.dot(jc), jc.dot(ja), jc.dot(jc);
  const Eigen::Vector2d x = gram.ldlt().solve(Eigen::Vector2d(ja.dot(d), jc.dot(d)));
  return {x[0], -x[0] - x[1], x[1]};
}

SurfaceJacobian surfaceJacobian(const ddf::DisplacementField& ddf, int face, const Vec3& mu,
                                const RasterCell& cell) {
  double h = 0.0, ha = 0.0, hc = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double hi = ddf.allHeights()[cell.index[i]];
    h += cell.weight[i] * hi, ha += cell.dWeightA[i] * hi, hc += cell.dWeightC[i] * hi;
  }
  return jacobianFrom(ddf, face, mu, h, ha, hc);
}

double cellHeight(const ddf::DisplacementField& ddf, const RasterCell& cell) {
  double h = 0.0;
  for (int i = 0; i < 3; ++i) h += cell.weight[i] * ddf.allHeights()[cell.index[i]];
  return h;
}

RasterCell rasterCell(const ddf::DisplacementField& ddf, int face, const Vec3& mu) {
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  const double a = snap(mu[0] * n), c = snap(mu[2] * n);
  int a0 = std::min(static_cast<int>(std::floor(a)), n - 1);
  int c0 = std::min(static_cast<int>(std::floor(c)), n - 1);
  if (a0 + c0 > n - 1) --c0;
  a0 = std::max(a0, 0), c0 = std::max(c0, 0);
  const double fa = a - a0, fc = c - c0;
  const std::size_t base = static_cast<std::size_t>(face) * ddf.pointsPerFace();
  RasterCell cell;
  if (fa + fc <= 1.0 || a0 + c0 == n - 1) {
    cell.index = {base + raster.index(a0, c0), base + raster.index(a0 + 1, c0),
                  base + raster.index(a0, c0 + 1)};
    cell.weight = {1.0 - fa - fc, fa, fc};
    cell.dWeightA = Vec3(-1.0, 1.0, 0.0) * n;
    cell.dWeightC = Vec3(-1.0, 0.0, 1.0) * n;
  } else {
    cell.index = {base + raster.index(a0 + 1, c0 + 1), base + raster.index(a0, c0 + 1),
                  base + raster.index(a0 + 1, c0)};
    cell.weight = {fa + fc - 1.0, 1.0 - fa, 1.0 - fc};
    cell.dWeightA = Vec3(1.0, -1.0, 0.0) * n;
    cell.dWeightC = Vec3(1.0, 0.0, -1.0) * n;
  }
  return cell;
}

Vec3 clampBary(const Vec3& bary) {
  const Vec3 c = bary.cwiseMax(0.0);
  const double sum = c.sum();
  return sum > 0.0 ? Vec3(c / sum) : Vec3(Vec3::Constant(1.0 / 3.0));
}

Vec3 canonicalSign(const Vec3& d) {
  int best = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(d[i]) > std::abs(d[best])) best = i;
  return d[best] < 0.0 ? Vec3(-d) : d;
}

double meanRasterSpacing(const ddf::DisplacementField& ddf) {
  const ddf::SupportMesh& mesh = ddf.support();
  double sum = 0.0;
  for (const auto& e : mesh.edges()) sum += mesh.calc_edge_length(e);
  return mesh.n_edges() ? sum / mesh.n_edges() / ddf.raster().steps() : 0.0;
}

void checkTraceInput(const ddf::DisplacementField& ddf, const LineField& field,
                     const SurfaceLocation& seed, const StreamlineParams& params, const char* who) {
  const std::string name(who);
  if (field.size() != ddf.allHeights().size()) {
    throw InvalidInput(name + ": line field has " + std::to_string(field.size()) +
                       " entries, expected " + std::to_string(ddf.allHeights().size()));
  }
  if (seed.face < 0 || seed.face >= ddf.faceCount()) {
    throw InvalidInput(name + ": seed face " + std::to_string(seed.face) + " out of range [0, " +
                       std::to_string(ddf.faceCount()) + ")");
  }
  if (!seed.bary.allFinite())
    throw InvalidInput(name + ": seed barycentric coordinates are not finite");
  if (params.stepMm < 0.0 || params.maxLengthMm < 0.0 || params.loopToleranceMm < 0.0 ||
      params.minLoopLengthMm < 0.0 || params.nearPathDistanceMm < 0.0 || params.maxSteps < 0) {
    throw InvalidInput(name + ": negative step, length, tolerance or step count");
  }
  if (!params.faceMask.empty() &&
      params.faceMask.size() != static_cast<std::size_t>(ddf.faceCount())) {
    throw InvalidInput(name + ": face mask has " + std::to_string(params.faceMask.size()) +
                       " entries, expected one per face (" + std::to_string(ddf.faceCount()) + ")");
  }
}

int faceAcross(const ddf::DisplacementField& ddf, int face, int corner) {
  // Local edge opposite local vertex c is (c + 1) % 3 (edge 0 = p1 p2, 1 = p2 p3, 2 = p3 p1).
  const ddf::RasterTopology& topo = ddf.topology();
  const auto& sides = topo.edgeFaces(topo.faceEdge(face, (corner + 1) % 3));
  return sides[0] == face ? sides[1] : sides[0];
}

Vec3 mapAcross(const ddf::DisplacementField& ddf, int from, int to, const Vec3& bary, int dropped) {
  const auto& a = ddf.faceVertices(from);
  const auto& b = ddf.faceVertices(to);
  Vec3 mapped = Vec3::Zero();
  for (int c = 0; c < 3; ++c) {
    if (c == dropped) continue;
    const auto it = std::find(b.begin(), b.end(), a[c]);
    if (it != b.end()) mapped[it - b.begin()] = bary[c];
  }
  return mapped;
}

PathProximity::PathProximity(const std::vector<std::vector<Vec3>>& paths, double distanceMm)
    : distance_(distanceMm), grid_(distanceMm > 0.0 ? distanceMm : 1.0) {
  if (!(distance_ > 0.0)) return;
  for (const auto& path : paths)
    for (std::size_t s = 0; s < path.size(); ++s)
      grid_.add(path[s], path[std::min(s + 1, path.size() - 1)], Vec3::Zero(), -1, 0.0);
}

bool PathProximity::near(const Vec3& q) const {
  return distance_ > 0.0 && grid_.near(q, Vec3::Zero(), distance_);
}

SurfaceLocation FieldSampler::locate(int face, const Vec3& bary) const {
  const RasterCell cell = rasterCell(ddf_, face, bary);
  double h = 0.0;
  for (int i = 0; i < 3; ++i)
    if (cell.weight[i] != 0.0) h += cell.weight[i] * ddf_.allHeights()[cell.index[i]];
  return {face, bary, h, ddf_.pointAt(face, bary, h)};
}

std::optional<FieldSample> FieldSampler::sample(int face, const Vec3& baryIn,
                                                const Vec3& ref) const {
  const Vec3 mu = clampBary(baryIn);
  const RasterCell cell = rasterCell(ddf_, face, mu);
  Vec3 sum = Vec3::Zero();
  double h = 0.0, ha = 0.0, hc = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double hi = ddf_.allHeights()[cell.index[i]];
    h += cell.weight[i] * hi, ha += cell.dWeightA[i] * hi, hc += cell.dWeightC[i] * hi;
    if (cell.weight[i] == 0.0) continue;
    const Vec3& f = field_[cell.index[i]];
    if (f.isZero()) return std::nullopt;
    sum += (f.dot(ref) < 0.0 ? -cell.weight[i] : cell.weight[i]) * f;
  }
  if (sum.norm() < minCoherence_) return std::nullopt;
  const SurfaceJacobian jac = jacobianFrom(ddf_, face, mu, h, ha, hc);
  const Vec3 normal = jac.ja.cross(jac.jc).normalized();
  Vec3 d = sum - sum.dot(normal) * normal;
  const double len = d.norm();
  if (!(len > 1e-3 * sum.norm())) return std::nullopt;
  d /= len;
  if (d.dot(ref) < 0.0) d = -d;
  return FieldSample{d, jac.toBary(d), normal};
}

std::optional<Vec3> FieldSampler::startDirection(const SurfaceLocation& start) const {
  const RasterCell cell = rasterCell(ddf_, start.face, start.bary);
  int heaviest = -1;
  for (int i = 0; i < 3; ++i)
    if (!field_[cell.index[i]].isZero() && (heaviest < 0 || cell.weight[i] > cell.weight[heaviest]))
      heaviest = i;
  if (heaviest < 0) return std::nullopt;
  const auto at = sample(start.face, start.bary, canonicalSign(field_[cell.index[heaviest]]));
  if (!at) return std::nullopt;
  return canonicalSign(at->dir);
}

StopRules::StopRules(const StreamlineParams& params, double stepMm)
    : mask_(params.faceMask),
      loopTolerance_(params.loopToleranceMm > 0.0 ? params.loopToleranceMm : stepMm),
      minLoopLength_(params.minLoopLengthMm > 0.0 ? params.minLoopLengthMm : 10.0 * loopTolerance_),
      proximity_(params.existingPaths, params.nearPathDistanceMm) {}

std::optional<StopReason> StopRules::at(HalfLine& half, const SurfaceLocation& seed) const {
  const SurfaceLocation& cur = half.points.back();
  if (half.lengthMm >= minLoopLength_ && (cur.point - seed.point).norm() < loopTolerance_) {
    half.lengthMm += (seed.point - cur.point).norm();
    half.points.push_back(seed);  // close the polyline exactly
    return StopReason::ClosedLoop;
  }
  if (proximity_.near(cur.point)) return StopReason::NearExistingPath;
  return std::nullopt;
}

std::optional<TraceStart> prepareTrace(const FieldSampler& sampler, const StopRules& rules,
                                       const SurfaceLocation& seed, Streamline& early) {
  TraceStart s;
  s.start = sampler.locate(seed.face, clampBary(seed.bary));
  early = Streamline{};
  early.points = {s.start};
  early.stop = early.backwardStop = StopReason::Singularity;
  if (!rules.allowed(s.start.face)) {
    early.stop = early.backwardStop = StopReason::RegionBoundary;
    return std::nullopt;
  }
  const auto dir = sampler.startDirection(s.start);
  if (!dir) return std::nullopt;
  s.dir0 = *dir;
  return s;
}

std::optional<SurfaceLocation> relocate(const FieldSampler& sampler, const StopRules& rules,
                                        int face, const Vec3& x) {
  const ddf::DisplacementField& ddf = sampler.ddf();
  Vec3 mu = Vec3::Zero();
  for (int hop = 0; hop < kMaxRelocateHops; ++hop) {
    // Of several roots the one whose height is closest to the surface's at its foot.
    double bestGap = std::numeric_limits<double>::infinity();
    bool found = false;
    for (const ddf::VProjection& root : ddf::vProject(ddf, face, x)) {
      if (!root.mu.allFinite() || !std::isfinite(root.h)) continue;
      const double gap = std::abs(root.h - sampler.locate(face, clampBary(root.mu)).h);
      if (gap < bestGap) bestGap = gap, mu = root.mu, found = true;
    }
    if (!found) return std::nullopt;
    int corner = 0;
    mu.minCoeff(&corner);
    if (mu[corner] >= -kInsideTolerance) break;
    const int next = faceAcross(ddf, face, corner);
    if (next < 0 || !rules.allowed(next)) break;
    face = next;
  }
  return sampler.locate(face, clampBary(mu));
}

std::optional<double> nextStepLength(const HalfLine& half, double stepMm, double lengthBudget,
                                     int stepBudget, const StreamlineParams& params) {
  const double s = std::min(stepMm, lengthBudget - half.lengthMm);
  if (half.steps >= stepBudget || !(s > kNoProgress * stepMm)) return std::nullopt;
  if (params.progress && half.steps % 256 == 0)
    reportProgress(params.progress, std::min(1.0, half.lengthMm / params.maxLengthMm));
  return s;
}

bool appendPoint(HalfLine& half, const SurfaceLocation& next, double moved,
                 const std::optional<StopReason>& edgeStop, const StopRules& rules,
                 const SurfaceLocation& seed) {
  half.lengthMm += moved;
  half.points.push_back(next);
  if (edgeStop) {
    half.stop = *edgeStop;
    return true;
  }
  if (const auto stop = rules.at(half, seed)) {
    half.stop = *stop;
    return true;
  }
  return false;
}

double polylineLength(const std::vector<SurfaceLocation>& points) {
  double sum = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i)
    sum += (points[i].point - points[i - 1].point).norm();
  return sum;
}

}  // namespace ddfcam::planning::detail
