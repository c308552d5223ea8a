// SPDX-License-Identifier: MIT
// ddfcam: support reduction by constrained edge contraction (dissertation sec. 6.1-6.2).
#include "support_reducer.h"

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_reduction.h>
#include <ddfcam/ddf/v_shooting.h>
#include <ddfcam/ddf/vector_lengths.h>
#include <ddfcam/error.h>
#include <ddfcam/log.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>

namespace ddfcam::ddf {
namespace {

void checkParams(const SupportMesh& input, std::span<const Vec3> vectors,
                 std::span<const int> labels, const SupportReductionParams& p) {
  const auto fail = [](const std::string& what) {
    throw InvalidInput("support reduction: " + what);
  };
  if (vectors.size() != input.n_vertices())
    fail(std::to_string(vectors.size()) + " vectors for " + std::to_string(input.n_vertices()) +
         " vertices");
  if (!labels.empty() && labels.size() != input.n_faces())
    fail(std::to_string(labels.size()) + " labels for " + std::to_string(input.n_faces()) +
         " faces");
  if (p.resolution < 2) fail("resolution must be >= 2, got " + std::to_string(p.resolution));
  if (!(p.maxAngleDeg > 0.0 && p.maxAngleDeg <= 180.0))
    fail("maxAngleDeg must be in (0, 180], got " + std::to_string(p.maxAngleDeg));
  if (!(p.featureAngleDeg > 0.0 && p.featureAngleDeg <= 180.0))
    fail("featureAngleDeg must be in (0, 180], got " + std::to_string(p.featureAngleDeg));
  if (!(p.maxEdgeMm >= 0.0) || !(p.maxVectorLengthMm >= 0.0) || p.maxSweeps < 0)
    fail("maxEdgeMm, maxVectorLengthMm and maxSweeps must be >= 0");
  for (std::size_t v = 0; v < vectors.size(); ++v)
    if (!vectors[v].allFinite() || vectors[v].squaredNorm() == 0.0)
      fail("vector of vertex " + std::to_string(v) + " is zero or not finite");
}

}  // namespace

namespace detail {

SupportReducer::SupportReducer(const SupportMesh& input, std::span<const Vec3> vectors,
                               std::span<const int> labels, const SupportReductionParams& params)
    : params_(params), mesh_(input), labels_(labels.begin(), labels.end()) {
  mesh_.request_vertex_status();
  mesh_.request_edge_status();
  mesh_.request_halfedge_status();
  mesh_.request_face_status();
  if (labels_.empty()) labels_.assign(mesh_.n_faces(), -1);
  kept_ = keptVertices(mesh_, labels, params.featureAngleDeg);
  items_ = ReductionItems::fromMesh(mesh_);
  minCosine_ = std::cos(params.maxAngleDeg * M_PI / 180.0);
  faceVersion_.assign(mesh_.n_faces(), 0);
  edgeRefusedAt_.assign(mesh_.n_edges(), -1);
  hitCount_.assign(items_.size(), 0);
  delta_.assign(items_.size(), 0);
  itemStamp_.assign(items_.size(), 0);
  vertexStamp_.assign(items_.points.size(), 0);
  hasLabels_ = !labels.empty();
  report_.inputFaces = static_cast<int>(mesh_.n_faces());
  initialVectors(vectors);
  initialItems();
}

// The start must satisfy what every contraction keeps: with unique projection required, the
// input's directions get the sec. 4.4 lengths (h0 >= 1, non-adjacent crusts disjoint).
void SupportReducer::initialVectors(std::span<const Vec3> vectors) {
  vectors_.assign(vectors.begin(), vectors.end());
  if (!params_.requireUniqueProjection) return;
  DisplacementField field(mesh_, vectors_, 2);
  VectorLengthParams lengths;
  lengths.maxLengthMm = params_.maxVectorLengthMm;
  // A margin of 25 % in h0 leaves room for the contractions around every vertex (a face at
  // h0 = 1 exactly refuses any change that lowers it).
  lengths.safety = kInitialSafety;
  const VectorLengthReport report = chooseVectorLengths(field, lengths);
  if (report.remainingConflicts > 0)
    log(LogLevel::Warning, "support reduction: " + std::to_string(report.remainingConflicts) +
                               " crossing crust pairs of the input support remain");
  vectors_ = field.vectors();
}

FaceCorners SupportReducer::corners(int face) const {
  FaceCorners c;
  const auto ids = faceVertexIds(mesh_, face);
  for (int k = 0; k < 3; ++k) c.p[k] = toEigen(mesh_.point(SupportMesh::VertexHandle(ids[k])));
  for (int k = 0; k < 3; ++k) c.v[k] = vectors_[ids[k]];
  return c;
}

// At the start the support is the input: every ray hits its own face's item at h = 0 (nothing
// is nearer), and the rays through a shared edge or vertex hit the items around it as well.
// That is what V-shooting each face at its own and its neighbours' items gives, without the
// shooting (ties at h = 0 go to the own item).
void SupportReducer::initialItems() {
  const int faces = static_cast<int>(mesh_.n_faces());
  faceItems_.assign(faces, {});
  tbb::parallel_for(0, faces, [&](int f) {
    FaceItems& fi = faceItems_[f];
    for (const auto vh : mesh_.fv_range(SupportMesh::FaceHandle(f)))
      for (const auto fh : mesh_.vf_range(vh)) fi.items.push_back(fh.idx());
    std::sort(fi.items.begin(), fi.items.end());
    fi.items.erase(std::unique(fi.items.begin(), fi.items.end()), fi.items.end());
  });
  // Constraint (a) counts, per item, the faces whose item set holds it.
  for (const FaceItems& fi : faceItems_)
    for (int t : fi.items) ++hitCount_[t];
}

void SupportReducer::rebuildHash() {
  double extent = 0.0;
  int faces = 0;
  for (const auto fh : mesh_.faces()) {
    extent += crustBox(corners(fh.idx())).sizes().maxCoeff();
    ++faces;
  }
  hash_ = CrustBoxHash(faces > 0 && extent > 0.0 ? extent / faces : 1.0);
  for (const auto fh : mesh_.faces()) hash_.set(fh.idx(), crustBox(corners(fh.idx())));
}

void SupportReducer::count(Refusal r) {
  switch (r) {
    case Refusal::Boundary:
      ++report_.rejectedBoundary;
      break;
    case Refusal::Critical:
      ++report_.rejectedCritical;
      break;
    case Refusal::EdgeLength:
      ++report_.rejectedEdgeLength;
      break;
    case Refusal::UniqueProjection:
      ++report_.rejectedUniqueProjection;
      break;
    case Refusal::RayCoverage:
      ++report_.rejectedRayCoverage;
      break;
    case Refusal::Angle:
      ++report_.rejectedAngle;
      break;
    case Refusal::InputCoverage:
      ++report_.rejectedInputCoverage;
      break;
    case Refusal::Containment:
      ++report_.rejectedContainment;
      break;
    default:
      break;
  }
}

// Shortest feasible edge first (sec. 6.1): edges touched by a contraction wait for the next
// sweep, which sorts what is left again.
bool SupportReducer::sweep() {
  std::vector<std::pair<double, int>> order;
  for (const auto eh : mesh_.edges()) {
    const auto heh = mesh_.halfedge_handle(eh, 0);
    const double len =
        (mesh_.point(mesh_.to_vertex_handle(heh)) - mesh_.point(mesh_.from_vertex_handle(heh)))
            .norm();
    order.emplace_back(len, eh.idx());
  }
  std::sort(order.begin(), order.end());
  edgeModified_.assign(mesh_.n_edges(), 0);
  rebuildHash();
  const int before = report_.contractions;
  for (const auto& [len, e] : order) {
    const SupportMesh::EdgeHandle eh(e);
    if (mesh_.status(eh).deleted() || edgeModified_[e]) continue;
    if (++attempts_ % 256 == 0)
      reportProgress(params_.progress,
                     std::min(0.99, 1.0 - double(mesh_.n_faces() - 2 * report_.contractions) /
                                              std::max(1, report_.inputFaces)));
    const Refusal r = attempt(eh);
    count(r);
    if (r != Refusal::None && r != Refusal::Skipped) edgeRefusedAt_[e] = clock_;
  }
  return report_.contractions > before;
}

SupportReductionResult SupportReducer::run() {
  reportProgress(params_.progress, 0.0);
  while (report_.sweeps < params_.maxSweeps) {
    ++report_.sweeps;
    if (!sweep()) break;
  }
  SupportReductionResult out = result();
  reportProgress(params_.progress, 1.0);
  return out;
}

// The surviving faces and the vertices they use, in their old order, as a fresh mesh.
SupportReductionResult SupportReducer::result() const {
  SupportReductionResult out;
  std::vector<int> compact(mesh_.n_vertices(), -1);
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  for (const auto fh : mesh_.faces()) {
    std::array<int, 3> t = faceVertexIds(mesh_, fh.idx());
    for (int& v : t) {
      if (compact[v] < 0) {
        compact[v] = static_cast<int>(points.size());
        points.push_back(toEigen(mesh_.point(SupportMesh::VertexHandle(v))));
        out.vectors.push_back(vectors_[v]);
      }
      v = compact[v];
    }
    triangles.push_back(t);
    if (hasLabels_) out.faceLabels.push_back(labels_[fh.idx()]);
  }
  out.support = makeSupportMesh(points, triangles);
  out.report = report_;
  out.report.supportFaces = static_cast<int>(triangles.size());
  return out;
}

}  // namespace detail

SupportReductionResult reduceSupport(const SupportMesh& input, std::span<const Vec3> vectors,
                                     std::span<const int> inputLabels,
                                     const SupportReductionParams& params) {
  checkParams(input, vectors, inputLabels, params);
  // The time includes the set-up (the start's vector lengths and item buffers), a part of the
  // cost a user waits for.
  const auto start = std::chrono::steady_clock::now();
  detail::SupportReducer reducer(input, vectors, inputLabels, params);
  SupportReductionResult out = reducer.run();
  out.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace ddfcam::ddf
