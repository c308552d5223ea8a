// SPDX-License-Identifier: MIT
// Test support: a small mould study with every member filled (two stages, NaNs, history).
#pragma once

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/planning/mould/mould_study.h>

#include <cmath>
#include <limits>

namespace ddfcam::test {

/// A study on a 2 x 2-cell plane (8 faces, m = 3: 6 points per face, 48 copies): both
/// surfaces with fields, point-pair alignment, a two-stage result with crossing faces and NaN
/// points, and a compensation history of two iterations.
inline planning::MouldStudy sampleMouldStudy() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  planning::MouldStudy study;
  const auto plane = [](double z) {
    return ddf::planePatch({.size = {4.0, 4.0}, .cellsX = 2, .cellsY = 2, .m = 3, .planeZMm = z})
        .ddf;
  };
  ddf::DisplacementField mouldDdf = plane(0.0);
  study.mould.name = "mould.stl";
  study.mould.sourcePath = "mould.stl";
  study.mould.mesh =
      ddf::TriangleMesh{{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {4, 4, 0}}, {{0, 1, 2}, {1, 3, 2}}};
  study.mould.fields = {{"thickness", "mm", false, {1.0f, 1.1f, 0.9f, nan}}};
  planning::LoadedSurface formed = study.mould;
  formed.name = "formed.vtu";
  formed.sourcePath = "formed.vtu";
  formed.mesh.vertices[3].z() = 0.25;
  formed.fields = {{"strain", "", true, {0.1f, -0.0f}}, {"thickness", "mm", false, {1, 2, 3, 4}}};
  study.formed = formed;
  study.alignment.method = planning::AlignmentMethod::PointPairs;
  study.alignment.transform[3] = 1.5;
  study.alignment.rmsMm = 0.125;
  for (int i = 0; i < 3; ++i)
    study.alignment.pointPairs.push_back({ddf::Vec3(i, 1, 2), ddf::Vec3(i + 1.5, 1, 2)});
  study.comparison.resolution = 3;
  study.comparison.band = {-0.25, 0.75};
  study.comparison.flipNormal = true;
  study.comparison.sequence.reachMm = 2.5;
  study.comparison.sequence.crustSafety = 0.7;
  study.comparison.sequence.maxStages = 5;

  planning::SurfaceComparison result;
  ddf::DeformationStage first{plane(0.1), 0.5, {1, 4}};
  ddf::DeformationStage second{plane(0.2), 1.0, {}};
  const std::size_t n = first.ddf.allHeights().size();
  first.ddf.allHeights()[7] = nan;
  result.sequence.stages = {first, second};
  for (std::size_t i = 0; i < n; ++i)
    result.sequence.deformedPoints.emplace_back(0.5 * i, 1.0, 0.25);
  result.sequence.deformedPoints[7] = ddf::Vec3::Constant(std::nan(""));
  result.sequence.crossingFaces = {1, 4};
  result.sequence.unresolvedFaces = {4};
  result.sequence.missingPoints = 1;
  result.deviation = {"deviation", "mm", true, std::vector<float>(n, 0.25f)};
  result.deviation.values[7] = nan;
  result.deviationVectors.assign(n, ddf::Vec3(0.0, 0.0, 0.25));
  result.deviationVectors[7] = ddf::Vec3::Constant(std::nan(""));
  result.statistics = {0.25, -0.5, 0.125, 0.3, 90.0, 6.0, 4.0, 16.0, 24};
  result.band = study.comparison.band;
  study.result = result;

  planning::CompensationHistory history;
  history.target = mouldDdf;
  const std::size_t nt = mouldDdf.allHeights().size();
  planning::CompensationIteration zero;
  zero.mouldHeights.assign(nt, 0.0f);
  zero.formedHeights.assign(nt, 0.3f);
  zero.formedHeights[2] = nan;
  zero.formedSource = "formed.vtu";
  zero.maxDeviationMm = 0.3;
  zero.rmsDeviationMm = 0.29;
  planning::CompensationIteration one;
  one.mouldHeights.assign(nt, -0.3f);
  one.lambda = 1.0;
  one.pointsOutsideCrust = 2;
  history.iterations = {zero, one};
  study.compensation = std::move(history);
  return study;
}

}  // namespace ddfcam::test
