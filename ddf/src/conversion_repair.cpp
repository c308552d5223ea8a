// SPDX-License-Identifier: MIT
// ddfcam: validation of a converted DDF and the repairs the conversion can make.
#include "conversion_repair.h"

#include <ddfcam/ddf/crust.h>

#include <algorithm>
#include <map>
#include <utility>

namespace ddfcam::ddf::detail {
namespace {

/// Gives every class of coincident vertices (within the validation tolerance) one vector:
/// the normalised sum of the unit directions, scaled to the shortest length of the class.
/// Returns the number of vertices whose vector changed.
int unifyCoincidentVectors(DisplacementField& ddf, double toleranceMm) {
  const auto classes = coincidentVertexClasses(ddf, toleranceMm);
  std::map<int, std::pair<Vec3, double>> shared;  // class -> (direction sum, shortest length)
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    auto [it, fresh] = shared.try_emplace(classes[v], Vec3::Zero(), ddf.vector(v).norm());
    it->second.first += ddf.vector(v).normalized();
    it->second.second = std::min(it->second.second, ddf.vector(v).norm());
  }
  std::vector<Vec3> vectors = ddf.vectors();
  int changed = 0;
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    const auto& [sum, length] = shared[classes[v]];
    const Vec3 unified = length * sum.normalized();
    if (unified.isApprox(vectors[v], 1e-12)) continue;  // alone at its position, or agrees
    vectors[v] = unified;
    ++changed;
  }
  ddf.setVectors(std::move(vectors));
  return changed;
}

bool failsCrusts(const ValidationReport& report) {
  return report.count(3) > 0;
}

/// Chooses the lengths again with a limit of half the longest current vector.
void chooseShorterLengths(ConversionResult& result, const ConversionParams& params) {
  double longest = 0.0;
  for (const Vec3& v : result.ddf.vectors()) longest = std::max(longest, v.norm());
  VectorLengthParams lengths = lengthParams(params);
  lengths.maxLengthMm = 0.5 * longest;
  lengths.maxIterations = 2 * params.lengths.maxIterations;
  if (params.progress) lengths.progress = [&](double) { return params.progress(0.6); };
  result.lengths = chooseVectorLengths(result.ddf, lengths);
  ++result.report.lengthRetries;
}

}  // namespace

VectorLengthParams lengthParams(const ConversionParams& params) {
  VectorLengthParams lengths = params.lengths;
  if (lengths.coincidentToleranceMm == 0.0)
    lengths.coincidentToleranceMm = params.validation.coincidentToleranceMm;
  lengths.progress = nullptr;
  return lengths;
}

int countBoundaryLoops(const SupportMesh& mesh) {
  std::vector<char> seen(mesh.n_halfedges(), 0);
  int loops = 0;
  for (const auto h : mesh.halfedges()) {
    if (!mesh.is_boundary(h) || seen[h.idx()]) continue;
    ++loops;
    for (auto g = h; !seen[g.idx()]; g = mesh.next_halfedge_handle(g)) seen[g.idx()] = 1;
  }
  return loops;
}

int countNonManifoldEdges(const std::vector<std::array<int, 3>>& triangles) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  return static_cast<int>(
      std::count_if(uses.begin(), uses.end(), [](const auto& e) { return e.second > 2; }));
}

void validateAndRepair(ConversionResult& result, const ConversionParams& params) {
  constexpr int kMaxLengthRetries = 3;
  ConversionReport& report = result.report;
  report.validated = true;
  report.validation = validate(result.ddf, params.validation);
  if (report.validation.count(2) > 0) {
    report.unifiedVectors =
        unifyCoincidentVectors(result.ddf, params.validation.coincidentToleranceMm);
    report.validation = validate(result.ddf, params.validation);
  }
  while (failsCrusts(report.validation) && report.lengthRetries < kMaxLengthRetries) {
    chooseShorterLengths(result, params);
    if (report.unifiedVectors > 0)
      unifyCoincidentVectors(result.ddf, params.validation.coincidentToleranceMm);
    report.validation = validate(result.ddf, params.validation);
  }
}

}  // namespace ddfcam::ddf::detail
