// SPDX-License-Identifier: MIT
// ddfcam: a deformed surface as heights over a mould DDF, split into a sequence of DDFs where
// the unique-projection property would fail (dissertation ch. 9, fig. 9.5).
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/deformation_sequence.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/pseudo_normals.h>
#include <ddfcam/error.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "deformation_stage.h"

namespace ddfcam::ddf {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

void validateInput(const DisplacementField& mould, const TriangleMesh& deformed,
                   const DeformationSequenceParams& params) {
  if (mould.faceCount() == 0) throw InvalidInput("deformation sequence: the mould DDF is empty");
  if (deformed.triangles.empty())
    throw InvalidInput("deformation sequence: the deformed surface has no triangles");
  const int vertexCount = static_cast<int>(deformed.vertices.size());
  for (std::size_t t = 0; t < deformed.triangles.size(); ++t)
    for (const int v : deformed.triangles[t])
      if (v < 0 || v >= vertexCount)
        throw InvalidInput("deformation sequence: deformed triangle " + std::to_string(t) +
                           " has vertex index " + std::to_string(v) + " out of range");
  if (!(params.reachMm >= 0.0) || !std::isfinite(params.reachMm))
    throw InvalidInput("deformation sequence: reachMm must be finite and >= 0");
  if (!(params.crustSafety > 0.0 && params.crustSafety <= 1.0))
    throw InvalidInput("deformation sequence: crustSafety must be in (0, 1]");
  if (params.maxStages < 1) throw InvalidInput("deformation sequence: maxStages must be >= 1");
  if (params.stallStages < 0) throw InvalidInput("deformation sequence: stallStages must be >= 0");
}

// Unit directions of the mould's vectors (stage 0 keeps them).
std::vector<Vec3> mouldDirections(const DisplacementField& mould) {
  std::vector<Vec3> dirs(mould.vectors());
  for (std::size_t v = 0; v < dirs.size(); ++v) {
    const double length = dirs[v].norm();
    if (!(length > 0.0) || !std::isfinite(length))
      throw InvalidInput("deformation sequence: mould vector " + std::to_string(v) +
                         " is zero or not finite");
    dirs[v] /= length;
  }
  return dirs;
}

double boundingDiagonal(const DisplacementField& ddf) {
  Eigen::AlignedBox3d box;
  for (int v = 0; v < ddf.vertexCount(); ++v) box.extend(ddf.position(v));
  return box.diagonal().norm();
}

// Vector length of a stage: the requested reach, or 1.25 x the farthest support vertex.
double stageReach(const DisplacementField& field, const detail::TriangleBvh& bvh,
                  const DeformationSequenceParams& params) {
  if (params.reachMm > 0.0) return params.reachMm;
  const double floor = 1e-3 * boundingDiagonal(field);
  return std::max(1.25 * detail::largestVertexDistance(field, bvh), floor);
}

// A stage DDF on @p support with unit @p dirs scaled to the stage's reach, heights filled
// from @p deformed (NaN where a stubble misses it).
DisplacementField makeStage(const SupportMesh& support, std::vector<Vec3> dirs, int m,
                            const TriangleMesh& deformed, const detail::TriangleBvh& bvh,
                            const DeformationSequenceParams& params, double progressBase) {
  DisplacementField field(support, dirs, m, std::numeric_limits<float>::quiet_NaN());
  const double reach = stageReach(field, bvh, params);
  for (auto& d : dirs) d *= reach;
  field.setVectors(std::move(dirs));
  const CrustHash hash(field, crustHashParamsFor(field));
  FillParams fill;
  const double span = 1.0 / params.maxStages;
  if (params.progress)
    fill.progress = [&](double f) { return params.progress(progressBase + span * f); };
  fillFromMesh(field, hash, deformed, fill);
  return field;
}

struct Crossing {
  std::vector<int> faces;  // ascending
  double minRatio = kInf;  // smallest positive h0 / |h| over the crossing faces
};

Crossing findCrossing(const DisplacementField& field, double safety) {
  const std::vector<double> ratios = detail::crustRatios(field);
  Crossing crossing;
  for (int f = 0; f < field.faceCount(); ++f) {
    if (!(ratios[f] * safety < 1.0)) continue;
    crossing.faces.push_back(f);
    // Faces violating constraint 1 (h0 = 0) cannot be helped by any fraction; they stay
    // crossing and end up unresolved rather than forcing the smallest step everywhere.
    if (ratios[f] > 0.0) crossing.minRatio = std::min(crossing.minRatio, ratios[f]);
  }
  return crossing;
}

// Watches the splits for headway: a split that carried less than kSlowFraction of the remaining
// deformation, after which the crossing faces fell by less than kSlowDrop, made none.
class StallWatch {
 public:
  explicit StallWatch(int limit) : limit_(limit) {}

  // Called for stage k with its crossing count and the previous stage's fraction; true when
  // the last limit_ splits in a row made no headway.
  bool stalled(int k, std::size_t crossing, double previousFraction) {
    const bool slow =
        k > 0 && previousFraction<kSlowFraction&& static_cast<double>(crossing)>(1.0 - kSlowDrop) *
                     previous_;
    slowSplits_ = slow ? slowSplits_ + 1 : 0;
    previous_ = static_cast<double>(crossing);
    return limit_ > 0 && crossing > 0 && slowSplits_ >= limit_;
  }

 private:
  static constexpr double kSlowFraction = 0.25;
  static constexpr double kSlowDrop = 0.1;
  int limit_;
  int slowSplits_ = 0;
  double previous_ = 0.0;
};

std::vector<int> mergeSorted(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

// Moves @p support's vertices by fraction @p t of @p field's vertex heights; returns folds.
std::vector<int> advanceSupport(const DisplacementField& field, double t, SupportMesh& support) {
  const std::vector<Vec3> moves = detail::vertexMoves(field, t);
  std::vector<Vec3> positions(field.vertexCount());
  for (int v = 0; v < field.vertexCount(); ++v) {
    positions[v] = field.position(v) + moves[v];
    support.set_point(OpenMesh::VertexHandle(v), toOpenMesh(positions[v]));
  }
  return detail::flippedFaces(field, positions);
}

std::vector<Vec3> computeDeformedPoints(const DisplacementField& last, std::size_t& missing) {
  const std::size_t per = last.pointsPerFace();
  std::vector<Vec3> points(static_cast<std::size_t>(last.faceCount()) * per);
  const int n = last.raster().steps();
  tbb::parallel_for(tbb::blocked_range<int>(0, last.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f)
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i + k <= n; ++i) {
          const std::size_t local = last.raster().index(i, k);
          const float h = last.heights(f)[local];
          points[f * per + local] =
              std::isfinite(h) ? last.surfacePoint(f, i, k) : Vec3::Constant(kNaN);
        }
  });
  missing = std::count_if(points.begin(), points.end(),
                          [](const Vec3& p) { return !std::isfinite(p.x()); });
  return points;
}

}  // namespace

DeformationSequence buildDeformationSequence(const DisplacementField& mould,
                                             const TriangleMesh& deformed,
                                             const DeformationSequenceParams& params) {
  validateInput(mould, deformed, params);
  const detail::TriangleBvh bvh(deformed);
  SupportMesh support = mould.support();
  std::vector<Vec3> dirs = mouldDirections(mould);
  const double minFraction = 1.0 / (2.0 * params.maxStages);
  DeformationSequence sequence;
  std::vector<int> folds;
  StallWatch watch(params.stallStages);
  for (int k = 0;; ++k) {
    reportProgress(params.progress, static_cast<double>(k) / params.maxStages);
    DeformationStage stage{makeStage(support, dirs, mould.resolution(), deformed, bvh, params,
                                     static_cast<double>(k) / params.maxStages),
                           1.0,
                           {}};
    Crossing crossing = findCrossing(stage.ddf, params.crustSafety);
    if (k == 0) sequence.crossingFaces = crossing.faces;
    const double t = std::min(1.0, params.crustSafety * crossing.minRatio);
    sequence.stalled =
        watch.stalled(k, crossing.faces.size(), k > 0 ? sequence.stages.back().fraction : 1.0);
    const bool last =
        crossing.faces.empty() || k + 1 == params.maxStages || t >= 1.0 || sequence.stalled;
    stage.crossingFaces = std::move(crossing.faces);
    if (last) {
      sequence.unresolvedFaces = mergeSorted(stage.crossingFaces, folds);
      sequence.stages.push_back(std::move(stage));
      break;
    }
    stage.fraction = std::max(t, minFraction);
    folds = mergeSorted(std::move(folds), advanceSupport(stage.ddf, stage.fraction, support));
    dirs = pseudoNormals(support).normals;
    sequence.stages.push_back(std::move(stage));
  }
  sequence.deformedPoints =
      computeDeformedPoints(sequence.stages.back().ddf, sequence.missingPoints);
  reportProgress(params.progress, 1.0);
  return sequence;
}

namespace {

// Start times tau_k of the stages: tau_0 = 0, tau_{k+1} = tau_k + t_k (1 - tau_k).
std::vector<double> stageTimes(const DeformationSequence& sequence) {
  std::vector<double> taus{0.0};
  for (std::size_t s = 0; s + 1 < sequence.stages.size(); ++s)
    taus.push_back(taus.back() + sequence.stages[s].fraction * (1.0 - taus.back()));
  return taus;
}

// Position at time @p lambda of raster point (i, k) of face f on the path through the stage
// supports; the last segment is g + w h v of the last stage, so one stage is exactly
// F(lambda) = g + lambda h v.
Vec3 morphPoint(const DeformationSequence& sequence, const std::vector<double>& taus, int f, int i,
                int k, double lambda) {
  const DisplacementField& last = sequence.stages.back().ddf;
  const float h = last.height(f, i, k);
  if (!std::isfinite(h)) return Vec3::Constant(kNaN);
  const Vec3 bary = last.rasterBary(i, k);
  const std::size_t stages = taus.size();
  std::size_t s = 0;
  while (s + 1 < stages && lambda >= taus[s + 1]) ++s;
  const double span = (s + 1 < stages ? taus[s + 1] : 1.0) - taus[s];
  const double w = (lambda - taus[s]) / span;
  const Vec3 a = sequence.stages[s].ddf.basePoint(f, bary);
  if (s + 1 == stages) return a + (w * static_cast<double>(h)) * last.vectorAt(f, bary);
  return a + w * (sequence.stages[s + 1].ddf.basePoint(f, bary) - a);
}

std::vector<Vec3> morphWith(const DeformationSequence& sequence,
                            const std::function<double(std::size_t)>& lambdaOf) {
  if (sequence.stages.empty()) return {};
  const DisplacementField& first = sequence.stages.front().ddf;
  const std::size_t per = first.pointsPerFace();
  const int n = first.raster().steps();
  const std::vector<double> taus = stageTimes(sequence);
  std::vector<Vec3> out(static_cast<std::size_t>(first.faceCount()) * per);
  tbb::parallel_for(tbb::blocked_range<int>(0, first.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f)
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i + k <= n; ++i) {
          const std::size_t index = f * per + first.raster().index(i, k);
          out[index] = morphPoint(sequence, taus, f, i, k, lambdaOf(index));
        }
  });
  return out;
}

}  // namespace

std::vector<Vec3> morphPositions(const DeformationSequence& sequence, double lambda) {
  return morphWith(sequence, [lambda](std::size_t) { return lambda; });
}

std::vector<Vec3> morphPositions(const DeformationSequence& sequence,
                                 std::span<const float> lambdas) {
  const std::size_t expected =
      sequence.stages.empty() ? 0 : sequence.stages.front().ddf.allHeights().size();
  if (lambdas.size() != expected)
    throw InvalidInput("morphPositions: " + std::to_string(lambdas.size()) + " lambdas for " +
                       std::to_string(expected) + " raster point copies");
  return morphWith(sequence, [lambdas](std::size_t i) { return static_cast<double>(lambdas[i]); });
}

}  // namespace ddfcam::ddf
