// SPDX-License-Identifier: MIT
// ddfcam: the displacement adjustment loop on DDF heights: history, formed responses, steps.
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/surface_comparison.h>
#include <ddfcam/planning/mould/springback_compensation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace ddfcam::planning {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::size_t countOutsideCrust(const std::vector<float>& heights) {
  return static_cast<std::size_t>(std::count_if(heights.begin(), heights.end(), [](float h) {
    return std::isfinite(h) && std::abs(h) > 1.0f;
  }));
}

void checkSize(const ddf::DisplacementField& target, std::size_t size, const char* what) {
  if (size != target.allHeights().size()) {
    throw InvalidInput(std::string(what) + ": " + std::to_string(size) +
                       " heights given, the target DDF has " +
                       std::to_string(target.allHeights().size()) + " raster point copies");
  }
}

// v . n per raster point copy, n the unit normal of the support's raster (heights 0) oriented
// like v: the normal compareSurfaces() measures its deviations along.
std::vector<float> supportNormalFactors(const ddf::DisplacementField& target) {
  ddf::DisplacementField flat = target;
  std::fill(flat.allHeights().begin(), flat.allHeights().end(), 0.0f);
  const std::vector<ddf::Vec3> normals = rasterPointNormals(flat);
  std::vector<float> factors(normals.size());
  const int n = target.raster().steps();
  std::size_t l = 0;
  for (int f = 0; f < target.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l)
        factors[l] =
            static_cast<float>(target.vectorAt(f, target.rasterBary(i, k)).dot(normals[l]));
  return factors;
}

}  // namespace

CompensationHistory startCompensation(ddf::DisplacementField target) {
  if (target.faceCount() == 0) throw InvalidInput("startCompensation: the target DDF has no faces");
  CompensationHistory history{std::move(target), {}};
  CompensationIteration first;
  first.mouldHeights = history.target.allHeights();
  first.pointsOutsideCrust = countOutsideCrust(first.mouldHeights);
  history.iterations.push_back(std::move(first));
  return history;
}

std::vector<float> formedHeightsFromMesh(const ddf::DisplacementField& target,
                                         const ddf::TriangleMesh& formed,
                                         const ddf::DeformationSequenceParams& params) {
  ComparisonParams comparison;
  comparison.sequence = params;
  comparison.progress = params.progress;
  const SurfaceComparison result = compareSurfaces(target, formed, comparison);
  const std::vector<float> factors = supportNormalFactors(target);
  checkSize(target, result.deviation.values.size(), "formedHeightsFromMesh: comparison");
  std::vector<float> heights(factors.size(), kNaN);
  // Deviations on faces the sequence left unresolved are not trustworthy: NaN keeps the mould.
  std::vector<char> unresolved(static_cast<std::size_t>(target.faceCount()), 0);
  for (int f : result.sequence.unresolvedFaces) unresolved.at(static_cast<std::size_t>(f)) = 1;
  for (std::size_t l = 0; l < heights.size(); ++l) {
    if (unresolved[l / target.pointsPerFace()]) continue;
    const double deviation = result.deviation.values[l];
    // A stubble grazing the support (v . n ~ 0) cannot carry a normal deviation into a height.
    if (std::isfinite(deviation) && factors[l] > 1e-12f)
      heights[l] = static_cast<float>(deviation / static_cast<double>(factors[l]));
  }
  return heights;
}

void recordFormedResponse(CompensationHistory& history, std::vector<float> formedHeights,
                          std::string source) {
  if (history.iterations.empty())
    throw InvalidInput("recordFormedResponse: the compensation history has no iteration");
  checkSize(history.target, formedHeights.size(), "recordFormedResponse");
  ddf::DisplacementField formed = history.target;
  formed.allHeights() = formedHeights;
  const ScalarField deviation =
      deviationMap(formed, std::span<const float>(history.target.allHeights()));
  // Throws InvalidInput when no formed height is finite; the history stays unchanged then.
  const ErrorStatistics stats = errorStatistics(deviation, history.target, ToleranceBand{});
  CompensationIteration& last = history.iterations.back();
  last.formedHeights = std::move(formedHeights);
  last.formedSource = std::move(source);
  last.maxDeviationMm = std::max(std::abs(stats.maxMm), std::abs(stats.minMm));
  last.rmsDeviationMm = stats.rmsMm;
}

void compensationStep(CompensationHistory& history, double lambda) {
  if (!(lambda > 0.0 && lambda <= 10.0)) {
    throw InvalidInput("compensationStep: lambda = " + std::to_string(lambda) +
                       " is outside (0, 10]");
  }
  if (history.iterations.empty() || history.iterations.back().formedHeights.empty()) {
    throw InvalidInput("compensationStep: iteration " + std::to_string(history.iterations.size()) +
                       " has no forming response yet (import the formed part or run the model)");
  }
  const CompensationIteration& last = history.iterations.back();
  const std::vector<float>& target = history.target.allHeights();
  CompensationIteration next;
  next.mouldHeights = last.mouldHeights;
  for (std::size_t l = 0; l < target.size(); ++l) {
    const double s = last.formedHeights[l];
    if (std::isfinite(s))
      next.mouldHeights[l] = static_cast<float>(last.mouldHeights[l] - lambda * (s - target[l]));
  }
  next.lambda = lambda;
  next.pointsOutsideCrust = countOutsideCrust(next.mouldHeights);
  history.iterations.push_back(std::move(next));
}

ddf::TriangleMesh mouldMesh(const CompensationHistory& history, int iteration) {
  if (iteration < 0 || iteration >= static_cast<int>(history.iterations.size())) {
    throw InvalidInput("mouldMesh: iteration " + std::to_string(iteration) + " is outside [0, " +
                       std::to_string(history.iterations.size()) + ")");
  }
  ddf::DisplacementField mould = history.target;
  mould.allHeights() = history.iterations[static_cast<std::size_t>(iteration)].mouldHeights;
  return ddf::extractRasterMesh(mould).mesh;
}

}  // namespace ddfcam::planning
