// SPDX-License-Identifier: MIT
// ddfcam: the fans of the support vertices split at crease edges into smooth wedges.
#include "curvature_wedges.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>

namespace ddfcam::planning::detail {
namespace {

using ddf::Vec3;

int findRoot(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

// Two faces of one fan share an edge through the fan's vertex when they share two vertices.
bool shareEdge(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  int common = 0;
  for (const int x : a) common += static_cast<int>(std::find(b.begin(), b.end(), x) != b.end());
  return common >= 2;
}

// Unit normals of the represented triangles, on the +v side (zero for faces without area).
std::vector<Vec3> unitNormals(const ddf::DisplacementField& ddf, const std::vector<Vec3>& q) {
  std::vector<Vec3> out(static_cast<std::size_t>(ddf.faceCount()));
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& fv = ddf.faceVertices(f);
    Vec3 n = (q[fv[1]] - q[fv[0]]).cross(q[fv[2]] - q[fv[0]]);
    if (n.dot(ddf.vector(fv[0]) + ddf.vector(fv[1]) + ddf.vector(fv[2])) < 0.0) n = -n;
    out[static_cast<std::size_t>(f)] = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
  }
  return out;
}

// Wedge labels 0, 1, ... of the faces of v's fan, in fan order.
std::vector<int> fanLabels(const ddf::DisplacementField& ddf, const std::vector<Vec3>& normals,
                           const std::vector<int>& faceLabels, int v, double cosCrease) {
  const std::vector<int>& fan = ddf.topology().vertexFaces(v);
  std::vector<int> parent(fan.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t a = 0; a < fan.size(); ++a)
    for (std::size_t b = a + 1; b < fan.size(); ++b) {
      const Vec3& na = normals[static_cast<std::size_t>(fan[a])];
      const Vec3& nb = normals[static_cast<std::size_t>(fan[b])];
      const bool flatless = na.isZero() || nb.isZero();
      if (!shareEdge(ddf.faceVertices(fan[a]), ddf.faceVertices(fan[b]))) continue;
      if (!faceLabels.empty() && faceLabels[static_cast<std::size_t>(fan[a])] !=
                                     faceLabels[static_cast<std::size_t>(fan[b])])
        continue;
      if (flatless || na.dot(nb) >= cosCrease)
        parent[findRoot(parent, static_cast<int>(a))] = findRoot(parent, static_cast<int>(b));
    }
  std::vector<int> label(fan.size(), -1), rootLabel(fan.size(), -1);
  int next = 0;
  for (std::size_t a = 0; a < fan.size(); ++a) {
    const int root = findRoot(parent, static_cast<int>(a));
    if (rootLabel[root] < 0) rootLabel[root] = next++;
    label[a] = rootLabel[root];
  }
  return label;
}

}  // namespace

int CurvatureWedges::at(const ddf::DisplacementField& ddf, int v, int f) const {
  const std::vector<int>& fan = ddf.topology().vertexFaces(v);
  const auto it = std::find(fan.begin(), fan.end(), f);
  return ofFan[static_cast<std::size_t>(v)][static_cast<std::size_t>(it - fan.begin())];
}

CurvatureWedges curvatureWedges(const ddf::DisplacementField& ddf, const std::vector<Vec3>& corners,
                                const std::vector<int>& faceLabels, double cosCrease) {
  const std::vector<Vec3> normals = unitNormals(ddf, corners);
  CurvatureWedges out;
  out.ofFan.resize(static_cast<std::size_t>(ddf.vertexCount()));
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    std::vector<int> label = fanLabels(ddf, normals, faceLabels, v, cosCrease);
    const int base = out.count();
    const int wedges = label.empty() ? 0 : *std::max_element(label.begin(), label.end()) + 1;
    out.vertex.resize(static_cast<std::size_t>(base + wedges), v);
    out.faces.resize(static_cast<std::size_t>(base + wedges));
    const std::vector<int>& fan = ddf.topology().vertexFaces(v);
    for (std::size_t a = 0; a < fan.size(); ++a) {
      label[a] += base;
      out.faces[static_cast<std::size_t>(label[a])].push_back(fan[a]);
    }
    out.ofFan[static_cast<std::size_t>(v)] = std::move(label);
  }
  return out;
}

std::vector<int> wedgeNeighbourhood(const ddf::DisplacementField& ddf,
                                    const CurvatureWedges& wedges, int w, int rings) {
  std::vector<int> faces = wedges.faces[static_cast<std::size_t>(w)];
  std::sort(faces.begin(), faces.end());
  for (int r = 1; r < rings; ++r) {
    std::vector<int> grown = faces;
    for (const int h : faces)
      for (const int u : ddf.faceVertices(h)) {
        const auto& more = wedges.faces[static_cast<std::size_t>(wedges.at(ddf, u, h))];
        grown.insert(grown.end(), more.begin(), more.end());
      }
    std::sort(grown.begin(), grown.end());
    grown.erase(std::unique(grown.begin(), grown.end()), grown.end());
    faces = std::move(grown);
  }
  return faces;
}

}  // namespace ddfcam::planning::detail
