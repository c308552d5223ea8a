// SPDX-License-Identifier: MIT
// ddfcam: deformed vs mould surface on the mould's DDF: deviations, vectors, statistics.
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/surface_comparison.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void checkParams(const ComparisonParams& params) {
  if (params.resolution < 2)
    throw InvalidInput("compareSurfaces: resolution must be >= 2, got " +
                       std::to_string(params.resolution));
  validateToleranceBand(params.band);
}

void checkDeformed(const ddf::TriangleMesh& deformed) {
  if (deformed.triangles.empty() || deformed.vertices.empty())
    throw InvalidInput("compareSurfaces: the deformed mesh is empty (" +
                       std::to_string(deformed.vertices.size()) + " vertices, " +
                       std::to_string(deformed.triangles.size()) + " triangles)");
}

// Maps a sub-range [from, to] of the overall progress onto a callback (empty stays empty).
ProgressCallback subProgress(const ProgressCallback& progress, double from, double to) {
  if (!progress) return {};
  return [progress, from, to](double x) { return progress(from + (to - from) * x); };
}

std::string boxText(const Vec3& lo, const Vec3& hi) {
  std::ostringstream out;
  out.precision(4);
  out << "(" << lo.x() << ", " << lo.y() << ", " << lo.z() << ")..(" << hi.x() << ", " << hi.y()
      << ", " << hi.z() << ") mm";
  return out.str();
}

[[noreturn]] void throwNoOverlap(const ddf::DisplacementField& mould,
                                 const ddf::TriangleMesh& deformed) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int v = 0; v < mould.vertexCount(); ++v) {
    lo = lo.cwiseMin(mould.position(v));
    hi = hi.cwiseMax(mould.position(v));
  }
  const auto box = deformed.bounds();
  throw InvalidInput(
      "compareSurfaces: the surfaces do not overlap: no raster point of the mould (" +
      std::to_string(mould.faceCount()) + " triangles, " + boxText(lo, hi) +
      ") finds the deformed surface (" + std::to_string(deformed.triangles.size()) +
      " triangles, " + boxText(box[0], box[1]) + ")");
}

// The mould surface itself: heights 0, so raster normals and areas are the mould's.
ddf::DisplacementField flatMould(const ddf::DisplacementField& mouldDdf) {
  ddf::DisplacementField flat = mouldDdf;
  std::fill(flat.allHeights().begin(), flat.allHeights().end(), 0.0f);
  return flat;
}

// Statistics over the resolved faces; throws when all deviations found lie on unresolved ones.
ErrorStatistics resolvedStatistics(const SurfaceComparison& comparison,
                                   const ddf::DisplacementField& flat, const ToleranceBand& band) {
  const std::vector<int> faces = resolvedFaces(comparison);
  const ComparisonCoverage coverage = comparisonCoverage(comparison);
  if (faces.empty() || !(coverage.compared.coveredAreaMm2 > 0.0))
    throw InvalidInput(
        "compareSurfaces: the comparison failed: every deviation found lies on one "
        "of the " +
        std::to_string(coverage.unresolvedFaces) +
        " unresolved faces (the deformation sequence did not resolve them), so "
        "none can be trusted; allow more stages or check the alignment");
  return errorStatistics(comparison.deviation, flat, band, faces);
}

// Deviation vectors q - g and signed deviations (q - g) . n per raster point copy.
void fillDeviations(const ddf::DisplacementField& flat, const std::vector<Vec3>& deformedPoints,
                    bool flipNormal, SurfaceComparison& out) {
  const std::vector<Vec3> normals = rasterPointNormals(flat);
  const double sign = flipNormal ? -1.0 : 1.0;
  const int n = flat.raster().steps();
  out.deviation =
      ScalarField{"deviation", "mm", true, std::vector<float>(deformedPoints.size()), {}};
  out.deviationVectors.assign(deformedPoints.size(), Vec3::Constant(kNaN));
  tbb::parallel_for(tbb::blocked_range<int>(0, flat.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      std::size_t l = static_cast<std::size_t>(f) * flat.pointsPerFace();
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i + k <= n; ++i, ++l) {
          const Vec3& q = deformedPoints[l];
          if (!q.allFinite()) {
            out.deviation.values[l] = static_cast<float>(kNaN);
            continue;
          }
          const Vec3 d = q - flat.basePoint(f, flat.rasterBary(i, k));
          out.deviationVectors[l] = d;
          out.deviation.values[l] = static_cast<float>(sign * d.dot(normals[l]));
        }
    }
  });
}

}  // namespace

SurfaceComparison compareSurfaces(const ddf::TriangleMesh& mould, const ddf::TriangleMesh& deformed,
                                  const ComparisonParams& params) {
  checkParams(params);
  if (mould.triangles.empty() || mould.vertices.empty())
    throw InvalidInput("compareSurfaces: the mould mesh is empty (" +
                       std::to_string(mould.vertices.size()) + " vertices, " +
                       std::to_string(mould.triangles.size()) + " triangles)");
  checkDeformed(deformed);
  ddf::ConversionParams conversion;
  conversion.resolution = params.resolution;
  // The sequence sets its own vector lengths and heights: the length choice would be wasted.
  conversion.chooseLengths = false;
  conversion.progress = subProgress(params.progress, 0.0, 0.1);
  const ddf::ConversionResult converted = ddf::convertMeshToDdf(mould, conversion);
  ComparisonParams rest = params;
  rest.progress = subProgress(params.progress, 0.1, 1.0);
  return compareSurfaces(converted.ddf, deformed, rest);
}

SurfaceComparison compareSurfaces(const ddf::DisplacementField& mouldDdf,
                                  const ddf::TriangleMesh& deformed,
                                  const ComparisonParams& params) {
  validateToleranceBand(params.band);
  checkDeformed(deformed);
  if (mouldDdf.faceCount() == 0) throw InvalidInput("compareSurfaces: the mould DDF has no faces");
  ddf::DeformationSequenceParams sequenceParams = params.sequence;
  if (params.progress) sequenceParams.progress = subProgress(params.progress, 0.0, 0.95);
  SurfaceComparison out;
  out.sequence = ddf::buildDeformationSequence(mouldDdf, deformed, sequenceParams);
  const ddf::DisplacementField flat = flatMould(mouldDdf);
  fillDeviations(flat, out.sequence.deformedPoints, params.flipNormal, out);
  if (std::none_of(out.deviation.values.begin(), out.deviation.values.end(),
                   [](float x) { return std::isfinite(x); }))
    throwNoOverlap(mouldDdf, deformed);
  out.band = params.band;
  out.statistics = resolvedStatistics(out, flat, params.band);
  reportProgress(params.progress, 1.0);
  return out;
}

void updateComparisonBand(SurfaceComparison& comparison, const ToleranceBand& band,
                          bool reverseSign) {
  validateToleranceBand(band);
  if (comparison.sequence.stages.empty())
    throw InvalidInput("updateComparisonBand: the comparison has no stages");
  if (reverseSign)
    for (float& value : comparison.deviation.values) value = -value;
  comparison.band = band;
  comparison.statistics =
      resolvedStatistics(comparison, flatMould(comparison.sequence.stages[0].ddf), band);
}

std::string stallAdvice(const SurfaceComparison& comparison) {
  const ddf::DeformationSequence& sequence = comparison.sequence;
  if (!sequence.stalled) return {};
  return "the deformation sequence stalled after " + std::to_string(sequence.stages.size()) +
         " stages with " + std::to_string(sequence.unresolvedFaces.size()) + " of " +
         std::to_string(sequence.stages.at(0).ddf.faceCount()) +
         " faces still leaving the unique-projection crust (each split carried only a sliver of "
         "the deformation; those faces are left out of the statistics). The formed surface "
         "lies beyond the crust the mould's support allows there: check the alignment, swap "
         "mould and formed (the smoother, coarser surface should be the mould), or use a "
         "coarser mould support (decimate a dense mesh such as an exported raster mesh)";
}

std::vector<int> resolvedFaces(const SurfaceComparison& comparison) {
  const int faces = comparison.sequence.stages.at(0).ddf.faceCount();
  const std::vector<int>& unresolved = comparison.sequence.unresolvedFaces;
  std::vector<int> out;
  out.reserve(static_cast<std::size_t>(faces));
  for (int f = 0; f < faces; ++f)
    if (!std::binary_search(unresolved.begin(), unresolved.end(), f)) out.push_back(f);
  return out;
}

ComparisonCoverage comparisonCoverage(const SurfaceComparison& comparison) {
  const ddf::DisplacementField flat = flatMould(comparison.sequence.stages.at(0).ddf);
  const std::vector<double> areas = rasterPointAreas(flat);
  const std::vector<int>& unresolved = comparison.sequence.unresolvedFaces;
  std::vector<char> isUnresolved(static_cast<std::size_t>(flat.faceCount()), 0);
  for (int f : unresolved)
    if (f >= 0 && f < flat.faceCount()) isUnresolved[static_cast<std::size_t>(f)] = 1;
  ComparisonCoverage out;
  out.unresolvedFaces = unresolved.size();
  const std::vector<float>& deviation = comparison.deviation.values;
  for (std::size_t l = 0; l < areas.size() && l < deviation.size(); ++l) {
    out.compared.totalAreaMm2 += areas[l];
    if (!std::isfinite(deviation[l]))
      out.missingAreaMm2 += areas[l];
    else if (isUnresolved[l / flat.pointsPerFace()])
      out.unresolvedAreaMm2 += areas[l];
    else
      out.compared.coveredAreaMm2 += areas[l];
  }
  return out;
}

ScalarField crossingRegionField(const SurfaceComparison& comparison) {
  const ddf::DisplacementField& ddf = comparison.sequence.stages.at(0).ddf;
  ScalarField out{"unique projection fails", "", false,
                  std::vector<float>(ddf.allHeights().size(), 0.0f), {}};
  const auto mark = [&](const std::vector<int>& faces, float value) {
    for (int f : faces) {
      auto begin = out.values.begin() + static_cast<std::ptrdiff_t>(f * ddf.pointsPerFace());
      std::fill(begin, begin + static_cast<std::ptrdiff_t>(ddf.pointsPerFace()), value);
    }
  };
  mark(comparison.sequence.crossingFaces, 1.0f);
  mark(comparison.sequence.unresolvedFaces, 2.0f);
  return out;
}

}  // namespace ddfcam::planning
