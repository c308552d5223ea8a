// SPDX-License-Identifier: MIT
// ddfcam: mesh -> DDF baseline conversion (weld, manifold support, pseudo-normals, lengths).
#include "conversion_accuracy.h"
#include "conversion_repair.h"
#include "conversion_resolution.h"
#include "conversion_tolerance.h"

#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/error.h>
#include <ddfcam/log.h>

#include <Eigen/Geometry>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>

namespace ddfcam::ddf {
namespace {

struct CellHash {
  std::size_t operator()(const std::array<long long, 3>& c) const {
    return static_cast<std::size_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
  }
};

/// Index of the representative (first vertex within @p tol) of every input vertex.
std::vector<int> weldVertices(const std::vector<Vec3>& points, double tol) {
  std::unordered_map<std::array<long long, 3>, std::vector<int>, CellHash> grid;
  std::vector<int> rep(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    const std::array<long long, 3> c = {static_cast<long long>(std::floor(p.x() / tol)),
                                        static_cast<long long>(std::floor(p.y() / tol)),
                                        static_cast<long long>(std::floor(p.z() / tol))};
    int found = -1;
    for (int d = 0; d < 27 && found < 0; ++d) {
      const auto it = grid.find({c[0] + d % 3 - 1, c[1] + d / 3 % 3 - 1, c[2] + d / 9 - 1});
      if (it == grid.end()) continue;
      for (int j : it->second)
        if ((points[j] - p).norm() <= tol) {
          found = j;
          break;
        }
    }
    rep[i] = found >= 0 ? found : static_cast<int>(i);
    if (found < 0) grid[c].push_back(static_cast<int>(i));
  }
  return rep;
}

bool degenerate(const std::array<int, 3>& t, const std::vector<Vec3>& p) {
  if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return true;
  const Vec3 e1 = p[t[1]] - p[t[0]], e2 = p[t[2]] - p[t[0]];
  const double longest = std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()});
  return !(e1.cross(e2).norm() > 1e-12 * longest);
}

/// Which candidate triangles OpenMesh accepts, added in order (its own error stream muted).
std::vector<char> manifoldAcceptance(const std::vector<Vec3>& points,
                                     const std::vector<std::array<int, 3>>& triangles) {
  SupportMesh scratch;
  std::vector<SupportMesh::VertexHandle> vh;
  vh.reserve(points.size());
  for (const Vec3& p : points) vh.push_back(scratch.add_vertex(toOpenMesh(p)));
  const bool wasEnabled = omerr().is_enabled();
  omerr().disable();
  std::vector<char> accepted(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    accepted[i] = scratch.add_face(vh[t[0]], vh[t[1]], vh[t[2]]).is_valid();
  }
  if (wasEnabled) omerr().enable();
  return accepted;
}

/// A non-negative finite length parameter, or InvalidInput naming it.
void checkLength(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value))
    throw InvalidInput(std::string("mesh conversion: ") + name + " must be >= 0 mm, got " +
                       std::to_string(value));
}

void checkInput(const TriangleMesh& mesh, const ConversionParams& params) {
  if (params.resolution < 2)
    throw InvalidInput("mesh conversion: resolution must be >= 2, got " +
                       std::to_string(params.resolution));
  checkLength(params.toleranceMm, "the tolerance");
  checkLength(params.rasterSpacingMm, "the raster spacing");
  checkLength(params.stockMm, "the stock allowance");
  if (!params.inputLabels.empty() && params.inputLabels.size() != mesh.triangles.size())
    throw InvalidInput("mesh conversion: " + std::to_string(params.inputLabels.size()) +
                       " input labels for " + std::to_string(mesh.triangles.size()) +
                       " triangles (one label per triangle, or none)");
  const int n = static_cast<int>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int v : mesh.triangles[f])
      if (v < 0 || v >= n)
        throw InvalidInput("mesh conversion: triangle " + std::to_string(f) + " refers to vertex " +
                           std::to_string(v) + " of " + std::to_string(n));
}

/// Welded, non-degenerate, distinct triangles and the input index of each.
struct Candidates {
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> source;
  std::vector<int> rep;  ///< per input vertex, its welded representative
};

double weldTolerance(const TriangleMesh& mesh, const ConversionParams& params) {
  if (params.weldToleranceMm > 0.0) return params.weldToleranceMm;
  const auto box = mesh.bounds();
  const double diag = (box[1] - box[0]).norm();
  return std::max({1e-9 * diag, params.validation.coincidentToleranceMm, 1e-300});
}

/// The corners of @p t in ascending order: equal for repeats in any order or orientation.
std::array<int, 3> sortedCorners(std::array<int, 3> t) {
  std::sort(t.begin(), t.end());
  return t;
}

/// Whether the corners of @p t run in ascending cyclic order (its orientation against the
/// sorted corners): two triangles on the same corners face opposite ways when this differs.
bool ascendingOrientation(const std::array<int, 3>& t) {
  const int first = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
  return t[(first + 1) % 3] < t[(first + 2) % 3];
}

/// Per undirected edge, the number of triangles of @p triangles on it whose @p keep is set.
std::map<std::pair<int, int>, int> edgeFaceCounts(const std::vector<std::array<int, 3>>& triangles,
                                                  const std::vector<char>& keep) {
  std::map<std::pair<int, int>, int> count;
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int k = 0; keep[i] && k < 3; ++k) {
      const int a = triangles[i][k], b = triangles[i][(k + 1) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  return count;
}

/// Removes repeated triangles from @p out. A copy facing the same way as a kept one is a
/// duplicate. A copy facing the other way makes a back-to-back pair, a zero-thickness fin or
/// membrane as scanner zipper meshes have. Where the rest of the mesh has exactly one face on
/// an edge of the pair, the surface needs one of them there and the first is kept; where it
/// has none (the fin's free edge) or two or more on every edge, and two or more on at least
/// one, both faces go: keeping one would leave three faces on an edge, so the manifold check
/// would drop it or a neighbour and open a hole in the surface around it.
void removeRepeats(Candidates& out, ConversionReport& report) {
  std::map<std::array<int, 3>, std::pair<int, bool>> firstOf;  // sorted corners -> (index, facing)
  std::vector<char> keep(out.triangles.size(), 1);
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i < out.triangles.size(); ++i) {
    const bool facing = ascendingOrientation(out.triangles[i]);
    const auto [it, fresh] =
        firstOf.try_emplace(sortedCorners(out.triangles[i]), static_cast<int>(i), facing);
    if (fresh) continue;
    if (it->second.second != facing && it->second.first >= 0) {
      pairs.emplace_back(it->second.first, static_cast<int>(i));
      it->second.first = -1;  // a third copy is a duplicate of one of the pair
    } else {
      keep[i] = 0, ++report.duplicateFaces;
    }
  }
  const auto count = edgeFaceCounts(out.triangles, keep);
  for (const auto& [first, second] : pairs) {
    bool needed = false, extra = false;
    for (int k = 0; k < 3; ++k) {
      const int a = out.triangles[first][k], b = out.triangles[first][(k + 1) % 3];
      const int others = count.at({std::min(a, b), std::max(a, b)}) - 2;
      needed |= others == 1;
      extra |= others >= 2;
    }
    keep[second] = 0;
    if (extra && !needed)
      keep[first] = 0, report.backToBackFaces += 2;
    else
      ++report.duplicateFaces;
  }
  std::size_t n = 0;
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) out.triangles[n] = out.triangles[i], out.source[n++] = out.source[i];
  out.triangles.resize(n);
  out.source.resize(n);
}

Candidates weldedCandidates(const TriangleMesh& mesh, const ConversionParams& params,
                            ConversionReport& report) {
  Candidates out;
  out.rep = weldVertices(mesh.vertices, weldTolerance(mesh, params));
  for (std::size_t i = 0; i < out.rep.size(); ++i) report.weldedVertices += out.rep[i] != int(i);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const std::array<int, 3> w = {out.rep[t[0]], out.rep[t[1]], out.rep[t[2]]};
    if (degenerate(w, mesh.vertices)) {
      ++report.degenerateFaces;
      continue;
    }
    out.triangles.push_back(w);
    out.source.push_back(static_cast<int>(f));
  }
  removeRepeats(out, report);
  report.nonManifoldEdges = detail::countNonManifoldEdges(out.triangles);
  return out;
}

/// Input vertices that are their own weld representative and no triangle refers to.
int countUnusedVertices(const TriangleMesh& mesh, const std::vector<int>& rep) {
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int v : t) used[rep[v]] = 1;
  int unused = 0;
  for (std::size_t v = 0; v < rep.size(); ++v) unused += rep[v] == int(v) && !used[v];
  return unused;
}

/// Drops the candidates OpenMesh rejects and builds the support from the used vertices only.
SupportMesh buildSupport(const TriangleMesh& mesh, const ConversionParams& params,
                         ConversionResult& result) {
  ConversionReport& report = result.report;
  const Candidates cand = weldedCandidates(mesh, params, report);
  const auto accepted = manifoldAcceptance(mesh.vertices, cand.triangles);
  std::vector<int> compact(mesh.vertices.size(), -1);
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  int firstDropped = -1;
  for (std::size_t i = 0; i < cand.triangles.size(); ++i) {
    if (!accepted[i]) {
      if (report.droppedFaces++ == 0) firstDropped = cand.source[i];
      continue;
    }
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) {
      const int v = cand.triangles[i][k];
      if (compact[v] < 0)
        compact[v] = static_cast<int>(points.size()), points.push_back(mesh.vertices[v]);
      t[k] = compact[v];
    }
    triangles.push_back(t);
    result.sourceTriangle.push_back(cand.source[i]);
  }
  report.unusedVertices = countUnusedVertices(mesh, cand.rep);
  report.orphanedVertices = static_cast<int>(mesh.vertices.size()) - report.weldedVertices -
                            report.unusedVertices - static_cast<int>(points.size());
  if (report.droppedFaces > 0)
    log(LogLevel::Warning, "mesh conversion: dropped " + std::to_string(report.droppedFaces) +
                               " triangles that make the support non-manifold or flip its "
                               "orientation (first: input triangle " +
                               std::to_string(firstDropped) + ")");
  if (triangles.empty()) throw InvalidInput("mesh conversion: no usable triangle in the mesh");
  return makeSupportMesh(points, triangles);
}

/// Vector lengths (sec. 4.4), then the check of the constraints and its repairs. A reduced
/// support keeps the reduction's vectors: each contraction chose them (h0 >= 1) and checked
/// with them that every stubble hits the input, which a fresh choice of lengths could undo.
void chooseLengthsAndCheck(const ConversionParams& params, ConversionResult& result) {
  if (params.support != SupportChoice::Reduced) {
    VectorLengthParams lengths = detail::lengthParams(params);
    lengths.progress = detail::progressShare(params.progress, 0.4, 0.6);
    result.lengths = chooseVectorLengths(result.ddf, lengths);
  }
  if (params.validateResult) detail::validateAndRepair(result, params);
  ConversionReport& report = result.report;
  report.shortenedVectors = result.lengths.shortenedVertices;
  if (report.validated && !report.valid())
    log(LogLevel::Warning, "mesh conversion: " + conversionVerdict(report));
}

/// Per support face, the label of its input triangle (empty without labels).
std::vector<int> supportFaceLabels(const ConversionParams& params,
                                   const std::vector<int>& sourceTriangle) {
  std::vector<int> labels;
  if (params.inputLabels.empty()) return labels;
  labels.reserve(sourceTriangle.size());
  for (int t : sourceTriangle) labels.push_back(params.inputLabels[t]);
  return labels;
}

/// The support, vectors and labels the DDF is built from: as given, or reduced (sec. 6.1-6.2).
struct SupportParts {
  SupportMesh support;
  std::vector<Vec3> vectors;
  std::vector<int> labels;
};

void reduce(SupportParts& parts, const ConversionParams& params, ConversionResult& result) {
  SupportReductionParams reduction = params.reduction;
  reduction.resolution = params.resolution;
  reduction.progress = detail::progressShare(params.progress, 0.1, 0.4);
  SupportReductionResult reduced =
      reduceSupport(parts.support, parts.vectors, parts.labels, reduction);
  parts.support = std::move(reduced.support);
  parts.vectors = std::move(reduced.vectors);
  if (!parts.labels.empty()) parts.labels = std::move(reduced.faceLabels);
  result.reduction = reduced.report;
  result.report.reducedSupport = true;
  result.report.reduction = reduced.report;
  // Those name faces and vertices of the unreduced support; the report keeps their counts.
  result.sourceTriangle.clear();
  result.repairedVertices.clear();
  result.infeasibleVertices.clear();
}

/// The first raster resolution: the spacing rule's when a spacing is set, else as given.
int firstResolution(const SupportMesh& support, const ConversionParams& params) {
  if (!(params.rasterSpacingMm > 0.0)) return params.resolution;
  return detail::resolutionForSpacing(detail::longestSupportEdgeMm(support),
                                      static_cast<int>(support.n_faces()), params.rasterSpacingMm,
                                      params.maxRasterPoints);
}

/// Pseudo-normal directions of @p support, repaired for constraint 1, with their counts.
std::vector<Vec3> supportDirections(const SupportMesh& support, const ConversionParams& params,
                                    ConversionResult& result) {
  auto normals = pseudoNormals(support, params.normals);
  result.repairedVertices = std::move(normals.repairedVertices);
  result.infeasibleVertices = std::move(normals.infeasibleVertices);
  result.report.repairedDirections = static_cast<int>(result.repairedVertices.size());
  result.report.infeasibleVertices = static_cast<int>(result.infeasibleVertices.size());
  if (!result.infeasibleVertices.empty())
    log(LogLevel::Warning, "mesh conversion: " + std::to_string(result.infeasibleVertices.size()) +
                               " vertices have no front-facing direction (first: vertex " +
                               std::to_string(result.infeasibleVertices.front()) + ")");
  return std::move(normals.normals);
}

/// The copies of the result's summary its report carries for callers that only get the report.
void copySummary(ConversionResult& result) {
  result.report.resolution = result.ddf.resolution();
  result.report.rasterSpacingMm =
      detail::longestSupportEdgeMm(result.ddf.support()) / (result.ddf.resolution() - 1);
  result.report.accuracy = result.accuracy;
  result.report.stock = result.stock;
}

/// One conversion; @p warnOnMiss logs a tolerance not met (see fillHeights).
ConversionResult convertOnce(const TriangleMesh& mesh, const ConversionParams& params,
                             bool warnOnMiss) {
  checkInput(mesh, params);
  ConversionResult result;
  result.report.inputVertices = static_cast<int>(mesh.vertices.size());
  result.report.inputTriangles = static_cast<int>(mesh.triangles.size());
  reportProgress(params.progress, 0.0);
  SupportParts parts;
  parts.support = buildSupport(mesh, params, result);
  reportProgress(params.progress, 0.1);
  parts.vectors = supportDirections(parts.support, params, result);
  result.report.boundaryLoops = detail::countBoundaryLoops(parts.support);
  parts.labels = supportFaceLabels(params, result.sourceTriangle);
  const std::vector<int> keptTriangles = result.sourceTriangle;
  if (params.support == SupportChoice::Reduced) reduce(parts, params, result);
  result.supportLabels = parts.labels;
  const int m = firstResolution(parts.support, params);
  result.ddf = DisplacementField(std::move(parts.support), std::move(parts.vectors), m, 0.0f);
  result.report.supportVertices = result.ddf.vertexCount();
  result.report.supportFaces = result.ddf.faceCount();
  reportProgress(params.progress, 0.4);
  if (params.chooseLengths) {
    chooseLengthsAndCheck(params, result);
    detail::fillHeights(mesh, params, keptTriangles, result, warnOnMiss);
  }
  copySummary(result);
  reportProgress(params.progress, 1.0);
  return result;
}

}  // namespace

ConversionResult convertMeshToDdf(const TriangleMesh& mesh, const ConversionParams& params) {
  if (params.support != SupportChoice::Reduced || !(params.toleranceMm > 0.0) ||
      !params.chooseLengths)
    return convertOnce(mesh, params, true);
  checkInput(mesh, params);
  const double spacing =
      params.rasterSpacingMm > 0.0 ? params.rasterSpacingMm : detail::medianEdgeMm(mesh);
  if (!(spacing > 0.0)) return convertOnce(mesh, params, true);
  return detail::convertReducedForTolerance(
      params, spacing, [&](const ConversionParams& p) { return convertOnce(mesh, p, false); });
}

}  // namespace ddfcam::ddf
