// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/error.h>

#include <algorithm>
#include <limits>
#include <string>

namespace ddfcam::ddf {

DisplacementField::DisplacementField(SupportMesh support, std::vector<Vec3> vectors, int m,
                                     float initialHeight)
    : support_(std::move(support)) {
  if (vectors.size() != support_.n_vertices()) {
    throw InvalidInput(
        "DDF needs one displacement vector per support vertex: " + std::to_string(vectors.size()) +
        " vectors for " + std::to_string(support_.n_vertices()) + " vertices");
  }
  topology_ = RasterTopology(support_, m);
  positions_.reserve(support_.n_vertices());
  for (const auto vh : support_.vertices()) positions_.push_back(toEigen(support_.point(vh)));
  vectors_ = std::move(vectors);
  faceVertices_.resize(support_.n_faces());
  for (int f = 0; f < static_cast<int>(faceVertices_.size()); ++f)
    faceVertices_[f] = topology_.faceVertices(f);
  pointsPerFace_ = topology_.raster().pointCount();
  heights_.assign(pointsPerFace_ * faceVertices_.size(), initialHeight);
}

void DisplacementField::setVectors(std::vector<Vec3> vectors) {
  if (vectors.size() != positions_.size()) {
    throw InvalidInput("setVectors: " + std::to_string(vectors.size()) + " vectors for " +
                       std::to_string(positions_.size()) + " vertices");
  }
  vectors_ = std::move(vectors);
}

Vec3 DisplacementField::basePoint(int f, const Vec3& bary) const {
  const auto& fv = faceVertices_[f];
  return bary[0] * positions_[fv[0]] + bary[1] * positions_[fv[1]] + bary[2] * positions_[fv[2]];
}

Vec3 DisplacementField::vectorAt(int f, const Vec3& bary) const {
  const auto& fv = faceVertices_[f];
  return bary[0] * vectors_[fv[0]] + bary[1] * vectors_[fv[1]] + bary[2] * vectors_[fv[2]];
}

Vec3 DisplacementField::pointAt(int f, const Vec3& bary, double h) const {
  return basePoint(f, bary) + h * vectorAt(f, bary);
}

Vec3 DisplacementField::rasterBary(int i, int k) const {
  const int n = raster().steps();
  const double inv = 1.0 / n;
  return {i * inv, (n - i - k) * inv, k * inv};
}

Vec3 DisplacementField::surfacePoint(int f, int i, int k) const {
  return pointAt(f, rasterBary(i, k), height(f, i, k));
}

namespace {

// Value all copies take: the minimum, or the copy of the lowest-index face.
struct SharedValue {
  SharedPolicy policy;
  float value = std::numeric_limits<float>::infinity();
  int face = std::numeric_limits<int>::max();
  void add(int f, float h) {
    if (policy == SharedPolicy::Minimum) {
      value = std::min(value, h);
    } else if (f < face) {
      face = f, value = h;
    }
  }
};

}  // namespace

void DisplacementField::syncEdge(int edge, SharedPolicy policy) {
  const auto& sides = topology_.edgeFaces(edge);
  if (sides[0] < 0 || sides[1] < 0) return;
  const int n = raster().steps();
  const int e0 = topology_.localEdgeOf(sides[0], edge), e1 = topology_.localEdgeOf(sides[1], edge);
  float* h0 = heights(sides[0]).data();
  float* h1 = heights(sides[1]).data();
  for (int t = 1; t < n; ++t) {
    float& a = h0[topology_.edgeCopyLocal(sides[0], e0, t)];
    float& b = h1[topology_.edgeCopyLocal(sides[1], e1, t)];
    SharedValue shared{policy};
    shared.add(sides[0], a);
    shared.add(sides[1], b);
    a = b = shared.value;
  }
}

void DisplacementField::syncVertex(int vertex, SharedPolicy policy) {
  const int n = raster().steps();
  auto localIndex = [&](int f) {
    const auto& fv = faceVertices_[f];
    return raster().index(fv[0] == vertex ? n : 0, fv[2] == vertex ? n : 0);
  };
  SharedValue shared{policy};
  for (int f : topology_.vertexFaces(vertex)) shared.add(f, heights(f)[localIndex(f)]);
  for (int f : topology_.vertexFaces(vertex)) heights(f)[localIndex(f)] = shared.value;
}

void DisplacementField::synchronizeShared(SharedPolicy policy) {
  for (int e = 0; e < static_cast<int>(support_.n_edges()); ++e) syncEdge(e, policy);
  for (int v = 0; v < vertexCount(); ++v) syncVertex(v, policy);
}

void DisplacementField::synchronizeShared(SharedPolicy policy, std::span<const int> faces) {
  for (int f : faces) {
    for (int e = 0; e < 3; ++e) syncEdge(topology_.faceEdge(f, e), policy);
    for (int v : faceVertices_[f]) syncVertex(v, policy);
  }
}

std::size_t DisplacementField::memoryBytes() const {
  // OpenMesh array kernel: per vertex a point and a halfedge handle, per face a handle, per
  // halfedge (vertex, face, next, prev) handles.
  const std::size_t meshBytes = support_.n_vertices() * (sizeof(OpenMesh::Vec3d) + 4) +
                                support_.n_faces() * 4 + support_.n_halfedges() * 16;
  return meshBytes + topology_.memoryBytes() + faceVertices_.capacity() * sizeof(faceVertices_[0]) +
         positions_.capacity() * sizeof(Vec3) + vectors_.capacity() * sizeof(Vec3) +
         heights_.capacity() * sizeof(float);
}

}  // namespace ddfcam::ddf
