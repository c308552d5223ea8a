// SPDX-License-Identifier: MIT
// ddfcam: path spacing from error maps (sec. 8.4.1): an advancing front of paths, then fix-ups.
#include <ddfcam/planning/lines/spacing_refinement.h>

#include "spacing_workpiece.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/lines/line_ordering.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

namespace ddfcam::planning {
namespace {

/// Largest number of times a front path is moved back because its scallop is too high.
constexpr int kFrontCorrections = 4;

/// Largest number of violating raster points (the worst) a fix-up iteration seeds from.
constexpr std::size_t kFixUpCandidates = 4096;

void validateInputs(const ddf::DisplacementField& goal, const LineField& field,
                    const std::vector<std::uint8_t>& faceMask,
                    const SpacingRefinementParams& params) {
  if (field.size() != goal.allHeights().size()) {
    throw InvalidInput("refineSpacing: the flow field has " + std::to_string(field.size()) +
                       " entries, the goal " + std::to_string(goal.allHeights().size()) +
                       " raster points");
  }
  if (!faceMask.empty() && faceMask.size() != static_cast<std::size_t>(goal.faceCount())) {
    throw InvalidInput("refineSpacing: the face mask has " + std::to_string(faceMask.size()) +
                       " entries, the goal " + std::to_string(goal.faceCount()) + " faces");
  }
  if (!faceMask.empty() && std::none_of(faceMask.begin(), faceMask.end(), [](auto v) { return v; }))
    throw InvalidInput("refineSpacing: the region (face mask) is empty");
  if (!(params.toleranceMm > 0.0) || !std::isfinite(params.toleranceMm))
    throw InvalidInput("refineSpacing: tolerance " + std::to_string(params.toleranceMm) +
                       " mm is not > 0");
  if (params.maxIterations < 0)
    throw InvalidInput("refineSpacing: maxIterations " + std::to_string(params.maxIterations) +
                       " is negative");
  if (params.sampleStepMm < 0.0 || params.minSpacingMm < 0.0 || params.stockAllowanceMm < 0.0)
    throw InvalidInput("refineSpacing: sample step, minimum spacing and allowance must be >= 0");
  const double allowance =
      params.stockAllowanceMm > 0.0 ? params.stockAllowanceMm : 2.5 * params.toleranceMm;
  if (!(allowance > 2.0 * params.toleranceMm))
    throw InvalidInput("refineSpacing: the stock allowance " + std::to_string(allowance) +
                       " mm is not above twice the tolerance");
}

/// One run of refineSpacing(): the workpiece, the paths so far and the recorded iterations.
class Refiner {
 public:
  Refiner(const ddf::DisplacementField& goal, const LineField& field,
          const std::vector<std::uint8_t>& faceMask, const Tool& tool,
          const SpacingRefinementParams& params)
      : goal_(goal), field_(field), mask_(faceMask), tool_(tool), params_(params) {
    validateTool(tool);
    tracing_ = params.tracing;
    tracing_.faceMask = faceMask;
    tracing_.progress = nullptr;
    tolerance_ = params.toleranceMm;
    result_.allowanceMm =
        params.stockAllowanceMm > 0.0 ? params.stockAllowanceMm : 2.5 * params.toleranceMm;
    rasterSpacing_ = spacing::meanRasterSpacing(goal, faceMask);
    delta_ = params.sampleStepMm > 0.0 ? params.sampleStepMm : 0.25 * rasterSpacing_;
    minSpacing_ = params.minSpacingMm > 0.0 ? params.minSpacingMm : rasterSpacing_;
    work_ = spacing::raisedStock(goal, result_.allowanceMm);
  }

  SpacingRefinementResult run() {
    sampleTransverseLine();
    runFront();
    for (int it = 1; it <= params_.maxIterations; ++it) {
      reportProgress(params_.progress, 0.5 + 0.5 * (it - 1) / params_.maxIterations);
      if (!fixUp()) break;
    }
    reportProgress(params_.progress, 1.0);
    return finish();
  }

 private:
  Streamline trace(const ddf::SurfaceLocation& seed) const {
    Streamline line = traceStreamline(goal_, field_, seed, tracing_);
    dropRepeatedPoints(line);
    return line;
  }

  void cut(const std::vector<Streamline>& lines) {
    spacing::cutLines(work_, goal_, lines, tool_, params_.toolIndex, params_.pathParams,
                      params_.depthBuffer, feedTolerance());
  }

  void sampleTransverseLine() {
    const ddf::SurfaceLocation seed = params_.transverseSeed
                                          ? *params_.transverseSeed
                                          : spacing::regionCentreLocation(goal_, mask_);
    const Streamline across =
        traceStreamline(goal_, transverseField(goal_, field_), seed, tracing_);
    if (across.points.size() < 2)
      throw InvalidInput("refineSpacing: no transverse line can be traced through the region");
    // The line's own end points close the samples, so that the strips between the region
    // boundary and the outer paths are checked too (the last step is shorter than delta).
    samples_ = seedsAlong(goal_, across, delta_);
    if ((samples_.front().point - across.points.front().point).norm() > 1e-9)
      samples_.insert(samples_.begin(), across.points.front());
    if ((samples_.back().point - across.points.back().point).norm() > 1e-9)
      samples_.push_back(across.points.back());
    if (samples_.size() < 3)
      throw InvalidInput("refineSpacing: the transverse line through the region is too short");
  }

  double deviationAt(const std::vector<float>& error, std::size_t j) const {
    return ddf::interpolateOnFace(goal_, error, samples_[j].face, samples_[j].bary);
  }

  /// Distance along the transverse line from sample @p from to where @p error first exceeds
  /// the tolerance (linear between samples); nullopt if it never does up to the far end.
  std::optional<double> reachForward(const std::vector<float>& error, std::size_t from) const {
    double previous = deviationAt(error, from);
    if (!std::isfinite(previous)) previous = 0.0;
    std::size_t previousIndex = from;
    for (std::size_t j = from + 1; j < samples_.size(); ++j) {
      const double e = deviationAt(error, j);
      if (!std::isfinite(e)) continue;
      if (e > frontTarget()) {
        const double frac =
            previous < frontTarget() ? (frontTarget() - previous) / (e - previous) : 0.0;
        return (static_cast<double>(previousIndex - from) + frac) * delta_;
      }
      previous = e;
      previousIndex = j;
    }
    return std::nullopt;
  }

  /// Sample index of the first front path: the reach of a trial groove cut one raster spacing
  /// from the start of the transverse line into a scratch copy of the stock.
  std::size_t firstFrontIndex() {
    const std::size_t last = samples_.size() - 1;
    const std::size_t trialIndex =
        std::min(last, static_cast<std::size_t>(std::lround(rasterSpacing_ / delta_)));
    ddf::DisplacementField trialWork = work_;
    spacing::cutLines(trialWork, goal_, {trace(samples_[trialIndex])}, tool_, params_.toolIndex,
                      params_.pathParams, params_.depthBuffer, feedTolerance());
    const auto reach = reachForward(spacing::regionDeviation(trialWork, goal_, mask_), trialIndex);
    if (!reach) return last / 2;
    return std::min(last, static_cast<std::size_t>(std::floor(*reach / delta_)));
  }

  void runFront() {
    const std::size_t last = samples_.size() - 1;
    // The first path: at the reach of a trial groove from the start, so that the strip between
    // the region boundary and the path is within the tolerance.
    std::size_t j = placeCorrected(0, firstFrontIndex(), false).first;
    for (;;) {
      reportProgress(params_.progress, 0.5 * static_cast<double>(j) / static_cast<double>(last));
      const auto reach = reachForward(error_, j);
      if (!reach || j == last) break;
      const auto step = std::max<std::size_t>(
          {static_cast<std::size_t>(std::floor(2.0 * gain_ * *reach / delta_)), minStep(), 1});
      const std::size_t proposed = std::min(last, j + step);
      const auto [next, scallop] = placeCorrected(j, proposed, true);
      // Feedback: 2 d predicts the spacing of a symmetric groove; the scallop actually left
      // (tool facets, poses, curvature) tunes the next prediction where it grows about with
      // the square of the spacing (not for a step-shaped groove, whose scallop is ~0 or the
      // whole allowance). The end path is no sample.
      if (next == proposed && proposed < last && scallop > 0.5 * frontTarget())
        gain_ = std::clamp(gain_ * std::sqrt(0.95 * frontTarget() / scallop), 0.8, 1.25);
      result_.frontSpacingsMm.push_back(static_cast<double>(next - j) * delta_);
      j = next;
    }
    if (paths_.empty()) throw InvalidInput("refineSpacing: no path can be traced in the region");
    record(static_cast<int>(paths_.size()));
  }

  std::size_t minStep() const {
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(minSpacing_ / delta_)));
  }

  /// Cuts a front path at sample @p proposed; while the largest deviation between sample
  /// @p from and it exceeds the tolerance, undoes it and places it closer to @p from (the
  /// scallop grows about with the square of the distance). @p from is a path when
  /// @p fromPath, else the start of the line. Returns the sample index used and the scallop.
  std::pair<std::size_t, double> placeCorrected(std::size_t from, std::size_t proposed,
                                                bool fromPath) {
    const ddf::DisplacementField before = work_;
    const std::size_t pathsBefore = paths_.size();
    std::size_t at = proposed;
    for (int attempt = 0;; ++attempt) {
      addFrontPath(at);
      const double scallop = largestBetween(from, at);
      const std::size_t distance = at - from;
      const std::size_t smallest = fromPath ? minStep() : 0;
      if (scallop <= frontTarget() || distance <= smallest || attempt == kFrontCorrections)
        return {at, scallop};
      const double shrink = std::min(0.99, 0.99 * std::sqrt(frontTarget() / scallop));
      const auto shorter =
          static_cast<std::size_t>(std::floor(static_cast<double>(distance) * shrink));
      at = from + std::max(smallest, std::min(shorter, distance - 1));
      work_ = before;
      paths_.resize(pathsBefore);
    }
  }

  /// Traces the path through sample @p j, cuts it and updates the error field.
  void addFrontPath(std::size_t j) {
    // A seed on the region boundary may not leave it; the end samples are boundary points.
    j = std::clamp<std::size_t>(j, 1, samples_.size() - 2);
    const Streamline line = trace(samples_[j]);
    if (line.points.size() >= 2) {
      paths_.push_back(line);
      cut({line});
    }
    error_ = spacing::regionDeviation(work_, goal_, mask_);
  }

  /// Largest deviation at the transverse samples from @p from to @p to (the scallop between
  /// two neighbouring front paths).
  double largestBetween(std::size_t from, std::size_t to) const {
    double worst = -std::numeric_limits<double>::infinity();
    for (std::size_t j = from; j <= to; ++j) {
      const double e = deviationAt(error_, j);
      if (std::isfinite(e)) worst = std::max(worst, e);
    }
    return worst;
  }

  /// One fix-up iteration: paths through the worst violating raster points, each farther than
  /// half the smallest front spacing from the paths added before it. False if nothing to do.
  bool fixUp() {
    std::vector<std::size_t> violating;
    for (std::size_t i = 0; i < error_.size(); ++i)
      if (error_[i] > tolerance_) violating.push_back(i);
    if (violating.empty()) return false;
    // The worst points first; a bounded number keeps an iteration cheap on large parts.
    const std::size_t considered = std::min(violating.size(), kFixUpCandidates);
    std::partial_sort(violating.begin(), violating.begin() + considered, violating.end(),
                      [&](std::size_t a, std::size_t b) { return error_[a] > error_[b]; });
    violating.resize(considered);
    const double clearance = 0.5 * std::max(minSpacing_, smallestFrontSpacing());
    std::vector<Streamline> added;
    for (std::size_t index : violating) {
      const ddf::SurfaceLocation seed = spacing::rasterLocation(goal_, index);
      // A seed on top of an existing path would add a duplicate that changes nothing (e.g.
      // material left at a feed end): such points stay reported instead.
      if (nearAny(seed.point, added, clearance) || nearAny(seed.point, paths_, 0.5 * clearance))
        continue;
      Streamline line = trace(seed);
      if (line.points.size() >= 2) added.push_back(std::move(line));
    }
    if (added.empty()) return false;
    cut(added);
    paths_.insert(paths_.end(), added.begin(), added.end());
    error_ = spacing::regionDeviation(work_, goal_, mask_);
    record(static_cast<int>(added.size()));
    return true;
  }

  static bool nearAny(const ddf::Vec3& p, const std::vector<Streamline>& lines, double distance) {
    return std::any_of(lines.begin(), lines.end(), [&](const Streamline& line) {
      return spacing::distanceToLine(p, line) < distance;
    });
  }

  /// Feed chord and cusp between poses: a twentieth of the tolerance. The transverse line meets
  /// the poses at any phase, so the front aims at the tolerance less this (frontTarget()).
  double feedTolerance() const { return 0.05 * tolerance_; }

  /// Deviation the front allows along the transverse line.
  double frontTarget() const { return tolerance_ - feedTolerance(); }

  double smallestFrontSpacing() const {
    const auto& s = result_.frontSpacingsMm;
    return s.empty() ? minSpacing_ : *std::min_element(s.begin(), s.end());
  }

  double totalLength() const {
    return std::accumulate(paths_.begin(), paths_.end(), 0.0,
                           [](double sum, const Streamline& l) { return sum + l.lengthMm; });
  }

  void record(int added) {
    const spacing::FieldExtremes extremes = spacing::fieldExtremes(error_);
    if (!extremes.any) throw InvalidInput("refineSpacing: the region has no finite deviation");
    RefinementIteration it;
    it.pathsAdded = added;
    it.pathCount = static_cast<int>(paths_.size());
    it.maxErrorMm = extremes.maxMm;
    it.minErrorMm = extremes.minMm;
    it.totalLengthMm = totalLength();
    it.worstPoint = spacing::rasterLocation(goal_, extremes.worst).point;
    it.paths = paths_;
    if (params_.keepErrorFields) it.errorField = error_;
    result_.iterations.push_back(std::move(it));
  }

  SpacingRefinementResult finish() {
    RefinementIteration& lastIteration = result_.iterations.back();
    lastIteration.errorField.clear();
    result_.paths = paths_;
    result_.toolPath = spacing::placeLines(goal_, paths_, tool_, params_.toolIndex,
                                           params_.pathParams, feedTolerance());
    result_.maxErrorMm = lastIteration.maxErrorMm;
    result_.minErrorMm = lastIteration.minErrorMm;
    result_.totalLengthMm = lastIteration.totalLengthMm;
    result_.converged = result_.maxErrorMm <= tolerance_;
    result_.produced = std::move(work_);
    result_.errorField = std::move(error_);
    return std::move(result_);
  }

  const ddf::DisplacementField& goal_;
  const LineField& field_;
  const std::vector<std::uint8_t>& mask_;
  const Tool& tool_;
  const SpacingRefinementParams& params_;
  StreamlineParams tracing_;
  double tolerance_ = 0.0;
  double rasterSpacing_ = 0.0;
  double delta_ = 0.0;
  double minSpacing_ = 0.0;
  double gain_ = 1.0;  ///< correction of the predicted front spacing 2 d, in [0.8, 1.25]
  std::vector<ddf::SurfaceLocation> samples_;
  ddf::DisplacementField work_;
  std::vector<float> error_;
  std::vector<Streamline> paths_;
  SpacingRefinementResult result_;
};

}  // namespace

SpacingRefinementResult refineSpacing(const ddf::DisplacementField& goal, const LineField& field,
                                      const std::vector<std::uint8_t>& faceMask, const Tool& tool,
                                      const SpacingRefinementParams& params) {
  validateInputs(goal, field, faceMask, params);
  Refiner refiner(goal, field, faceMask, tool, params);
  return refiner.run();
}

}  // namespace ddfcam::planning
