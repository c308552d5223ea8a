// SPDX-License-Identifier: MIT
// ddfcam: pieces shared by the three streamline tracers (field sampling, stop rules, joining).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/lines/streamline.h>

#include "separation_grid.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace ddfcam::planning::detail {

using ddf::SurfaceLocation;
using ddf::Vec3;
using StopReason = Streamline::StopReason;

/// A step whose end lies this close to its start (relative to the step) made no progress.
inline constexpr double kNoProgress = 1e-9;

/// The raster triangle around a barycentric point (the cell interpolateOnFace uses): storage
/// indices of its corners, their linear weights and the weights' derivatives along the
/// parameter directions a = e1 - e2 and c = e3 - e2 (per unit of barycentric coordinate).
struct RasterCell {
  std::array<std::size_t, 3> index{};
  Vec3 weight = Vec3::Zero();
  Vec3 dWeightA = Vec3::Zero();
  Vec3 dWeightC = Vec3::Zero();
};

RasterCell rasterCell(const ddf::DisplacementField& ddf, int face, const Vec3& mu);

/// Negative coordinates set to 0, the rest rescaled to sum 1 (the centroid if all vanish).
Vec3 clampBary(const Vec3& bary);

/// Sign of a line direction that does not depend on the sign it came with: the component of
/// largest magnitude is made positive.
Vec3 canonicalSign(const Vec3& d);

/// Mean support edge length / (m - 1), mm.
double meanRasterSpacing(const ddf::DisplacementField& ddf);

/// The checks documented for traceStreamline(); @p who names the caller in messages.
void checkTraceInput(const ddf::DisplacementField& ddf, const LineField& field,
                     const SurfaceLocation& seed, const StreamlineParams& params, const char* who);

/// The face across the local edge opposite local vertex @p corner of @p face (-1: boundary).
int faceAcross(const ddf::DisplacementField& ddf, int face, int corner);

/// Barycentric coordinates in @p to of a point of @p from whose coordinate @p dropped is 0
/// (a point on their shared edge).
Vec3 mapAcross(const ddf::DisplacementField& ddf, int from, int to, const Vec3& bary, int dropped);

/// Existing paths in a SeparationGrid of cell size = the stop distance (no normals, so no
/// segment is ignored); nothing is near when the distance is not positive.
class PathProximity {
 public:
  PathProximity(const std::vector<std::vector<Vec3>>& paths, double distanceMm);
  /// True when @p q is closer than the distance to a path.
  bool near(const Vec3& q) const;

 private:
  double distance_;
  SeparationGrid grid_;
};

/// Field direction at a point: unit tangent of the surface, the same direction as a
/// barycentric velocity per mm of arc length (components sum to 0), and the unit normal.
struct FieldSample {
  Vec3 dir = Vec3::Zero();
  Vec3 dBary = Vec3::Zero();
  Vec3 normal = Vec3::Zero();
};

/// Tangents of the surface g + h v along the parameter directions a = e1 - e2 and c = e3 - e2
/// at @p mu of @p face, with h interpolated over @p cell (the raster triangle of mu).
struct SurfaceJacobian {
  Vec3 ja = Vec3::Zero();
  Vec3 jc = Vec3::Zero();
  /// The barycentric velocity (components sum to 0) whose image is nearest @p d.
  Vec3 toBary(const Vec3& d) const;
};
SurfaceJacobian surfaceJacobian(const ddf::DisplacementField& ddf, int face, const Vec3& mu,
                                const RasterCell& cell);

/// The height h interpolated linearly over @p cell (as ddf::interpolateOnFace does).
double cellHeight(const ddf::DisplacementField& ddf, const RasterCell& cell);

/// Interpolation of a sign-free line field and of the surface over the raster triangles.
class FieldSampler {
 public:
  FieldSampler(const ddf::DisplacementField& ddf, const LineField& field, double minCoherence)
      : ddf_(ddf), field_(field), minCoherence_(minCoherence) {}

  const ddf::DisplacementField& ddf() const { return ddf_; }
  const LineField& field() const { return field_; }
  /// The surface location at (face, bary) (bary used as given).
  SurfaceLocation locate(int face, const Vec3& bary) const;
  /// The interpolated field at (face, bary), each entry's sign aligned with @p ref, projected
  /// onto the tangent plane, normalised and signed like @p ref; nullopt where the field is
  /// undefined (a zero entry with weight) or incoherent (StreamlineParams::minCoherence).
  std::optional<FieldSample> sample(int face, const Vec3& bary, const Vec3& ref) const;
  /// The sign-free starting direction at @p start: the field there, signed by the canonical
  /// sign of the heaviest defined entry of its cell and then made canonical itself.
  std::optional<Vec3> startDirection(const SurfaceLocation& start) const;

 private:
  const ddf::DisplacementField& ddf_;
  const LineField& field_;
  double minCoherence_;
};

/// One direction of a line from the seed.
struct HalfLine {
  std::vector<SurfaceLocation> points;  ///< after the seed
  StopReason stop = StopReason::MaxLength;
  double lengthMm = 0.0;
  int steps = 0;
};

/// The stop rules every tracer shares: face mask, closed loop and existing paths.
class StopRules {
 public:
  StopRules(const StreamlineParams& params, double stepMm);
  bool allowed(int face) const {
    return mask_.empty() || mask_[static_cast<std::size_t>(face)] != 0;
  }
  /// The loop or proximity stop at the newest point of @p half (closing a loop appends the
  /// seed and its distance).
  std::optional<StopReason> at(HalfLine& half, const SurfaceLocation& seed) const;

 private:
  const std::vector<std::uint8_t>& mask_;
  double loopTolerance_;
  double minLoopLength_;
  PathProximity proximity_;
};

/// The seed located on the surface and the sign-free forward direction there; a one-point
/// line in @p early when nothing can be traced (seed outside the mask: RegionBoundary;
/// undefined field: Singularity).
struct TraceStart {
  SurfaceLocation start;
  Vec3 dir0 = Vec3::Zero();
};
std::optional<TraceStart> prepareTrace(const FieldSampler& sampler, const StopRules& rules,
                                       const SurfaceLocation& seed, Streamline& early);

/// The length of the next step of @p half, mm: @p stepMm cut to the length budget; nullopt when
/// the length or step budget is used up (a MaxLength stop). Reports progress every 256 steps.
/// @throws Cancelled if params.progress asks to stop.
std::optional<double> nextStepLength(const HalfLine& half, double stepMm, double lengthBudget,
                                     int stepBudget, const StreamlineParams& params);

/// Appends @p next, @p moved mm on, to @p half, then applies @p edgeStop (a stop met on the
/// way to next) and the loop and proximity rules; true when @p half stopped there.
bool appendPoint(HalfLine& half, const SurfaceLocation& next, double moved,
                 const std::optional<StopReason>& edgeStop, const StopRules& rules,
                 const SurfaceLocation& seed);

/// Traces forward with @p dir0, then (unless the loop closed) backward with the remaining
/// length and step budgets, and joins both halves around @p start.
template <class TraceHalf>
Streamline traceBothWays(const TraceStart& s, const StreamlineParams& params,
                         TraceHalf&& traceHalf) {
  const HalfLine forward = traceHalf(s.dir0, params.maxLengthMm, params.maxSteps);
  HalfLine backward;
  backward.stop = StopReason::ClosedLoop;
  if (forward.stop != StopReason::ClosedLoop) {
    backward = traceHalf(Vec3(-s.dir0), params.maxLengthMm - forward.lengthMm,
                         params.maxSteps - forward.steps);
  }
  Streamline line;
  line.stop = forward.stop;
  line.backwardStop = backward.stop;
  line.points.assign(backward.points.rbegin(), backward.points.rend());
  line.seedIndex = line.points.size();
  line.points.push_back(s.start);
  line.points.insert(line.points.end(), forward.points.begin(), forward.points.end());
  line.lengthMm = forward.lengthMm + backward.lengthMm;
  return line;
}

/// The driver every tracer shares: checks the input (@p who names the caller), builds the
/// field sampler and stop rules, prepares the seed and traces both halves with the stepper
/// makeStepper(sampler, rules, stepMm) returns (its traceHalf(start, dir, length, steps) gives a
/// HalfLine); finish(sampler, rules, line) may then post-process the joined line.
template <class MakeStepper, class Finish>
Streamline traceWith(const ddf::DisplacementField& ddf, const LineField& field,
                     const SurfaceLocation& seed, const StreamlineParams& params, const char* who,
                     MakeStepper&& makeStepper, Finish&& finish) {
  checkTraceInput(ddf, field, seed, params, who);
  const double stepMm = params.stepMm > 0.0 ? params.stepMm : meanRasterSpacing(ddf);
  const FieldSampler sampler(ddf, field, params.minCoherence);
  const StopRules rules(params, stepMm);
  Streamline early;
  const auto start = prepareTrace(sampler, rules, seed, early);
  if (!start) return early;
  const auto stepper = makeStepper(sampler, rules, stepMm);
  Streamline line = traceBothWays(*start, params, [&](const Vec3& dir, double length, int steps) {
    return stepper.traceHalf(start->start, dir, length, steps);
  });
  finish(sampler, rules, line);
  return line;
}

/// traceWith without post-processing.
template <class MakeStepper>
Streamline traceWith(const ddf::DisplacementField& ddf, const LineField& field,
                     const SurfaceLocation& seed, const StreamlineParams& params, const char* who,
                     MakeStepper&& makeStepper) {
  return traceWith(ddf, field, seed, params, who, std::forward<MakeStepper>(makeStepper),
                   [](const FieldSampler&, const StopRules&, Streamline&) {});
}

/// The surface location nearest @p x found by V-projecting it onto @p face and, while the foot
/// lies outside, onto the face across the edge it lies beyond (never into a face the rules
/// forbid; there the foot is clamped onto the face); nullopt if a face has no V-projection.
std::optional<SurfaceLocation> relocate(const FieldSampler& sampler, const StopRules& rules,
                                        int face, const Vec3& x);

/// Polyline length of @p points, mm.
double polylineLength(const std::vector<SurfaceLocation>& points);

}  // namespace ddfcam::planning::detail
