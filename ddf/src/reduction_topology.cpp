// SPDX-License-Identifier: MIT
// ddfcam: topology of the edge contractions of the support reduction (sec. 6.1).
#include "reduction_topology.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ddfcam::ddf::detail {
namespace {

void pushUnique(std::vector<int>& list, int value) {
  if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

Vec3 faceNormalOf(const SupportMesh& mesh, SupportMesh::FaceHandle fh) {
  std::array<Vec3, 3> p;
  int k = 0;
  for (const auto vh : mesh.fv_range(fh)) p[k++] = toEigen(mesh.point(vh));
  return (p[1] - p[0]).cross(p[2] - p[0]).normalized();
}

void markFeatureEdges(const SupportMesh& mesh, double featureAngleDeg, std::vector<char>& kept) {
  if (!(featureAngleDeg < 180.0)) return;
  const double minCosine = std::cos(featureAngleDeg * M_PI / 180.0);
  for (const auto eh : mesh.edges()) {
    if (mesh.is_boundary(eh)) continue;
    const auto h = mesh.halfedge_handle(eh, 0);
    const Vec3 n0 = faceNormalOf(mesh, mesh.face_handle(h));
    const Vec3 n1 = faceNormalOf(mesh, mesh.face_handle(mesh.opposite_halfedge_handle(h)));
    if (n0.dot(n1) >= minCosine) continue;
    kept[mesh.from_vertex_handle(h).idx()] = 1;
    kept[mesh.to_vertex_handle(h).idx()] = 1;
  }
}

}  // namespace

std::vector<char> keptVertices(const SupportMesh& mesh, std::span<const int> faceLabels,
                               double featureAngleDeg) {
  std::vector<char> kept(mesh.n_vertices(), 0);
  markFeatureEdges(mesh, featureAngleDeg, kept);
  for (const auto vh : mesh.vertices()) {
    if (mesh.is_boundary(vh)) {
      kept[vh.idx()] = 1;
      continue;
    }
    if (faceLabels.empty()) continue;
    int label = -1;
    bool first = true;
    for (const auto fh : mesh.vf_range(vh)) {
      const int l = faceLabels[fh.idx()];
      if (!first && l != label) kept[vh.idx()] = 1;
      label = l, first = false;
    }
  }
  return kept;
}

bool isCriticalEdge(SupportMesh& mesh, SupportMesh::HalfedgeHandle heh) {
  const auto a = mesh.from_vertex_handle(heh), b = mesh.to_vertex_handle(heh);
  const auto c = mesh.to_vertex_handle(mesh.next_halfedge_handle(heh));
  const auto d =
      mesh.to_vertex_handle(mesh.next_halfedge_handle(mesh.opposite_halfedge_handle(heh)));
  // A vertex adjacent to both ends other than the two apexes closes a 3-cycle with no face.
  for (const auto x : mesh.vv_range(a)) {
    if (x == b || x == c || x == d) continue;
    for (const auto y : mesh.vv_range(b))
      if (y == x) return true;
  }
  // Faces (a, c, d) and (b, c, d) would both become (new, c, d) (a tetrahedron).
  if (const auto cd = mesh.find_halfedge(c, d);
      cd.is_valid() && !mesh.is_boundary(mesh.edge_handle(cd))) {
    const auto apex = [&](SupportMesh::HalfedgeHandle h) {
      return mesh.to_vertex_handle(mesh.next_halfedge_handle(h));
    };
    const auto x = apex(cd), y = apex(mesh.opposite_halfedge_handle(cd));
    if ((x == a && y == b) || (x == b && y == a)) return true;
  }
  return !mesh.is_collapse_ok(heh);
}

ContractionRegion contractionRegion(const SupportMesh& mesh, SupportMesh::HalfedgeHandle heh) {
  ContractionRegion r;
  r.heh = heh;
  r.a = mesh.from_vertex_handle(r.heh).idx();
  r.b = mesh.to_vertex_handle(r.heh).idx();
  r.removed = {mesh.face_handle(r.heh).idx(),
               mesh.face_handle(mesh.opposite_halfedge_handle(r.heh)).idx()};
  for (const int v : {r.a, r.b}) {
    const SupportMesh::VertexHandle vh(v);
    for (const auto fh : mesh.vf_range(vh))
      if (fh.idx() != r.removed[0] && fh.idx() != r.removed[1]) pushUnique(r.modified, fh.idx());
    for (const auto x : mesh.vv_range(vh))
      if (x.idx() != r.a && x.idx() != r.b) pushUnique(r.ring, x.idx());
  }
  for (const int v : r.ring)
    for (const auto fh : mesh.vf_range(SupportMesh::VertexHandle(v))) {
      const int f = fh.idx();
      if (f == r.removed[0] || f == r.removed[1]) continue;
      if (std::find(r.modified.begin(), r.modified.end(), f) != r.modified.end()) continue;
      pushUnique(r.neighbours, f);
    }
  return r;
}

std::array<int, 3> faceVertexIds(const SupportMesh& mesh, int face) {
  std::array<int, 3> ids{};
  int k = 0;
  for (const auto vh : mesh.fv_range(SupportMesh::FaceHandle(face))) ids[k++] = vh.idx();
  return ids;
}

}  // namespace ddfcam::ddf::detail
