// SPDX-License-Identifier: MIT
// ddfcam: private building blocks of the deformation sequence (point/mesh distance, stages).
#include "deformation_stage.h"

#include <ddfcam/ddf/closest_point.h>
#include <ddfcam/ddf/crust.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ddfcam::ddf::detail {
namespace {

constexpr int kLeafSize = 4;
constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh) : mesh_(mesh) {
  const int count = static_cast<int>(mesh.triangles.size());
  order_.resize(count);
  std::iota(order_.begin(), order_.end(), 0);
  centroids_.resize(count);
  for (int t = 0; t < count; ++t) {
    const auto& tri = mesh.triangles[t];
    centroids_[t] = (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3.0;
  }
  nodes_.reserve(2 * static_cast<std::size_t>(count / kLeafSize + 1));
  if (count > 0) build(0, count, 0);
}

int TriangleBvh::build(int first, int count, int depth) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3d box, centres;
  for (int i = first; i < first + count; ++i) {
    for (int c = 0; c < 3; ++c) box.extend(mesh_.vertices[mesh_.triangles[order_[i]][c]]);
    centres.extend(centroids_[order_[i]]);
  }
  nodes_[index].box = box;
  if (count <= kLeafSize || depth > 60) {
    nodes_[index].first = first, nodes_[index].count = count;
    return index;
  }
  int axis = 0;
  centres.sizes().maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count,
                   [&](int a, int b) { return centroids_[a][axis] < centroids_[b][axis]; });
  const int left = build(first, half, depth + 1);
  const int right = build(first + half, count - half, depth + 1);
  nodes_[index].first = left, nodes_[index].count = 0, nodes_[index].right = right;
  return index;
}

double TriangleBvh::triangleDistanceSq(int t, const Vec3& p) const {
  const auto& tri = mesh_.triangles[t];
  const Vec3& a = mesh_.vertices[tri[0]];
  return (closestPointOnTriangle(p, a, mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]) - p)
      .squaredNorm();
}

double TriangleBvh::distance(const Vec3& p) const {
  if (nodes_.empty()) return kInf;
  double best = kInf;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (node.box.squaredExteriorDistance(p) >= best) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i)
        best = std::min(best, triangleDistanceSq(order_[i], p));
      continue;
    }
    // Visit the nearer child first so that its bound prunes the other.
    const int a = node.first, b = node.right;
    const bool aFirst =
        nodes_[a].box.squaredExteriorDistance(p) <= nodes_[b].box.squaredExteriorDistance(p);
    stack.push_back(aFirst ? b : a);
    stack.push_back(aFirst ? a : b);
  }
  return std::sqrt(best);
}

double largestVertexDistance(const DisplacementField& ddf, const TriangleBvh& bvh) {
  return tbb::parallel_reduce(
      tbb::blocked_range<int>(0, ddf.vertexCount()), 0.0,
      [&](const tbb::blocked_range<int>& range, double acc) {
        for (int v = range.begin(); v != range.end(); ++v)
          acc = std::max(acc, bvh.distance(ddf.position(v)));
        return acc;
      },
      [](double a, double b) { return std::max(a, b); });
}

std::vector<double> crustRatios(const DisplacementField& ddf) {
  std::vector<double> ratios(ddf.faceCount(), kInf);
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      float up = 0.0f, down = 0.0f;
      for (const float h : ddf.heights(f)) {
        if (h > up) up = h;
        if (-h > down) down = -h;
      }
      if (up == 0.0f && down == 0.0f) continue;
      const CrustHeights h0 = crustHeights(ddf, f);
      if (up > 0.0f) ratios[f] = std::min(ratios[f], h0.positive / up);
      if (down > 0.0f) ratios[f] = std::min(ratios[f], h0.negative / down);
    }
  });
  return ratios;
}

namespace {

// Height of vertex v's corner raster point in the first face copy where it is finite.
float vertexHeight(const DisplacementField& ddf, int v) {
  const int n = ddf.raster().steps();
  for (const int f : ddf.topology().vertexFaces(v)) {
    const auto& fv = ddf.faceVertices(f);
    const int corner = fv[0] == v ? 0 : (fv[1] == v ? 1 : 2);
    const std::size_t local =
        corner == 0 ? ddf.raster().index(n, 0)
                    : (corner == 1 ? ddf.raster().index(0, 0) : ddf.raster().index(0, n));
    const float h = ddf.heights(f)[local];
    if (std::isfinite(h)) return h;
  }
  return std::numeric_limits<float>::quiet_NaN();
}

// Fills unknown moves with the mean of known neighbour moves, sweep by sweep.
void diffuseMoves(const DisplacementField& ddf, std::vector<Vec3>& moves,
                  std::vector<char>& known) {
  const auto& mesh = ddf.support();
  for (int sweep = 0; sweep < 8; ++sweep) {
    std::vector<std::pair<int, Vec3>> updates;
    for (int v = 0; v < ddf.vertexCount(); ++v) {
      if (known[v]) continue;
      Vec3 sum = Vec3::Zero();
      int count = 0;
      for (const auto w : mesh.vv_range(OpenMesh::VertexHandle(v)))
        if (known[w.idx()]) sum += moves[w.idx()], ++count;
      if (count > 0) updates.emplace_back(v, sum / count);
    }
    if (updates.empty()) return;
    for (const auto& [v, move] : updates) moves[v] = move, known[v] = 1;
  }
}

}  // namespace

std::vector<Vec3> vertexMoves(const DisplacementField& ddf, double t) {
  const int count = ddf.vertexCount();
  std::vector<Vec3> moves(count, Vec3::Zero());
  std::vector<char> known(count, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, count), [&](const auto& range) {
    for (int v = range.begin(); v != range.end(); ++v) {
      const float h = vertexHeight(ddf, v);
      if (!std::isfinite(h)) continue;
      moves[v] = t * static_cast<double>(h) * ddf.vector(v), known[v] = 1;
    }
  });
  diffuseMoves(ddf, moves, known);
  return moves;
}

std::vector<int> flippedFaces(const DisplacementField& ddf, const std::vector<Vec3>& positions) {
  std::vector<int> flipped;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& fv = ddf.faceVertices(f);
    const Vec3 before = (ddf.position(fv[1]) - ddf.position(fv[0]))
                            .cross(ddf.position(fv[2]) - ddf.position(fv[0]));
    const Vec3 after =
        (positions[fv[1]] - positions[fv[0]]).cross(positions[fv[2]] - positions[fv[0]]);
    if (before.squaredNorm() > 0 && !(before.dot(after) > 0)) flipped.push_back(f);
  }
  return flipped;
}

}  // namespace ddfcam::ddf::detail
