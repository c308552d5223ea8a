// SPDX-License-Identifier: MIT
// ddfcam: RK4 streamlines of a line field in the support faces' parameter domains (sec. 8.3).
#include <ddfcam/error.h>
#include <ddfcam/planning/streamline.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

namespace ddfcam::planning {
namespace {

using ddf::SurfaceLocation;
using ddf::Vec3;
using StopReason = Streamline::StopReason;

// A step whose exit point lies this close to its start made no progress.
constexpr double kNoProgress = 1e-9;
// Consecutive crossings without progress before the line gives up: more than a vertex's fan.
constexpr int kMaxIdleCrossings = 24;

// The raster triangle around a barycentric point (the cell interpolateOnFace uses): storage
// indices of its corners, their linear weights and the weights' derivatives along the
// parameter directions a = e1 - e2 and c = e3 - e2 (per unit of barycentric coordinate).
struct RasterCell {
  std::array<std::size_t, 3> index{};
  Vec3 weight = Vec3::Zero();
  Vec3 dWeightA = Vec3::Zero();
  Vec3 dWeightC = Vec3::Zero();
};

Vec3 clampBary(const Vec3& bary) {
  const Vec3 c = bary.cwiseMax(0.0);
  const double sum = c.sum();
  return sum > 0.0 ? Vec3(c / sum) : Vec3(Vec3::Constant(1.0 / 3.0));
}

double snap(double x) {
  const double r = std::round(x);
  return std::abs(x - r) < 1e-9 ? r : x;
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

// Sign of a line direction that does not depend on the sign it came with: the component of
// largest magnitude is made positive.
Vec3 canonicalSign(const Vec3& d) {
  int best = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(d[i]) > std::abs(d[best])) best = i;
  return d[best] < 0.0 ? Vec3(-d) : d;
}

// Existing paths in a uniform grid of cell size = the stop distance, each segment entered in
// every cell its bounding box overlaps, so a query looks at the 27 cells around a point.
class PathProximity {
 public:
  PathProximity(const std::vector<std::vector<Vec3>>& paths, double distanceMm)
      : paths_(paths), distance_(distanceMm) {
    if (!(distance_ > 0.0)) return;
    for (int p = 0; p < static_cast<int>(paths.size()); ++p) {
      const auto& path = paths[p];
      for (int s = 0; s < static_cast<int>(path.size()); ++s) {
        const Vec3& a = path[s];
        const Vec3& b = path[std::min<std::size_t>(s + 1, path.size() - 1)];
        const Eigen::Vector3i lo = cellOf(a.cwiseMin(b)), hi = cellOf(a.cwiseMax(b));
        for (int x = lo.x(); x <= hi.x(); ++x)
          for (int y = lo.y(); y <= hi.y(); ++y)
            for (int z = lo.z(); z <= hi.z(); ++z) cells_[key({x, y, z})].push_back({p, s});
      }
    }
  }

  bool near(const Vec3& q) const {
    if (cells_.empty()) return false;
    const Eigen::Vector3i c = cellOf(q);
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          const auto it = cells_.find(key(c + Eigen::Vector3i(x, y, z)));
          if (it == cells_.end()) continue;
          for (const auto& [p, s] : it->second)
            if (segmentDistance(q, p, s) < distance_) return true;
        }
    return false;
  }

 private:
  Eigen::Vector3i cellOf(const Vec3& p) const {
    return (p / distance_).array().floor().cast<int>();
  }
  static std::int64_t key(const Eigen::Vector3i& c) {
    return (static_cast<std::int64_t>(c.x()) * 73856093) ^
           (static_cast<std::int64_t>(c.y()) * 19349663) ^
           (static_cast<std::int64_t>(c.z()) * 83492791);
  }
  double segmentDistance(const Vec3& q, int p, int s) const {
    const auto& path = paths_[p];
    const Vec3& a = path[s];
    const Vec3 ab = path[std::min<std::size_t>(s + 1, path.size() - 1)] - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - q).norm();
  }

  const std::vector<std::vector<Vec3>>& paths_;
  double distance_;
  std::unordered_map<std::int64_t, std::vector<std::pair<int, int>>> cells_;
};

// Field direction at a point: unit tangent of the surface and the same direction as a
// barycentric velocity per mm of arc length (components sum to 0).
struct FieldSample {
  Vec3 dir = Vec3::Zero();
  Vec3 dBary = Vec3::Zero();
};

class Tracer {
 public:
  Tracer(const ddf::DisplacementField& ddf, const LineField& field, const StreamlineParams& params,
         double stepMm)
      : ddf_(ddf),
        field_(field),
        params_(params),
        step_(stepMm),
        loopTolerance_(params.loopToleranceMm > 0.0 ? params.loopToleranceMm : stepMm),
        minLoopLength_(params.minLoopLengthMm > 0.0 ? params.minLoopLengthMm
                                                    : 10.0 * loopTolerance_),
        proximity_(params.existingPaths, params.nearPathDistanceMm) {}

  SurfaceLocation locate(int face, const Vec3& bary) const {
    const RasterCell cell = rasterCell(ddf_, face, bary);
    double h = 0.0;
    for (int i = 0; i < 3; ++i)
      if (cell.weight[i] != 0.0) h += cell.weight[i] * ddf_.allHeights()[cell.index[i]];
    return {face, bary, h, ddf_.pointAt(face, bary, h)};
  }

  // The interpolated field at (face, bary), each entry's sign aligned with @p ref; nullopt
  // where the field is undefined or incoherent.
  std::optional<FieldSample> sample(int face, const Vec3& baryIn, const Vec3& ref) const {
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
    if (sum.norm() < params_.minCoherence) return std::nullopt;
    const auto& fv = ddf_.faceVertices(face);
    const Vec3 v = ddf_.vectorAt(face, mu);
    const Vec3 ja = ddf_.position(fv[0]) - ddf_.position(fv[1]) +
                    h * (ddf_.vector(fv[0]) - ddf_.vector(fv[1])) + ha * v;
    const Vec3 jc = ddf_.position(fv[2]) - ddf_.position(fv[1]) +
                    h * (ddf_.vector(fv[2]) - ddf_.vector(fv[1])) + hc * v;
    const Vec3 normal = ja.cross(jc).normalized();
    Vec3 d = sum - sum.dot(normal) * normal;
    const double len = d.norm();
    if (!(len > 1e-3 * sum.norm())) return std::nullopt;
    d /= len;
    if (d.dot(ref) < 0.0) d = -d;
    Eigen::Matrix2d gram;
    gram << ja.dot(ja), ja.dot(jc), jc.dot(ja), jc.dot(jc);
    const Eigen::Vector2d x = gram.ldlt().solve(Eigen::Vector2d(ja.dot(d), jc.dot(d)));
    return FieldSample{d, Vec3(x[0], -x[0] - x[1], x[1])};
  }

  // One classical RK4 step of length s from (face, bary); nullopt at a singularity.
  std::optional<FieldSample> rk4(int face, const Vec3& bary, const Vec3& ref, double s) const {
    const auto k1 = sample(face, bary, ref);
    if (!k1) return std::nullopt;
    const auto k2 = sample(face, bary + 0.5 * s * k1->dBary, k1->dir);
    if (!k2) return std::nullopt;
    const auto k3 = sample(face, bary + 0.5 * s * k2->dBary, k2->dir);
    if (!k3) return std::nullopt;
    const auto k4 = sample(face, bary + s * k3->dBary, k3->dir);
    if (!k4) return std::nullopt;
    const Vec3 dir = k1->dir + 2.0 * k2->dir + 2.0 * k3->dir + k4->dir;
    return FieldSample{dir.normalized(),
                       s / 6.0 * (k1->dBary + 2.0 * k2->dBary + 2.0 * k3->dBary + k4->dBary)};
  }

  struct Half {
    std::vector<SurfaceLocation> points;  // after the seed
    StopReason stop = StopReason::MaxLength;
    double lengthMm = 0.0;
    int steps = 0;
  };

  Half traceHalf(const SurfaceLocation& seed, const Vec3& dir0, double lengthBudget,
                 int stepBudget) const;

 private:
  // Where a step from @p bary by @p delta leaves face @p face: the edge point, moved onto the
  // neighbouring face; nullopt when it stays inside. Sets @p boundary when there is no
  // neighbour (the point then stays in @p face).
  std::optional<SurfaceLocation> crossEdge(int face, const Vec3& bary, const Vec3& delta,
                                           bool& boundary) const;
  // The stop rule met at the newest point of @p half (closing a loop appends the seed).
  std::optional<StopReason> stopAt(Half& half, const SurfaceLocation& seed, bool boundary) const;

  const ddf::DisplacementField& ddf_;
  const LineField& field_;
  const StreamlineParams& params_;
  double step_;
  double loopTolerance_;
  double minLoopLength_;
  PathProximity proximity_;
};

std::optional<SurfaceLocation> Tracer::crossEdge(int face, const Vec3& bary, const Vec3& delta,
                                                 bool& boundary) const {
  const Vec3 end = bary + delta;
  int exit = -1;
  double t = 1.0;
  for (int c = 0; c < 3; ++c) {
    if (end[c] >= -1e-14) continue;  // rounding of a step along an edge stays inside
    const double tc = bary[c] <= 0.0 ? 0.0 : bary[c] / (bary[c] - end[c]);
    if (exit < 0 || tc < t) exit = c, t = tc;
  }
  if (exit < 0) return std::nullopt;
  Vec3 cross = bary + t * delta;
  cross[exit] = 0.0;
  cross = clampBary(cross);
  // Local edge opposite local vertex c is (c + 1) % 3 (edge 0 = p1 p2, 1 = p2 p3, 2 = p3 p1).
  const ddf::RasterTopology& topo = ddf_.topology();
  const auto& sides = topo.edgeFaces(topo.faceEdge(face, (exit + 1) % 3));
  const int next = sides[0] == face ? sides[1] : sides[0];
  boundary = next < 0;
  if (boundary) return locate(face, cross);
  const auto& from = ddf_.faceVertices(face);
  const auto& to = ddf_.faceVertices(next);
  Vec3 mapped = Vec3::Zero();
  for (int c = 0; c < 3; ++c) {
    if (c == exit) continue;
    const auto it = std::find(to.begin(), to.end(), from[c]);
    mapped[it - to.begin()] = cross[c];
  }
  return locate(next, mapped);
}

Tracer::Half Tracer::traceHalf(const SurfaceLocation& seed, const Vec3& dir0, double lengthBudget,
                               int stepBudget) const {
  Half half;
  SurfaceLocation cur = seed;
  Vec3 ref = dir0;
  int idle = 0;
  for (;;) {
    const double s = std::min(step_, lengthBudget - half.lengthMm);
    if (half.steps >= stepBudget || !(s > kNoProgress * step_)) return half;  // MaxLength
    if (params_.progress && half.steps % 256 == 0)
      reportProgress(params_.progress, std::min(1.0, half.lengthMm / params_.maxLengthMm));
    const auto step = rk4(cur.face, cur.bary, ref, s);
    if (!step) {
      half.stop = StopReason::Singularity;
      return half;
    }
    ++half.steps;
    ref = step->dir;
    bool boundary = false;
    auto crossed = crossEdge(cur.face, cur.bary, step->dBary, boundary);
    SurfaceLocation next = crossed ? *crossed : locate(cur.face, clampBary(cur.bary + step->dBary));
    const double moved = (next.point - cur.point).norm();
    if (crossed && !boundary && moved <= kNoProgress * step_) {
      if (++idle > kMaxIdleCrossings) {
        half.stop = StopReason::Singularity;
        return half;
      }
      cur = next;  // same point, now in the neighbouring face
      continue;
    }
    idle = 0;
    half.lengthMm += moved;
    half.points.push_back(next);
    cur = next;
    if (const auto stop = stopAt(half, seed, boundary)) {
      half.stop = *stop;
      return half;
    }
  }
}

std::optional<StopReason> Tracer::stopAt(Half& half, const SurfaceLocation& seed,
                                         bool boundary) const {
  if (boundary) return StopReason::Boundary;
  const SurfaceLocation& cur = half.points.back();
  if (half.lengthMm >= minLoopLength_ && (cur.point - seed.point).norm() < loopTolerance_) {
    half.lengthMm += (seed.point - cur.point).norm();
    half.points.push_back(seed);  // close the polyline exactly
    return StopReason::ClosedLoop;
  }
  if (proximity_.near(cur.point)) return StopReason::NearExistingPath;
  return std::nullopt;
}

double meanRasterSpacing(const ddf::DisplacementField& ddf) {
  const ddf::SupportMesh& mesh = ddf.support();
  double sum = 0.0;
  for (const auto& e : mesh.edges()) sum += mesh.calc_edge_length(e);
  return mesh.n_edges() ? sum / mesh.n_edges() / ddf.raster().steps() : 0.0;
}

void checkTraceInput(const ddf::DisplacementField& ddf, const LineField& field,
                     const ddf::SurfaceLocation& seed, const StreamlineParams& params) {
  if (field.size() != ddf.allHeights().size()) {
    throw InvalidInput("traceStreamline: line field has " + std::to_string(field.size()) +
                       " entries, expected " + std::to_string(ddf.allHeights().size()));
  }
  if (seed.face < 0 || seed.face >= ddf.faceCount()) {
    throw InvalidInput("traceStreamline: seed face " + std::to_string(seed.face) +
                       " out of range [0, " + std::to_string(ddf.faceCount()) + ")");
  }
  if (!seed.bary.allFinite())
    throw InvalidInput("traceStreamline: seed barycentric coordinates are not finite");
  if (params.stepMm < 0.0 || params.maxLengthMm < 0.0 || params.loopToleranceMm < 0.0 ||
      params.minLoopLengthMm < 0.0 || params.nearPathDistanceMm < 0.0 || params.maxSteps < 0) {
    throw InvalidInput("traceStreamline: negative step, length, tolerance or step count");
  }
}

}  // namespace

Streamline traceStreamline(const ddf::DisplacementField& ddf, const LineField& field,
                           const ddf::SurfaceLocation& seed, const StreamlineParams& params) {
  checkTraceInput(ddf, field, seed, params);
  const double stepMm = params.stepMm > 0.0 ? params.stepMm : meanRasterSpacing(ddf);
  const Tracer tracer(ddf, field, params, stepMm);
  const SurfaceLocation start = tracer.locate(seed.face, clampBary(seed.bary));
  Streamline line;
  line.points = {start};
  line.stop = line.backwardStop = StopReason::Singularity;

  // The sign reference: the seed cell's heaviest defined entry, made sign-independent.
  const RasterCell cell = rasterCell(ddf, start.face, start.bary);
  int heaviest = -1;
  for (int i = 0; i < 3; ++i)
    if (!field[cell.index[i]].isZero() && (heaviest < 0 || cell.weight[i] > cell.weight[heaviest]))
      heaviest = i;
  if (heaviest < 0) return line;
  const auto at = tracer.sample(start.face, start.bary, canonicalSign(field[cell.index[heaviest]]));
  if (!at) return line;
  const Vec3 dir0 = canonicalSign(at->dir);

  const auto forward = tracer.traceHalf(start, dir0, params.maxLengthMm, params.maxSteps);
  line.stop = forward.stop;
  Tracer::Half backward;
  backward.stop = StopReason::ClosedLoop;
  if (forward.stop != StopReason::ClosedLoop) {
    backward = tracer.traceHalf(start, -dir0, params.maxLengthMm - forward.lengthMm,
                                params.maxSteps - forward.steps);
  }
  line.backwardStop = backward.stop;
  line.points.assign(backward.points.rbegin(), backward.points.rend());
  line.seedIndex = line.points.size();
  line.points.push_back(start);
  line.points.insert(line.points.end(), forward.points.begin(), forward.points.end());
  line.lengthMm = forward.lengthMm + backward.lengthMm;
  return line;
}

}  // namespace ddfcam::planning
