// SPDX-License-Identifier: MIT
// ddfcam: sampling step from a tolerance and tool placement along surface paths.
#include <ddfcam/planning/placement/path_sampling.h>

#include <ddfcam/error.h>
#include <ddfcam/planning/tools/tool_profiles.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Bounds the work a mistyped tolerance or override can ask for.
constexpr double kMaxPassPoses = 1e7;

/// A pass as a polyline parametrised by arc length, with its surface locations.
class PassPolyline {
 public:
  PassPolyline(const ddf::DisplacementField& ddf, const std::vector<ddf::SurfaceLocation>& locs)
      : ddf_(ddf), locs_(locs), cum_(locs.size(), 0.0) {
    for (std::size_t i = 1; i < locs.size(); ++i)
      cum_[i] = cum_[i - 1] + (locs[i].point - locs[i - 1].point).norm();
  }
  double length() const { return cum_.back(); }
  std::size_t size() const { return cum_.size(); }

  Vec3 point(double s) const {
    const auto [j, u] = segmentAt(s);
    return (1 - u) * locs_[j].point + u * locs_[j + 1].point;
  }

  /// The surface location at arc length @p s: barycentric interpolation inside a face,
  /// V-projection onto either face across a seam.
  ddf::SurfaceLocation location(double s) const {
    const auto [j, u] = segmentAt(s);
    const ddf::SurfaceLocation& a = locs_[j];
    const ddf::SurfaceLocation& b = locs_[j + 1];
    if (u <= 0.0) return a;
    if (u >= 1.0) return b;
    if (a.face == b.face) {
      ddf::SurfaceLocation out{a.face, (1 - u) * a.bary + u * b.bary, 0.0, Vec3::Zero()};
      out.h = ddf::interpolateOnFace(ddf_, ddf_.allHeights(), out.face, out.bary);
      out.point = ddf_.pointAt(out.face, out.bary, out.h);
      return out;
    }
    const Vec3 q = (1 - u) * a.point + u * b.point;
    // A segment may cross a third face between a's and b's (a quad diagonal): try every
    // face around their vertices; the right one puts q's foot inside, the others clamp it.
    std::vector<int> faces;
    for (const int f : {a.face, b.face})
      for (const int v : ddf_.faceVertices(f))
        for (const int g : ddf_.topology().vertexFaces(v))
          if (std::find(faces.begin(), faces.end(), g) == faces.end()) faces.push_back(g);
    std::optional<ddf::SurfaceLocation> best;
    for (const int face : faces) {
      const auto loc = ddf::locateOnFace(ddf_, face, q);
      if (loc && (!best || (loc->point - q).norm() < (best->point - q).norm())) best = loc;
    }
    return best ? *best : (u < 0.5 ? a : b);
  }

 private:
  std::pair<std::size_t, double> segmentAt(double s) const {
    s = std::clamp(s, 0.0, length());
    const auto it = std::upper_bound(cum_.begin(), cum_.end(), s);
    std::size_t j = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - cum_.begin() - 1, 0));
    j = std::min(j, cum_.size() - 2);
    const double len = cum_[j + 1] - cum_[j];
    return {j, len > 0.0 ? std::clamp((s - cum_[j]) / len, 0.0, 1.0) : 0.0};
  }

  const ddf::DisplacementField& ddf_;
  const std::vector<ddf::SurfaceLocation>& locs_;
  std::vector<double> cum_;
};

/// Curvature vector (towards the centre, length 1/radius) of the circle through a, b, c.
Vec3 curvatureVector(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = a - b, v = c - b, w = u.cross(v);
  const double w2 = w.squaredNorm();
  if (!(w2 > 1e-24 * u.squaredNorm() * v.squaredNorm())) return Vec3::Zero();
  const Vec3 offset = (u.squaredNorm() * v - v.squaredNorm() * u).cross(w) / (2.0 * w2);
  return offset / offset.squaredNorm();
}

/// Mean support edge length of @p face over m - 1: the raster spacing there, mm.
double rasterSpacing(const ddf::DisplacementField& ddf, int face) {
  const auto& v = ddf.faceVertices(face);
  const Vec3 &p1 = ddf.position(v[0]), &p2 = ddf.position(v[1]), &p3 = ddf.position(v[2]);
  const double mean = ((p2 - p1).norm() + (p3 - p2).norm() + (p1 - p3).norm()) / 3.0;
  return mean / (ddf.resolution() - 1);
}

/// Largest path and feed normal curvature over circles through points @p delta apart.
void measureCurvature(const ddf::DisplacementField& ddf, const PassPolyline& poly, double delta,
                      StepInputs& in) {
  const double length = poly.length();
  double kn = -kInf;
  const auto at = [&](double s) {
    const Vec3 k = curvatureVector(poly.point(s - delta), poly.point(s), poly.point(s + delta));
    in.feedCurvaturePerMm = std::max(in.feedCurvaturePerMm, k.norm());
    kn = std::max(kn, -k.dot(smoothSurfaceNormal(ddf, poly.location(s))));
  };
  if (length < 2.0 * delta) {
    delta = 0.5 * length;
    at(delta);
  } else {
    for (double s = delta; s <= length - delta + 1e-9 * length; s += 0.5 * delta) at(s);
  }
  in.feedNormalCurvaturePerMm = std::isfinite(kn) ? kn : 0.0;
}

void checkSampling(const PathSamplingParams& p) {
  if (!std::isfinite(p.toleranceMm) || !(p.toleranceMm > 0.0))
    throw InvalidInput("path sampling: tolerance " + std::to_string(p.toleranceMm) +
                       " mm is not positive");
  if (p.stepOverrideMm && (!std::isfinite(*p.stepOverrideMm) || !(*p.stepOverrideMm > 0.0)))
    throw InvalidInput("path sampling: step override " + std::to_string(*p.stepOverrideMm) +
                       " mm is not positive");
  if (!std::isfinite(p.rasterSpacingFactor) || p.rasterSpacingFactor < 0.0)
    throw InvalidInput("path sampling: raster spacing factor " +
                       std::to_string(p.rasterSpacingFactor) + " is negative or not finite");
}

/// Where the ray c + t d (t > 0) leaves the convex profile region (bounded by the profile and
/// the axis segment closing it): the smallest t at which it meets a piece; exact for arcs.
double exitParameter(const ToolProfile& profile, const Eigen::Vector2d& c,
                     const Eigen::Vector2d& d) {
  double best = kInf;
  const auto take = [&](double t) {
    if (t > 1e-14) best = std::min(best, t);
  };
  const auto segment = [&](const ProfilePoint& from, const ProfilePoint& to) {
    const Eigen::Vector2d p(from.axial, from.radial), e = Eigen::Vector2d(to.axial, to.radial) - p;
    const double det = d.x() * (-e.y()) - d.y() * (-e.x());
    if (std::abs(det) < 1e-300) return;
    const Eigen::Vector2d r = p - c;
    const double t = (r.x() * (-e.y()) - r.y() * (-e.x())) / det;
    const double u = (d.x() * r.y() - d.y() * r.x()) / det;
    if (u >= -1e-12 && u <= 1 + 1e-12) take(t);
  };
  for (const ProfileSegment& s : profile.segments) {
    if (!s.isArc) {
      segment(s.from, s.to);
      continue;
    }
    const Eigen::Vector2d f = c - Eigen::Vector2d(s.centre.axial, s.centre.radial);
    const double qa = d.squaredNorm(), qb = 2 * f.dot(d),
                 qc = f.squaredNorm() - s.arcRadius * s.arcRadius;
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) continue;
    for (const double sign : {-1.0, 1.0}) {
      const double t = (-qb + sign * std::sqrt(disc)) / (2 * qa);
      const Eigen::Vector2d q = f + t * d;
      const double u =
          std::remainder(std::atan2(q.y(), q.x()) - s.startAngle, 2 * std::numbers::pi) /
          s.sweepAngle;
      if (u >= -1e-9 && u <= 1 + 1e-9) take(t);
    }
  }
  segment(profile.segments.back().to, profile.segments.front().from);  // along the axis
  return best;
}

/// Bisection for the boundary between @p in (inside) and @p out (outside).
template <class Inside>
double boundary(double in, double out, const Inside& inside) {
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (in + out);
    (inside(mid) ? in : out) = mid;
  }
  return 0.5 * (in + out);
}

PathPose poseAt(const ddf::DisplacementField& ddf, const PassPolyline& poly, double s, double eps,
                const Tool& tool, const PlacementParams& placement) {
  const ddf::SurfaceLocation loc = poly.location(s);
  const Vec3 feed = poly.point(s + eps) - poly.point(s - eps);
  PathPose pose;
  pose.contact = loc.point;
  pose.pose =
      placeToolDetailed(tool, loc.point, smoothSurfaceNormal(ddf, loc), feed, placement).pose;
  return pose;
}

}  // namespace

const char* stepRuleName(StepRule rule) {
  switch (rule) {
    case StepRule::Override:
      return "override";
    case StepRule::FeedChord:
      return "feed chord";
    case StepRule::RasterSpacing:
      return "raster spacing";
    case StepRule::ToolProfile:
      return "tool profile";
    case StepRule::OrientationSweep:
      return "orientation sweep";
    case StepRule::Unconstrained:
      return "unconstrained";
  }
  return "unknown";
}

double toolFeedStepMm(const Tool& tool, const PlacementParams& placement,
                      double feedNormalCurvaturePerMm, double toleranceMm) {
  if (!std::isfinite(toleranceMm) || !(toleranceMm > 0.0))
    throw InvalidInput("tool feed step: tolerance " + std::to_string(toleranceMm) +
                       " mm is not positive");
  if (!std::isfinite(feedNormalCurvaturePerMm))
    throw InvalidInput("tool feed step: the feed normal curvature is not finite");
  PlacementParams flat = placement;
  flat.depthMm = 0.0;
  // In the canonical contact frame: contact at the origin, n = +z, feed = +x.
  const Eigen::Isometry3d toPart =
      placeToolDetailed(tool, Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), flat).pose;
  const Eigen::Isometry3d toTool = toPart.inverse();
  const ToolProfile profile = toolProfile(tool);
  const auto [lo, hi] = profile.axialRange();
  const double size = profile.maxRadius() + (hi - lo);
  // An interior point of the convex profile region: the mean of the piece ends.
  Eigen::Vector2d interior = Eigen::Vector2d::Zero();
  for (const ProfileSegment& seg : profile.segments)
    interior += Eigen::Vector2d(seg.from.axial, seg.from.radial);
  interior /= static_cast<double>(profile.segments.size());
  const Vec3 axis = profile.axis == RevolveAxis::X ? Vec3::UnitX() : Vec3::UnitZ();
  const auto inside = [&](double x) {
    const Vec3 q = toTool * Vec3(x, 0.0, toleranceMm - 0.5 * feedNormalCurvaturePerMm * x * x);
    const double a = q.dot(axis);
    const Eigen::Vector2d d = Eigen::Vector2d(a, (q - a * axis).norm()) - interior;
    return d.norm() <= 1e-15 * size || exitParameter(profile, interior, d) >= 1.0;
  };
  // A tool lower than T above the contact can never leave a cusp above T.
  if (!inside(0.0)) return kInf;
  const double far = 2.0 * size + toleranceMm;
  return boundary(0.0, far, inside) - boundary(0.0, -far, inside);
}

SamplingStep chooseStep(const Tool& tool, const PlacementParams& placement,
                        const StepInputs& inputs, const PathSamplingParams& params) {
  checkSampling(params);
  const auto check = [](double v, const char* name) {
    if (!std::isfinite(v) || v < 0.0)
      throw InvalidInput(std::string("path sampling: ") + name + " " + std::to_string(v) +
                         " is negative or not finite");
  };
  check(inputs.feedCurvaturePerMm, "feed curvature");
  check(inputs.rasterSpacingMm, "raster spacing");
  if (!std::isfinite(inputs.feedNormalCurvaturePerMm))
    throw InvalidInput("path sampling: feed normal curvature is not finite");
  const double tol = params.toleranceMm;
  SamplingStep out;
  out.feedChordStepMm =
      inputs.feedCurvaturePerMm > 0.0 ? std::sqrt(8.0 * tol / inputs.feedCurvaturePerMm) : kInf;
  out.rasterStepMm = params.rasterSpacingFactor > 0.0 && inputs.rasterSpacingMm > 0.0
                         ? params.rasterSpacingFactor * inputs.rasterSpacingMm
                         : kInf;
  out.toolProfileStepMm = toolFeedStepMm(tool, placement, inputs.feedNormalCurvaturePerMm, tol);
  out.stepMm = kInf;
  out.rule = StepRule::Unconstrained;
  for (const auto& [step, rule] : {std::pair{out.feedChordStepMm, StepRule::FeedChord},
                                   std::pair{out.rasterStepMm, StepRule::RasterSpacing},
                                   std::pair{out.toolProfileStepMm, StepRule::ToolProfile}})
    if (step < out.stepMm) out.stepMm = step, out.rule = rule;
  if (params.stepOverrideMm) out.stepMm = *params.stepOverrideMm, out.rule = StepRule::Override;
  return out;
}

namespace {

/// Places the tool along one pass (uniform step, then eq. 5.8 insertion) into @p path.
PassSampling placePass(const ddf::DisplacementField& ddf, const PassPolyline& poly, double spacing,
                       const Tool& tool, const PlacementParams& placement,
                       const PathSamplingParams& sampling, ToolPath& path) {
  PassSampling ps;
  ps.lengthMm = poly.length();
  ps.inputs.rasterSpacingMm = spacing;
  // Circles through points a raster spacing (at least two input segments) apart see the
  // surface's shape, not the jitter of a traced line.
  const double meanSegment = ps.lengthMm / static_cast<double>(poly.size() - 1);
  const double delta = std::min(std::max(spacing, 2.0 * meanSegment), 0.5 * ps.lengthMm);
  measureCurvature(ddf, poly, delta, ps.inputs);
  ps.step = chooseStep(tool, placement, ps.inputs, sampling);
  const double ratio = ps.lengthMm / ps.step.stepMm;
  if (ratio > kMaxPassPoses)
    throw InvalidInput("placeAlongPath: a step of " + std::to_string(ps.step.stepMm) + " mm (" +
                       stepRuleName(ps.step.rule) + ") would need more than " +
                       std::to_string(static_cast<long>(kMaxPassPoses)) + " poses on one pass");
  const int k = std::isfinite(ratio) ? std::max(1, static_cast<int>(std::ceil(ratio - 1e-9))) : 1;
  ps.uniformPoses = k + 1;
  ps.bindingRule = ps.step.rule;
  const double h = ps.lengthMm / k;
  const double eps = 0.5 * std::min(h, delta);
  std::vector<PathPose> uniform;
  for (int i = 0; i <= k; ++i) uniform.push_back(poseAt(ddf, poly, i * h, eps, tool, placement));
  ps.firstPose = static_cast<int>(path.poses.size());
  path.passStarts.push_back(ps.firstPose);
  const double w = sampling.rasterSpacingFactor * spacing;
  const bool sweep = !sampling.stepOverrideMm && w > 0.0;
  const auto [bottom, top] = toolAxisEnds(tool);
  for (int i = 0; i <= k; ++i) {
    path.poses.push_back(uniform[i]);
    if (i == k || !sweep) continue;
    const Eigen::Isometry3d &p0 = uniform[i].pose, &p1 = uniform[i + 1].pose;
    const double move = std::max((p1 * bottom - p0 * bottom).norm(), (p1 * top - p0 * top).norm());
    const int n = static_cast<int>(std::ceil(std::min(move / w, kMaxPassPoses) - 1e-9));
    for (int j = 1; j < n; ++j)
      path.poses.push_back(
          poseAt(ddf, poly, (i + static_cast<double>(j) / n) * h, eps, tool, placement));
    ps.sweepInsertedPoses += std::max(0, n - 1);
  }
  if (ps.sweepInsertedPoses > 0) ps.bindingRule = StepRule::OrientationSweep;
  return ps;
}

}  // namespace

PlacedPath placeAlongPathDetailed(const ddf::DisplacementField& ddf,
                                  const std::vector<std::vector<ddf::SurfaceLocation>>& passes,
                                  const Tool& tool, int toolIndex, const PlacementParams& placement,
                                  const PathSamplingParams& sampling) {
  validateTool(tool);
  checkSampling(sampling);
  PlacedPath out;
  out.path.name = sampling.name;
  out.path.tool = toolIndex;
  out.path.feedMmPerMin = sampling.feedMmPerMin;
  for (std::size_t p = 0; p < passes.size(); ++p) {
    const auto& pass = passes[p];
    if (pass.size() < 2) continue;
    double spacing = kInf;
    for (const ddf::SurfaceLocation& loc : pass) {
      if (loc.face < 0 || loc.face >= ddf.faceCount())
        throw InvalidInput("placeAlongPath: pass " + std::to_string(p) + " has a point on face " +
                           std::to_string(loc.face) + ", out of range");
      spacing = std::min(spacing, rasterSpacing(ddf, loc.face));
    }
    const PassPolyline poly(ddf, pass);
    if (!(poly.length() > 1e-12)) continue;
    out.passes.push_back(placePass(ddf, poly, spacing, tool, placement, sampling, out.path));
  }
  if (out.path.poses.empty()) throw InvalidInput("placeAlongPath: no pass has two distinct points");
  return out;
}

ToolPath placeAlongPath(const ddf::DisplacementField& ddf,
                        const std::vector<std::vector<ddf::SurfaceLocation>>& passes,
                        const Tool& tool, int toolIndex, const PlacementParams& placement,
                        const PathSamplingParams& sampling) {
  return placeAlongPathDetailed(ddf, passes, tool, toolIndex, placement, sampling).path;
}

ToolPath placeAlongPath(const ddf::DisplacementField& ddf,
                        const std::vector<Streamline>& streamlines, const Tool& tool, int toolIndex,
                        const PlacementParams& placement, const PathSamplingParams& sampling) {
  std::vector<std::vector<ddf::SurfaceLocation>> passes;
  passes.reserve(streamlines.size());
  for (const Streamline& line : streamlines) passes.push_back(line.points);
  return placeAlongPath(ddf, passes, tool, toolIndex, placement, sampling);
}

}  // namespace ddfcam::planning
