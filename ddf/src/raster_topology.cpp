// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/raster_topology.h>
#include <ddfcam/error.h>

#include <algorithm>

namespace ddfcam::ddf {
namespace {

// The six lattice directions (di, dk); j follows from i + j + k = n.
constexpr std::array<std::array<int, 2>, 6> kLatticeSteps = {
    {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, -1}, {-1, 1}}};

}  // namespace

RasterTopology::RasterTopology(const SupportMesh& mesh, int m) : raster_{m} {
  if (m < 2) throw InvalidInput("raster resolution must be at least 2, got " + std::to_string(m));
  vertexCount_ = mesh.n_vertices();
  edgeCount_ = mesh.n_edges();
  const std::size_t faces = mesh.n_faces();
  faceVertices_.resize(faces);
  faceEdges_.resize(faces);
  edgeFaces_.assign(edgeCount_, {-1, -1});
  edgeVertices_.resize(edgeCount_);
  vertexFaces_.assign(vertexCount_, {});
  for (const auto eh : mesh.edges()) {
    const int a = eh.v0().idx(), b = eh.v1().idx();
    edgeVertices_[eh.idx()] = {std::min(a, b), std::max(a, b)};
  }
  for (const auto fh : mesh.faces()) {
    const int f = fh.idx();
    auto h = fh.halfedge();
    for (int e = 0; e < 3; ++e) {
      faceVertices_[f][e] = h.from().idx();
      faceEdges_[f][e] = h.edge().idx();
      auto& sides = edgeFaces_[h.edge().idx()];
      (sides[0] < 0 ? sides[0] : sides[1]) = f;
      vertexFaces_[h.from().idx()].push_back(f);
      h = h.next();
    }
  }
  const std::size_t n = raster_.steps();
  const std::size_t interior = n >= 3 ? (n - 1) * (n - 2) / 2 : 0;
  pointCount_ = vertexCount_ + edgeCount_ * (n - 1) + faces * interior;
}

PointId RasterTopology::id(int f, int i, int k) const {
  const int n = raster_.steps();
  const int j = n - i - k;
  const auto& fv = faceVertices_[f];
  if (i == n) return static_cast<PointId>(fv[0]);
  if (j == n) return static_cast<PointId>(fv[1]);
  if (k == n) return static_cast<PointId>(fv[2]);
  int localEdge = -1, tLocal = 0;
  if (k == 0) {
    localEdge = 0, tLocal = j;  // p1 -> p2
  } else if (i == 0) {
    localEdge = 1, tLocal = k;  // p2 -> p3
  } else if (j == 0) {
    localEdge = 2, tLocal = i;  // p3 -> p1
  }
  if (localEdge >= 0) {
    const int e = faceEdges_[f][localEdge];
    const bool forward = fv[localEdge] == edgeVertices_[e][0];
    const int t = forward ? tLocal : n - tLocal;
    return static_cast<PointId>(vertexCount_ + static_cast<std::size_t>(e) * (n - 1) + (t - 1));
  }
  const Raster inner{n - 2};
  const std::size_t interior = static_cast<std::size_t>(n - 1) * (n - 2) / 2;
  return static_cast<PointId>(vertexCount_ + edgeCount_ * (n - 1) + f * interior +
                              inner.index(i - 1, k - 1));
}

int RasterTopology::localEdgeOf(int face, int edge) const {
  for (int e = 0; e < 3; ++e)
    if (faceEdges_[face][e] == edge) return e;
  return -1;
}

std::uint32_t RasterTopology::edgeCopyLocal(int face, int localEdge, int t) const {
  const int n = raster_.steps();
  const auto& fv = faceVertices_[face];
  const int e = faceEdges_[face][localEdge];
  const bool forward = fv[localEdge] == edgeVertices_[e][0];
  const int tLocal = forward ? t : n - t;
  switch (localEdge) {
    case 0:
      return static_cast<std::uint32_t>(raster_.index(n - tLocal, 0));
    case 1:
      return static_cast<std::uint32_t>(raster_.index(0, tLocal));
    default:
      return static_cast<std::uint32_t>(raster_.index(tLocal, n - tLocal));
  }
}

void RasterTopology::forEachCopyImpl(PointId p, const std::function<void(PointCopy)>& fn) const {
  const std::size_t n = raster_.steps();
  if (p < vertexCount_) {
    for (int f : vertexFaces_[p]) {
      const auto& fv = faceVertices_[f];
      const int n_ = static_cast<int>(n);
      if (fv[0] == static_cast<int>(p)) fn({f, static_cast<std::uint32_t>(raster_.index(n_, 0))});
      if (fv[1] == static_cast<int>(p)) fn({f, static_cast<std::uint32_t>(raster_.index(0, 0))});
      if (fv[2] == static_cast<int>(p)) fn({f, static_cast<std::uint32_t>(raster_.index(0, n_))});
    }
    return;
  }
  std::size_t rest = p - vertexCount_;
  if (n >= 2 && rest < edgeCount_ * (n - 1)) {
    const int e = static_cast<int>(rest / (n - 1));
    const int t = static_cast<int>(rest % (n - 1)) + 1;
    for (int f : edgeFaces_[e]) {
      if (f >= 0) fn({f, edgeCopyLocal(f, localEdgeOf(f, e), t)});
    }
    return;
  }
  rest -= edgeCount_ * (n - 1);
  const std::size_t interior = (n - 1) * (n - 2) / 2;
  const int f = static_cast<int>(rest / interior);
  const std::size_t innerIndex = rest % interior;
  // Invert the inner raster index row by row (rows are short compared with the cost of a call).
  const Raster inner{static_cast<int>(n) - 2};
  int k = 0;
  while (k + 1 < inner.m && inner.rowOffset(k + 1) <= innerIndex) ++k;
  const int i = static_cast<int>(innerIndex - inner.rowOffset(k));
  fn({f, static_cast<std::uint32_t>(raster_.index(i + 1, k + 1))});
}

RasterCoord RasterTopology::coord(const PointCopy& c) const {
  const int n = raster_.steps();
  int k = 0;
  while (k < n && raster_.rowOffset(k + 1) <= c.local) ++k;
  const int i = static_cast<int>(c.local - raster_.rowOffset(k));
  return {i, n - i - k, k};
}

void RasterTopology::neighbors(PointId p, std::vector<PointId>& out) const {
  out.clear();
  const int n = raster_.steps();
  forEachCopy(p, [&](PointCopy c) {
    const RasterCoord rc = coord(c);
    for (const auto& s : kLatticeSteps) {
      const int i = rc.i + s[0], k = rc.k + s[1];
      const int j = n - i - k;
      if (i < 0 || k < 0 || j < 0 || i > n || k > n || j > n) continue;
      out.push_back(id(c.face, i, k));
    }
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

std::size_t RasterTopology::memoryBytes() const {
  constexpr std::size_t kMallocOverhead = 16;
  std::size_t bytes = faceVertices_.capacity() * sizeof(faceVertices_[0]) +
                      faceEdges_.capacity() * sizeof(faceEdges_[0]) +
                      edgeFaces_.capacity() * sizeof(edgeFaces_[0]) +
                      edgeVertices_.capacity() * sizeof(edgeVertices_[0]) +
                      vertexFaces_.capacity() * sizeof(vertexFaces_[0]);
  for (const auto& faces : vertexFaces_) bytes += faces.capacity() * sizeof(int) + kMallocOverhead;
  return bytes;
}

}  // namespace ddfcam::ddf
