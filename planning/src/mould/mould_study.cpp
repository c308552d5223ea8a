// SPDX-License-Identifier: MIT
// ddfcam: invariants and exact equality of the mould-planning part of a project.
#include <ddfcam/error.h>
#include <ddfcam/planning/mould/mould_study.h>

#include "../model/bitwise_equality.h"

#include <cmath>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>

namespace ddfcam::planning {
namespace {

using detail::sameBits;
using detail::sameEach;
using detail::sameOptional;

bool sameVecs(const std::vector<ddf::Vec3>& a, const std::vector<ddf::Vec3>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!sameBits(a[i], b[i])) return false;
  return true;
}

bool sameMeshField(const MeshField& a, const MeshField& b) {
  return a.name == b.name && a.unit == b.unit && a.perCell == b.perCell &&
         sameBits(a.values, b.values);
}

bool sameSurface(const LoadedSurface& a, const LoadedSurface& b) {
  return a.name == b.name && a.sourcePath == b.sourcePath && triangleMeshesEqual(a.mesh, b.mesh) &&
         sameEach(a.fields, b.fields, sameMeshField);
}

bool sameAlignment(const SurfaceAlignmentRecord& a, const SurfaceAlignmentRecord& b) {
  if (a.method != b.method || !sameBits(a.transform.data(), b.transform.data(), 16) ||
      !sameBits(a.rmsMm, b.rmsMm) || a.pointPairs.size() != b.pointPairs.size())
    return false;
  for (std::size_t i = 0; i < a.pointPairs.size(); ++i)
    if (!sameBits(a.pointPairs[i][0], b.pointPairs[i][0]) ||
        !sameBits(a.pointPairs[i][1], b.pointPairs[i][1]))
      return false;
  return true;
}

bool sameBand(const ToleranceBand& a, const ToleranceBand& b) {
  return sameBits(a.lowerMm, b.lowerMm) && sameBits(a.upperMm, b.upperMm);
}

bool sameParams(const ComparisonParams& a, const ComparisonParams& b) {
  return a.resolution == b.resolution && sameBand(a.band, b.band) && a.flipNormal == b.flipNormal &&
         sameBits(a.sequence.reachMm, b.sequence.reachMm) &&
         sameBits(a.sequence.crustSafety, b.sequence.crustSafety) &&
         a.sequence.maxStages == b.sequence.maxStages;
}

bool sameStatistics(const ErrorStatistics& a, const ErrorStatistics& b) {
  return sameBits(a.maxMm, b.maxMm) && sameBits(a.minMm, b.minMm) && sameBits(a.meanMm, b.meanMm) &&
         sameBits(a.rmsMm, b.rmsMm) && sameBits(a.inTolerancePercent, b.inTolerancePercent) &&
         sameBits(a.materialLeftPercent, b.materialLeftPercent) &&
         sameBits(a.overcutPercent, b.overcutPercent) && sameBits(a.areaMm2, b.areaMm2) &&
         a.points == b.points;
}

bool sameStage(const ddf::DeformationStage& a, const ddf::DeformationStage& b) {
  return displacementFieldsEqual(a.ddf, b.ddf) && sameBits(a.fraction, b.fraction) &&
         a.crossingFaces == b.crossingFaces;
}

bool sameComparison(const SurfaceComparison& a, const SurfaceComparison& b) {
  const ddf::DeformationSequence& s = a.sequence;
  const ddf::DeformationSequence& t = b.sequence;
  return sameEach(s.stages, t.stages, sameStage) && sameVecs(s.deformedPoints, t.deformedPoints) &&
         s.crossingFaces == t.crossingFaces && s.unresolvedFaces == t.unresolvedFaces &&
         s.missingPoints == t.missingPoints && a.deviation.name == b.deviation.name &&
         a.deviation.unit == b.deviation.unit && a.deviation.isSigned == b.deviation.isSigned &&
         sameBits(a.deviation.values, b.deviation.values) &&
         sameVecs(a.deviationVectors, b.deviationVectors) &&
         sameStatistics(a.statistics, b.statistics) && sameBand(a.band, b.band);
}

bool sameIteration(const CompensationIteration& a, const CompensationIteration& b) {
  return sameBits(a.mouldHeights, b.mouldHeights) && sameBits(a.formedHeights, b.formedHeights) &&
         a.formedSource == b.formedSource && sameBits(a.maxDeviationMm, b.maxDeviationMm) &&
         sameBits(a.rmsDeviationMm, b.rmsDeviationMm) && sameBits(a.lambda, b.lambda) &&
         a.pointsOutsideCrust == b.pointsOutsideCrust;
}

bool sameHistory(const CompensationHistory& a, const CompensationHistory& b) {
  return displacementFieldsEqual(a.target, b.target) &&
         sameEach(a.iterations, b.iterations, sameIteration);
}

void checkCount(const std::string& item, std::size_t count, std::size_t expected) {
  if (count != expected)
    throw InvalidInput(item + ": " + std::to_string(count) + " values, expected " +
                       std::to_string(expected));
}

void checkMesh(const std::string& item, const ddf::TriangleMesh& mesh) {
  const int n = static_cast<int>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int v : mesh.triangles[t])
      if (v < 0 || v >= n)
        throw InvalidInput(item + ": triangle " + std::to_string(t) + " references vertex " +
                           std::to_string(v) + " of " + std::to_string(n));
}

void checkSurface(const std::string& item, const LoadedSurface& surface) {
  checkMesh(item + " mesh", surface.mesh);
  for (const MeshField& field : surface.fields)
    checkCount(
        item + " field '" + field.name + "' (" + (field.perCell ? "per cell" : "per vertex") + ")",
        field.values.size(),
        field.perCell ? surface.mesh.triangles.size() : surface.mesh.vertices.size());
}

void checkFaces(const std::string& item, const std::vector<int>& faces, int faceCount) {
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (faces[i] < 0 || faces[i] >= faceCount)
      throw InvalidInput(item + ": face " + std::to_string(faces[i]) + " out of range [0, " +
                         std::to_string(faceCount) + ")");
    if (i > 0 && faces[i] <= faces[i - 1])
      throw InvalidInput(item + ": face " + std::to_string(faces[i]) +
                         " is not above its predecessor (faces must be ascending, unique)");
  }
}

void checkAlignment(const SurfaceAlignmentRecord& alignment) {
  const int method = static_cast<int>(alignment.method);
  if (method < 0 || method > static_cast<int>(AlignmentMethod::BestFit))
    throw InvalidInput("alignment: unknown method " + std::to_string(method));
  for (double value : alignment.transform)
    if (!std::isfinite(value)) throw InvalidInput("alignment: the transform is not finite");
  if (!(alignment.rmsMm >= 0.0) || !std::isfinite(alignment.rmsMm))
    throw InvalidInput("alignment: RMS residual must be finite and >= 0");
  if (alignment.method == AlignmentMethod::PointPairs && alignment.pointPairs.size() < 3)
    throw InvalidInput("alignment: point pairs need at least three pairs, got " +
                       std::to_string(alignment.pointPairs.size()));
}

void checkParams(const ComparisonParams& params) {
  if (params.resolution < 2)
    throw InvalidInput("comparison parameters: resolution " + std::to_string(params.resolution) +
                       " must be >= 2");
  validateToleranceBand(params.band);
  const ddf::DeformationSequenceParams& s = params.sequence;
  if (!(s.reachMm >= 0.0) || !std::isfinite(s.reachMm))
    throw InvalidInput("comparison parameters: reach must be finite and >= 0 mm");
  if (!(s.crustSafety > 0.0 && s.crustSafety <= 1.0))
    throw InvalidInput("comparison parameters: crust safety must lie in (0, 1]");
  if (s.maxStages < 1) throw InvalidInput("comparison parameters: at least one stage");
}

void checkHistory(const CompensationHistory& history) {
  if (history.iterations.empty()) throw InvalidInput("compensation: no iteration");
  const std::size_t n = history.target.allHeights().size();
  for (std::size_t j = 0; j < history.iterations.size(); ++j) {
    const CompensationIteration& it = history.iterations[j];
    const std::string item = "compensation iteration " + std::to_string(j);
    checkCount(item + " mould heights", it.mouldHeights.size(), n);
    if (!it.formedHeights.empty()) checkCount(item + " formed heights", it.formedHeights.size(), n);
  }
}

}  // namespace

bool triangleMeshesEqual(const ddf::TriangleMesh& a, const ddf::TriangleMesh& b) {
  return a.triangles == b.triangles && sameVecs(a.vertices, b.vertices);
}

bool displacementFieldsEqual(const ddf::DisplacementField& a, const ddf::DisplacementField& b) {
  if (a.vertexCount() != b.vertexCount() || a.faceCount() != b.faceCount() ||
      a.resolution() != b.resolution())
    return false;
  for (int f = 0; f < a.faceCount(); ++f)
    if (a.faceVertices(f) != b.faceVertices(f)) return false;
  for (int v = 0; v < a.vertexCount(); ++v)
    if (!sameBits(a.position(v), b.position(v)) || !sameBits(a.vector(v), b.vector(v)))
      return false;
  return sameBits(a.allHeights(), b.allHeights());
}

void validateSurfaceComparison(const SurfaceComparison& comparison) {
  const ddf::DeformationSequence& sequence = comparison.sequence;
  if (sequence.stages.empty()) throw InvalidInput("comparison: the sequence has no stage");
  const ddf::DisplacementField& first = sequence.stages.front().ddf;
  const std::size_t n = first.allHeights().size();
  for (std::size_t s = 0; s < sequence.stages.size(); ++s) {
    const ddf::DeformationStage& stage = sequence.stages[s];
    const std::string item = "comparison stage " + std::to_string(s);
    if (stage.ddf.faceCount() != first.faceCount() || stage.ddf.resolution() != first.resolution())
      throw InvalidInput(item + ": faces or resolution differ from stage 0");
    checkCount(item + " heights", stage.ddf.allHeights().size(), n);
    checkFaces(item + " crossing faces", stage.crossingFaces, first.faceCount());
  }
  checkCount("comparison deformed points", sequence.deformedPoints.size(), n);
  checkFaces("comparison crossing faces", sequence.crossingFaces, first.faceCount());
  checkFaces("comparison unresolved faces", sequence.unresolvedFaces, first.faceCount());
  if (sequence.missingPoints > n)
    throw InvalidInput("comparison: " + std::to_string(sequence.missingPoints) +
                       " missing points of " + std::to_string(n));
  checkCount("comparison deviation", comparison.deviation.values.size(), n);
  checkCount("comparison deviation vectors", comparison.deviationVectors.size(), n);
  validateToleranceBand(comparison.band);
}

void validateMouldStudy(const MouldStudy& study) {
  checkSurface("mould", study.mould);
  if (study.formed) checkSurface("formed surface", *study.formed);
  checkAlignment(study.alignment);
  checkParams(study.comparison);
  if (study.result) validateSurfaceComparison(*study.result);
  if (study.compensation) checkHistory(*study.compensation);
}

bool mouldStudiesEqual(const MouldStudy& a, const MouldStudy& b) {
  return sameSurface(a.mould, b.mould) && sameOptional(a.formed, b.formed, sameSurface) &&
         sameAlignment(a.alignment, b.alignment) && sameParams(a.comparison, b.comparison) &&
         sameOptional(a.result, b.result, sameComparison) &&
         sameOptional(a.compensation, b.compensation, sameHistory);
}

}  // namespace ddfcam::planning
