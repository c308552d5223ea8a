// SPDX-License-Identifier: MIT
// ddfcam: one tentative edge contraction of the support reduction and its constraints
// (sec. 6.1-6.2).
#include "support_reducer.h"

#include <ddfcam/ddf/v_shooting.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace ddfcam::ddf::detail {

Refusal SupportReducer::attempt(SupportMesh::EdgeHandle eh) {
  const auto heh = mesh_.halfedge_handle(eh, 0);
  const int a = mesh_.from_vertex_handle(heh).idx(), b = mesh_.to_vertex_handle(heh).idx();
  if (kept_[a] || kept_[b] || mesh_.is_boundary(eh)) return Refusal::Boundary;
  Tentative& t = scratch_;
  t.reset();
  t.region = contractionRegion(mesh_, heh);
  if (const long since = edgeRefusedAt_[eh.idx()]; since >= 0 && unchangedSince(t.region, since))
    return Refusal::Skipped;
  if (isCriticalEdge(mesh_, heh)) return Refusal::Critical;
  if (const Refusal r = placeNewVertex(t); r != Refusal::None) return r;
  gatherCandidates(t);
  // A crust that reaches a non-adjacent sheet (a thin part) may fit when shorter: the longest
  // admissible vector is tried first, then half and a quarter of its cap.
  const Vec3 averaged = t.vector;
  Refusal r = Refusal::None;
  for (int attemptNo = 0; attemptNo < kLengthTries; ++attemptNo) {
    t.vector = averaged;
    r = evaluate(t, std::ldexp(1.0, -attemptNo));
    if (r != Refusal::CrustConflict) break;
  }
  if (r == Refusal::None) commit(t);
  return r;
}

// The length of the new vector (cap scaled by @p capScale), the re-assignment of the items
// and the constraints on it, cheapest first.
Refusal SupportReducer::evaluate(Tentative& t, double capScale) {
  if (const Refusal r = chooseVector(t, capScale); r != Refusal::None) return r;
  Refusal r = rasterNewFaces(t);
  if (r == Refusal::None) r = checkInputCoverage(t);
  if (r == Refusal::None && params_.requireContainment && !contained(t)) r = Refusal::Containment;
  if (r == Refusal::None && params_.requireUniqueProjection && !crustsFree(t))
    r = Refusal::CrustConflict;
  if (r != Refusal::None) resetDelta(t);
  return r;
}

bool SupportReducer::unchangedSince(const ContractionRegion& r, long since) const {
  const auto newer = [&](int f) { return faceVersion_[f] > since; };
  return !newer(r.removed[0]) && !newer(r.removed[1]) &&
         std::none_of(r.modified.begin(), r.modified.end(), newer) &&
         std::none_of(r.neighbours.begin(), r.neighbours.end(), newer);
}

// The midpoint, moved along the averaged vector onto the nearest input item of the region
// (sec. 6.1); then the modified faces with the new vertex, refused when one folds over.
Refusal SupportReducer::placeNewVertex(Tentative& t) {
  const ContractionRegion& r = t.region;
  const Vec3 pa = toEigen(mesh_.point(SupportMesh::VertexHandle(r.a)));
  const Vec3 pb = toEigen(mesh_.point(SupportMesh::VertexHandle(r.b)));
  const Vec3 mid = 0.5 * (pa + pb);
  t.vector = 0.5 * (vectors_[r.a] + vectors_[r.b]);
  double best = 1.0 + 1e-12, shift = 0.0;
  const auto shootAt = [&](int f) {
    for (int item : faceItems_[f].items) {
      const auto shot = vShootLine(mid, t.vector, items_.corner(item, 0), items_.corner(item, 1),
                                   items_.corner(item, 2));
      if (shot && shot->lambda.minCoeff() >= -1e-9 && std::abs(shot->h) < best)
        best = std::abs(shot->h), shift = shot->h;
    }
  };
  shootAt(r.removed[0]), shootAt(r.removed[1]);
  for (int f : r.modified) shootAt(f);
  t.point = mid + shift * t.vector;
  // The shot can fold a face where the input is rough; the plain midpoint may not.
  if (!buildFaces(t)) {
    if (shift == 0.0) return Refusal::Critical;
    t.point = mid;
    if (!buildFaces(t)) return Refusal::Critical;
  }
  return checkEdgeLengths(t);
}

Refusal SupportReducer::checkEdgeLengths(const Tentative& t) const {
  if (params_.maxEdgeMm > 0.0)
    for (int v : t.region.ring)
      if ((toEigen(mesh_.point(SupportMesh::VertexHandle(v))) - t.point).norm() > params_.maxEdgeMm)
        return Refusal::EdgeLength;
  return Refusal::None;
}

// The modified faces with the new vertex; false when one folds over or degenerates.
bool SupportReducer::buildFaces(Tentative& t) const {
  const ContractionRegion& r = t.region;
  t.faces.clear();
  t.faceIds.clear();
  for (int f : r.modified) {
    NewFace nf;
    nf.corners = corners(f);
    std::array<int, 3> ids = faceVertexIds(mesh_, f);
    const Vec3 oldNormal =
        (nf.corners.p[1] - nf.corners.p[0]).cross(nf.corners.p[2] - nf.corners.p[0]);
    for (int k = 0; k < 3; ++k)
      if (ids[k] == r.a || ids[k] == r.b) nf.newCorner = k, ids[k] = r.b;
    nf.corners.p[nf.newCorner] = t.point;
    nf.corners.v[nf.newCorner] = t.vector;
    const auto& p = nf.corners.p;
    const Vec3 normal = (p[1] - p[0]).cross(p[2] - p[0]);
    const double longest = std::max(
        {(p[1] - p[0]).squaredNorm(), (p[2] - p[1]).squaredNorm(), (p[0] - p[2]).squaredNorm()});
    if (!(normal.dot(oldNormal) > 0.0) || !(normal.norm() > 1e-12 * longest)) return false;
    t.faces.push_back(nf);
    t.faceIds.push_back(ids);
  }
  return true;
}

// The new vector keeps the averaged direction; with unique projection required it gets the
// longest length (up to the cap) that keeps h0 >= 1 on its faces (sec. 4.4).
Refusal SupportReducer::chooseVector(Tentative& t, double capScale) {
  for (NewFace& f : t.faces) f.corners.v[f.newCorner] = t.vector;
  if (!params_.requireUniqueProjection) return Refusal::None;
  double cap = params_.maxVectorLengthMm;
  if (cap <= 0.0)
    for (int v : t.region.ring)
      cap = std::max(cap, (toEigen(mesh_.point(SupportMesh::VertexHandle(v))) - t.point).norm());
  const Vec3 direction = t.vector.normalized();
  const auto length = chooseNewVectorLength(t.faces, direction, cap * capScale);
  if (!length) return Refusal::UniqueProjection;
  t.vector = *length * direction;
  return Refusal::None;
}

// The items of the modified faces, and of their neighbours (fig. 6.7), offered to the
// re-assignment; rasterFace keeps those some new V-ray hits within the +-1 crust.
void SupportReducer::gatherCandidates(Tentative& t) {
  ++stampNow_;
  const auto add = [&](int f) {
    for (int item : faceItems_[f].items)
      if (itemStamp_[item] != stampNow_) itemStamp_[item] = stampNow_, t.candidates.push_back(item);
  };
  add(t.region.removed[0]), add(t.region.removed[1]);
  for (int f : t.region.modified) add(f);
  if (params_.neighbourCandidates)
    for (int f : t.region.neighbours) add(f);
}

// The new faces' item buffers, each checked at once against constraint (b) and the angle bound
// (sec. 6.2). The faces are shot in parallel; a face after the first refused one is skipped,
// which leaves the refusal of the serial order: every face before it is shot and passes.
Refusal SupportReducer::rasterNewFaces(Tentative& t) const {
  const std::size_t faces = t.faces.size();
  t.items.resize(faces);
  std::vector<Refusal>& why = t.why;
  why.assign(faces, Refusal::None);
  std::atomic<std::size_t> firstRefused{faces};
  tbb::parallel_for(std::size_t{0}, faces, [&](std::size_t i) {
    if (i > firstRefused.load(std::memory_order_relaxed)) return;
    rasterFace(t.faces[i].corners, params_.resolution, items_, t.candidates, t.items[i]);
    if (params_.requireRayCoverage && !everyRayHits(t.items[i]))
      why[i] = Refusal::RayCoverage;
    else if (params_.requireAngleBound &&
             !anglesBounded(t.faces[i].corners, params_.resolution, t.items[i], items_, minCosine_))
      why[i] = Refusal::Angle;
    if (why[i] == Refusal::None) return;
    std::size_t seen = firstRefused.load(std::memory_order_relaxed);
    while (i < seen && !firstRefused.compare_exchange_weak(seen, i)) {
    }
  });
  const std::size_t first = firstRefused.load();
  return first < faces ? why[first] : Refusal::None;
}

// Constraint (a) by a counter per item of the support faces it is assigned to (sec. 6.2): an
// item hit by some ray within the crust is in the face's item set, nearest hit or not.
Refusal SupportReducer::checkInputCoverage(Tentative& t) {
  ++stampNow_;
  const auto change = [&](const std::vector<int>& hits, int by) {
    for (int item : hits) {
      if (item < 0) continue;
      if (itemStamp_[item] != stampNow_)
        itemStamp_[item] = stampNow_, t.touchedItems.push_back(item);
      delta_[item] += by;
    }
  };
  for (int f : t.region.removed) change(faceItems_[f].items, -1);
  for (int f : t.region.modified) change(faceItems_[f].items, -1);
  for (const FaceItems& fi : t.items) change(fi.items, +1);
  if (params_.requireInputCoverage)
    for (int item : t.touchedItems)
      if (hitCount_[item] > 0 && hitCount_[item] + delta_[item] <= 0) return Refusal::InputCoverage;
  return Refusal::None;
}

void SupportReducer::resetDelta(Tentative& t) {
  for (int item : t.touchedItems) delta_[item] = 0;
  t.touchedItems.clear();
}

// Item vertices V-projecting onto a new face outside its +-1 crust must lie in the crust of
// another face of the region (sec. 6.2, containment).
bool SupportReducer::contained(const Tentative& t) {
  std::vector<FaceCorners> region;
  for (std::size_t i = 0; i < t.faces.size(); ++i) {
    ++vertexStampNow_;
    for (int item : t.items[i].items)
      for (int v : items_.vertices[item]) {
        if (vertexStamp_[v] == vertexStampNow_) continue;
        vertexStamp_[v] = vertexStampNow_;
        const Vec3& q = items_.points[v];
        if (betweenOffsets(t.faces[i].corners, q)) continue;
        if (placeVertex(q, {&t.faces[i].corners, 1}) != VertexPlace::Beyond) continue;
        if (region.empty()) {
          for (const NewFace& f : t.faces) region.push_back(f.corners);
          for (int f : t.region.neighbours) region.push_back(corners(f));
        }
        if (placeVertex(q, region) != VertexPlace::Inside) return false;
      }
  }
  return true;
}

// Non-adjacent crusts (sharing no vertex) of a new face and any other face must not meet.
bool SupportReducer::crustsFree(const Tentative& t) {
  const ContractionRegion& r = t.region;
  const auto inRegion = [&](int f) {
    return f == r.removed[0] || f == r.removed[1] ||
           std::find(r.modified.begin(), r.modified.end(), f) != r.modified.end();
  };
  std::vector<int> candidates;
  for (std::size_t i = 0; i < t.faces.size(); ++i) {
    hash_.query(crustBox(t.faces[i].corners), candidates);
    for (int g : candidates) {
      if (inRegion(g)) continue;
      const auto ids = faceVertexIds(mesh_, g);
      const bool adjacent = std::any_of(ids.begin(), ids.end(), [&](int v) {
        return std::find(t.faceIds[i].begin(), t.faceIds[i].end(), v) != t.faceIds[i].end();
      });
      if (!adjacent && crustsConflict(t.faces[i].corners, corners(g))) return false;
    }
  }
  return true;
}

void SupportReducer::commit(Tentative& t) {
  const ContractionRegion& r = t.region;
  mesh_.collapse(r.heh);
  const SupportMesh::VertexHandle vb(r.b);
  mesh_.set_point(vb, toOpenMesh(t.point));
  vectors_[r.b] = t.vector;
  ++clock_;
  for (int f : r.removed) {
    faceItems_[f].clear();
    hash_.remove(f);
    faceVersion_[f] = clock_;
  }
  for (std::size_t i = 0; i < r.modified.size(); ++i) {
    const int f = r.modified[i];
    faceItems_[f].items.swap(t.items[i].items);
    hash_.set(f, crustBox(t.faces[i].corners));
    faceVersion_[f] = clock_;
  }
  for (int item : t.touchedItems) hitCount_[item] += delta_[item], delta_[item] = 0;
  for (const auto eh : mesh_.ve_range(vb)) edgeModified_[eh.idx()] = 1;
  ++report_.contractions;
}

}  // namespace ddfcam::ddf::detail
