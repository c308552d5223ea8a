// SPDX-License-Identifier: MIT
// ddfcam: mesh -> DDF baseline conversion (weld, manifold support, pseudo-normals, lengths).
#include "conversion_repair.h"

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/error.h>
#include <ddfcam/log.h>

#include <Eigen/Geometry>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
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

void checkInput(const TriangleMesh& mesh, const ConversionParams& params) {
  if (params.resolution < 2)
    throw InvalidInput("mesh conversion: resolution must be >= 2, got " +
                       std::to_string(params.resolution));
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

Candidates weldedCandidates(const TriangleMesh& mesh, const ConversionParams& params,
                            ConversionReport& report) {
  Candidates out;
  out.rep = weldVertices(mesh.vertices, weldTolerance(mesh, params));
  for (std::size_t i = 0; i < out.rep.size(); ++i) report.weldedVertices += out.rep[i] != int(i);
  std::set<std::array<int, 3>> seen;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const std::array<int, 3> w = {out.rep[t[0]], out.rep[t[1]], out.rep[t[2]]};
    if (degenerate(w, mesh.vertices)) {
      ++report.degenerateFaces;
      continue;
    }
    if (!seen.insert(sortedCorners(w)).second) {
      ++report.duplicateFaces;
      continue;
    }
    out.triangles.push_back(w);
    out.source.push_back(static_cast<int>(f));
  }
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

// Heights from the input mesh along the stubbles (the depth buffer's fill mode): the support is
// the mesh, so heights come out ~0, but the input's dropped triangles and any later change of
// support are honoured the same way. Stubbles that miss keep h = 0, i.e. the support itself.
void fillFromInput(const TriangleMesh& mesh, const ConversionParams& params,
                   ConversionResult& result) {
  const CrustHash hash(result.ddf);
  FillParams fill;
  if (params.progress) fill.progress = [&](double x) { return params.progress(0.9 + 0.1 * x); };
  const FillReport report = fillFromMesh(result.ddf, hash, mesh, fill);
  result.filledPoints = report.filled;
  result.unfilledPoints = report.missing;
  result.report.unfilledPoints = report.missing;
}

/// Vector lengths (sec. 4.4), then the check of the constraints and its repairs.
void chooseLengthsAndCheck(const ConversionParams& params, ConversionResult& result) {
  VectorLengthParams lengths = detail::lengthParams(params);
  if (params.progress) lengths.progress = [&](double x) { return params.progress(0.2 + 0.7 * x); };
  result.lengths = chooseVectorLengths(result.ddf, lengths);
  if (params.validateResult) detail::validateAndRepair(result, params);
  ConversionReport& report = result.report;
  report.shortenedVectors = result.lengths.shortenedVertices;
  if (report.validated && !report.valid())
    log(LogLevel::Warning, "mesh conversion: " + conversionVerdict(report));
}

}  // namespace

ConversionResult convertMeshToDdf(const TriangleMesh& mesh, const ConversionParams& params) {
  checkInput(mesh, params);
  ConversionResult result;
  result.report.inputVertices = static_cast<int>(mesh.vertices.size());
  result.report.inputTriangles = static_cast<int>(mesh.triangles.size());
  reportProgress(params.progress, 0.0);
  SupportMesh support = buildSupport(mesh, params, result);
  reportProgress(params.progress, 0.1);
  auto normals = pseudoNormals(support, params.normals);
  result.repairedVertices = std::move(normals.repairedVertices);
  result.infeasibleVertices = std::move(normals.infeasibleVertices);
  result.report.repairedDirections = static_cast<int>(result.repairedVertices.size());
  result.report.infeasibleVertices = static_cast<int>(result.infeasibleVertices.size());
  if (!result.infeasibleVertices.empty())
    log(LogLevel::Warning, "mesh conversion: " + std::to_string(result.infeasibleVertices.size()) +
                               " vertices have no front-facing direction (first: vertex " +
                               std::to_string(result.infeasibleVertices.front()) + ")");
  result.report.boundaryLoops = detail::countBoundaryLoops(support);
  result.ddf =
      DisplacementField(std::move(support), std::move(normals.normals), params.resolution, 0.0f);
  result.report.supportVertices = result.ddf.vertexCount();
  result.report.supportFaces = result.ddf.faceCount();
  reportProgress(params.progress, 0.2);
  if (!params.chooseLengths) {
    reportProgress(params.progress, 1.0);
    return result;
  }
  chooseLengthsAndCheck(params, result);
  fillFromInput(mesh, params, result);
  reportProgress(params.progress, 1.0);
  return result;
}

}  // namespace ddfcam::ddf
