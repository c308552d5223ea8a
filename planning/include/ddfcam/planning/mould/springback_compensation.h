// SPDX-License-Identifier: MIT
// ddfcam: springback compensation by displacement adjustment on DDF heights:
// mould_{j+1} = mould_j - lambda (formed_j - target).
#pragma once

#include <ddfcam/ddf/deformation_sequence.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/progress.h>

#include <Eigen/Core>

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief One iteration of the compensation loop: a mould and (once known) the part it forms.
struct CompensationIteration {
  /// Heights c_j of the mould surface on the target DDF (layout allHeights(), units of the
  /// local vector). Iteration 0 holds the target's own heights.
  std::vector<float> mouldHeights;
  /// Heights s_j of the part formed in mould c_j; empty until the forming response is known.
  /// NaN where the formed surface was not found along a stubble.
  std::vector<float> formedHeights;
  /// Where the response came from: the imported file's name, or the model, e.g.
  /// "linear model alpha=0.3". Empty while formedHeights is empty.
  std::string formedSource;
  /// Largest |s_j - t| along the target's normal, mm (NaN until known).
  double maxDeviationMm = std::numeric_limits<double>::quiet_NaN();
  /// Area-weighted RMS of s_j - t along the target's normal, mm (NaN until known).
  double rmsDeviationMm = std::numeric_limits<double>::quiet_NaN();
  /// lambda that made this mould from the previous iteration (0 for iteration 0).
  double lambda = 0.0;
  /// Raster point copies whose mould height left the crust [-1, 1] (the mould surface there is
  /// outside the region the target DDF represents uniquely).
  std::size_t pointsOutsideCrust = 0;
  bool operator==(const CompensationIteration&) const = default;
};

/// @brief The compensation history kept by the project.
struct CompensationHistory {
  /// Target DDF: support = the target (design) surface, vectors long enough to reach the formed
  /// parts; its heights are the target shape t (zero when the target is the support itself).
  ddf::DisplacementField target;
  /// Iterations in order; never empty once started.
  std::vector<CompensationIteration> iterations;
};

/// @brief Starts a history on @p target: iteration 0 with mould = target.
/// @throws InvalidInput if @p target has no faces.
CompensationHistory startCompensation(ddf::DisplacementField target);

/// @brief Heights of @p formed along the stubbles of @p target: the signed normal deviation of
/// compareSurfaces() divided by v . n (so that a single-stage comparison gives the filled
/// heights exactly). NaN where the formed surface was not found and on the faces the deformation
/// sequence left unresolved (their deviations are not trustworthy; compensationStep() keeps the
/// mould there).
/// @throws InvalidInput if the surfaces do not overlap or the comparison fails
/// (compareSurfaces()). @throws Cancelled via params.progress.
std::vector<float> formedHeightsFromMesh(const ddf::DisplacementField& target,
                                         const ddf::TriangleMesh& formed,
                                         const ddf::DeformationSequenceParams& params = {});

/// @brief Records the forming response of the last iteration's mould and its deviation
/// statistics (max |.| and RMS along the target normal, area weighted as errorStatistics()).
/// @throws InvalidInput if @p formedHeights has the wrong size or the history is empty.
void recordFormedResponse(CompensationHistory& history, std::vector<float> formedHeights,
                          std::string source);

/// @brief Appends the next mould c_{j+1} = c_j - lambda (s_j - t) (points whose s_j is NaN keep
/// c_j). @p lambda in (0, 10].
/// @throws InvalidInput if the last iteration has no forming response or lambda is out of range.
void compensationStep(CompensationHistory& history, double lambda);

/// @brief Surface of the mould of iteration @p iteration as a raster mesh (for export to the
/// forming simulation), mm. @throws InvalidInput for an iteration out of range.
ddf::TriangleMesh mouldMesh(const CompensationHistory& history, int iteration);

/// @brief Linear springback S(C) = P + A (C - P) for planning and tests: P the shape the sheet
/// springs back towards, A = I - diag(alpha) (isotropic: one alpha; anisotropic: one alpha per
/// frame axis x, y, z).
struct LinearSpringbackModel {
  /// Isotropic springback share in [0, 1). Default 0.3.
  double alpha = 0.3;
  /// Shares along the frame axes x, y, z, each in [0, 1); when set, used instead of alpha (the
  /// formed points then leave the stubbles and are resampled onto the target DDF). Default none.
  std::optional<Eigen::Vector3d> axisAlpha;
  /// Heights of P on the target DDF (layout allHeights()). Default empty (invalid until set,
  /// e.g. by calibrateSpringback()).
  std::vector<float> relaxedHeights;
};

/// @brief Formed heights of the mould @p mouldHeights under @p model on @p target.
/// @throws InvalidInput for sizes or alphas out of range.
std::vector<float> linearSpringback(const LinearSpringbackModel& model,
                                    const ddf::DisplacementField& target,
                                    std::span<const float> mouldHeights);

/// @brief The isotropic model that reproduces a measured first forming: from s_0 = P + (1 -
/// alpha)(t - P), P = t + (s_0 - t) / alpha. @throws InvalidInput for alpha outside (0, 1).
LinearSpringbackModel calibrateSpringback(const ddf::DisplacementField& target,
                                          std::span<const float> firstFormedHeights, double alpha);

}  // namespace ddfcam::planning
