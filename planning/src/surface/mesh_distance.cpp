// SPDX-License-Identifier: MIT
// ddfcam: exact signed point-to-mesh distance (BVH, angle-weighted pseudo-normals).
#include <ddfcam/error.h>
#include <ddfcam/planning/surface/mesh_distance.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

namespace ddfcam::planning {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr std::uint32_t kLeafSize = 4;

// Feature of a triangle holding its closest point, indexing MeshDistance::FeatureNormals.
enum Feature : int { kVertexA, kVertexB, kVertexC, kEdgeAB, kEdgeBC, kEdgeCA, kFace };

struct Closest {
  Vec3 point;
  int feature;
};

Closest onSegment(const Vec3& p, const Vec3& a, const Vec3& b, int edge, int va, int vb) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  if (t <= 0.0) return {a, va};
  if (t >= 1.0) return {b, vb};
  return {a + t * ab, edge};
}

// A zero-area triangle is the union of its edges.
Closest onDegenerate(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  Closest best = onSegment(p, a, b, kEdgeAB, kVertexA, kVertexB);
  for (const Closest& other : {onSegment(p, b, c, kEdgeBC, kVertexB, kVertexC),
                               onSegment(p, c, a, kEdgeCA, kVertexC, kVertexA)}) {
    if ((other.point - p).squaredNorm() < (best.point - p).squaredNorm()) best = other;
  }
  return best;
}

// Ericson, Real-Time Collision Detection 5.1.5, with the Voronoi region reported.
Closest closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, kVertexA};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, kVertexB};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {a + d1 / (d1 - d3) * ab, kEdgeAB};
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, kVertexC};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {a + d2 / (d2 - d6) * ac, kEdgeCA};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b), kEdgeBC};
  const double denom = va + vb + vc;
  if (!(denom > 0.0)) return onDegenerate(p, a, b, c);
  return {a + ab * (vb / denom) + ac * (vc / denom), kFace};
}

double boxDistance2(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).squaredNorm();
}

std::uint64_t edgeKey(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
         static_cast<std::uint32_t>(std::max(a, b));
}

}  // namespace

MeshDistance::MeshDistance(const ddf::TriangleMesh& mesh)
    : vertices_(mesh.vertices), triangles_(mesh.triangles) {
  if (triangles_.empty()) throw InvalidInput("MeshDistance: the mesh has no triangles");
  const int vertexCount = static_cast<int>(vertices_.size());
  std::vector<Vec3> centroids(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    for (int v : triangles_[t]) {
      if (v < 0 || v >= vertexCount) {
        throw InvalidInput("MeshDistance: triangle " + std::to_string(t) + " uses vertex " +
                           std::to_string(v) + " of " + std::to_string(vertexCount));
      }
    }
    const auto& tri = triangles_[t];
    centroids[t] = (vertices_[tri[0]] + vertices_[tri[1]] + vertices_[tri[2]]) / 3.0;
  }
  order_.resize(triangles_.size());
  for (std::uint32_t t = 0; t < order_.size(); ++t) order_[t] = t;
  nodes_.reserve(2 * triangles_.size() / kLeafSize + 1);
  build(0, static_cast<std::uint32_t>(order_.size()), centroids);
  computeNormals();
}

// Median split along the longest axis of the centroids' extent.
std::uint32_t MeshDistance::build(std::uint32_t begin, std::uint32_t end,
                                  const std::vector<Vec3>& centroids) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  Vec3 cLo = lo, cHi = hi;
  for (std::uint32_t s = begin; s < end; ++s) {
    for (int v : triangles_[order_[s]])
      lo = lo.cwiseMin(vertices_[v]), hi = hi.cwiseMax(vertices_[v]);
    cLo = cLo.cwiseMin(centroids[order_[s]]), cHi = cHi.cwiseMax(centroids[order_[s]]);
  }
  nodes_[index].lo = lo;
  nodes_[index].hi = hi;
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  int axis = 0;
  (cHi - cLo).maxCoeff(&axis);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(
      order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
      [&](std::uint32_t x, std::uint32_t y) { return centroids[x][axis] < centroids[y][axis]; });
  const std::uint32_t left = build(begin, mid, centroids);
  const std::uint32_t right = build(mid, end, centroids);
  nodes_[index].first = left;
  nodes_[index].right = right;
  return index;
}

// Baerentzen & Aanaes 2005: angle-weighted vertex normals, edge normals as the sum of the
// adjacent face normals; zero-area triangles contribute nothing.
void MeshDistance::computeNormals() {
  std::vector<Vec3> faceNormal(triangles_.size());
  std::vector<Vec3> vertexNormal(vertices_.size(), Vec3::Zero());
  std::unordered_map<std::uint64_t, Vec3> edgeNormal;
  edgeNormal.reserve(triangles_.size() * 2);
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& tri = triangles_[t];
    const Vec3 n =
        (vertices_[tri[1]] - vertices_[tri[0]]).cross(vertices_[tri[2]] - vertices_[tri[0]]);
    const double norm = n.norm();
    faceNormal[t] = norm > 0.0 ? Vec3(n / norm) : Vec3::Zero();
    for (int s = 0; s < 3; ++s) {
      const Vec3 e1 = vertices_[tri[(s + 1) % 3]] - vertices_[tri[s]];
      const Vec3 e2 = vertices_[tri[(s + 2) % 3]] - vertices_[tri[s]];
      vertexNormal[tri[s]] += std::atan2(e1.cross(e2).norm(), e1.dot(e2)) * faceNormal[t];
      auto [it, inserted] = edgeNormal.try_emplace(edgeKey(tri[s], tri[(s + 1) % 3]), Vec3::Zero());
      it->second += faceNormal[t];
    }
  }
  normals_.resize(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& tri = triangles_[t];
    FeatureNormals& n = normals_[t];
    for (int s = 0; s < 3; ++s) {
      n[kVertexA + s] = vertexNormal[tri[s]];
      n[kEdgeAB + s] = edgeNormal.at(edgeKey(tri[s], tri[(s + 1) % 3]));
    }
    n[kFace] = faceNormal[t];
  }
}

std::optional<MeshClosestPoint> MeshDistance::closestPoint(const Vec3& p,
                                                           double maxDistanceMm) const {
  if (!p.allFinite()) return std::nullopt;
  double best2 = maxDistanceMm * maxDistanceMm;
  bool found = false;
  Closest best{Vec3::Zero(), kFace};
  std::uint32_t bestTriangle = 0;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (boxDistance2(p, node.lo, node.hi) > best2) continue;
    if (node.count > 0) {
      for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
        const auto& tri = triangles_[order_[s]];
        const Closest c =
            closestOnTriangle(p, vertices_[tri[0]], vertices_[tri[1]], vertices_[tri[2]]);
        const double d2 = (c.point - p).squaredNorm();
        if (d2 < best2 || (!found && d2 <= best2)) {
          best2 = d2, best = c, bestTriangle = order_[s], found = true;
        }
      }
      continue;
    }
    // Nearer child last, so that it is searched first and tightens the bound early.
    const double dl = boxDistance2(p, nodes_[node.first].lo, nodes_[node.first].hi);
    const double dr = boxDistance2(p, nodes_[node.right].lo, nodes_[node.right].hi);
    stack[top++] = dl <= dr ? node.right : node.first;
    stack[top++] = dl <= dr ? node.first : node.right;
  }
  if (!found) return std::nullopt;
  MeshClosestPoint out;
  out.distance = std::sqrt(best2);
  const double side = (p - best.point).dot(normals_[bestTriangle][best.feature]);
  out.signedDistance = side < 0.0 ? -out.distance : out.distance;
  out.point = best.point;
  out.triangle = static_cast<int>(bestTriangle);
  return out;
}

}  // namespace ddfcam::planning
