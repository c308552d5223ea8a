// SPDX-License-Identifier: MIT
// ddfcam: blending functions d(u, v) for the blended surface f = s + d h v (dissertation ch. 9).
#include <ddfcam/ddf/closest_point.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/mould/blend_function.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>

namespace ddfcam::planning {
namespace {

using ddf::DisplacementField;
using ddf::PointId;
using ddf::Vec3;

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

// Calls fn(face, local index, point id, i, k) for every raster point copy.
template <class Fn>
void forEachCopy(const DisplacementField& ddf, Fn&& fn) {
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) fn(f, raster.index(i, k), ddf.topology().id(f, i, k), i, k);
}

// Support point g of every raster point, by PointId.
std::vector<Vec3> supportPoints(const DisplacementField& ddf) {
  std::vector<Vec3> g(ddf.topology().pointCount(), Vec3::Zero());
  forEachCopy(ddf, [&](int f, std::size_t, PointId id, int i, int k) {
    g[id] = ddf.basePoint(f, ddf.rasterBary(i, k));
  });
  return g;
}

// Raster points on support edges with a face on one side only.
std::vector<PointId> boundaryPoints(const DisplacementField& ddf) {
  const ddf::RasterTopology& topo = ddf.topology();
  const int n = ddf.raster().steps();
  std::vector<PointId> out;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    for (int le = 0; le < 3; ++le) {
      const auto& sides = topo.edgeFaces(topo.faceEdge(f, le));
      if (sides[0] >= 0 && sides[1] >= 0) continue;
      for (int t = 0; t <= n; ++t) {
        // Local edges: 0 = p1->p2 (k = 0), 1 = p2->p3 (i = 0), 2 = p3->p1 (j = 0).
        const int i = le == 0 ? t : (le == 1 ? 0 : n - t);
        const int k = le == 0 ? 0 : t;
        out.push_back(topo.id(f, i, k));
      }
    }
  }
  return out;
}

// Painted flag per face; throws on an index out of range.
std::vector<char> paintedFaces(const DisplacementField& ddf, const std::vector<int>& faces) {
  std::vector<char> painted(ddf.faceCount(), 0);
  for (const int f : faces) {
    if (f < 0 || f >= ddf.faceCount())
      throw InvalidInput("blendWeights: painted face " + std::to_string(f) + " out of range (" +
                         std::to_string(ddf.faceCount()) + " faces)");
    painted[f] = 1;
  }
  return painted;
}

// Raster points with copies in both a painted and an unpainted face.
std::vector<PointId> regionBorder(const DisplacementField& ddf, const std::vector<char>& painted) {
  std::vector<char> in(ddf.topology().pointCount(), 0), out(in.size(), 0);
  forEachCopy(ddf,
              [&](int f, std::size_t, PointId id, int, int) { (painted[f] ? in : out)[id] = 1; });
  std::vector<PointId> border;
  for (std::size_t id = 0; id < in.size(); ++id)
    if (in[id] && out[id]) border.push_back(static_cast<PointId>(id));
  return border;
}

void checkWidth(double w, const char* what) {
  if (!(w > 0.0) || !std::isfinite(w))
    throw InvalidInput(std::string("blendWeights: ") + what + " " + std::to_string(w) +
                       " mm (must be > 0)");
}

// Per-point weight from a per-point distance: value S(d / width); infinite d gives value.
std::vector<double> rampFromDistance(const std::vector<double>& d, double width, double value) {
  std::vector<double> w(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) w[i] = value * smoothstep(d[i] / width);
  return w;
}

std::vector<double> pointWeights(const DisplacementField& ddf, const BlendParams& p,
                                 const std::vector<char>& painted) {
  switch (p.kind) {
    case BlendKind::Constant:
      return std::vector<double>(ddf.topology().pointCount(), p.value);
    case BlendKind::Radial: {
      checkWidth(p.radiusMm, "radius");
      if (!p.centreMm.allFinite()) throw InvalidInput("blendWeights: centre is not finite");
      const std::vector<Vec3> g = supportPoints(ddf);
      std::vector<double> w(g.size());
      for (std::size_t i = 0; i < g.size(); ++i)
        w[i] = p.value * (1.0 - smoothstep((g[i] - p.centreMm).norm() / p.radiusMm));
      return w;
    }
    case BlendKind::Region: {
      checkWidth(p.edgeWidthMm, "edge width");
      const std::vector<PointId> border = regionBorder(ddf, painted);
      return rampFromDistance(latticeDistances(ddf, border), p.edgeWidthMm, p.value);
    }
    case BlendKind::Boundary: {
      checkWidth(p.widthMm, "width");
      const std::vector<PointId> boundary = boundaryPoints(ddf);
      return rampFromDistance(latticeDistances(ddf, boundary), p.widthMm, p.value);
    }
  }
  throw InvalidInput("blendWeights: unknown blend kind");
}

// The raster lattice as a compressed adjacency list: the three edges of every upward lattice
// cell of every face, both directions (edges on shared support edges appear once per face,
// which Dijkstra tolerates), weighted by the distance between support points.
struct LatticeGraph {
  std::vector<std::size_t> offsets;  // #points + 1
  std::vector<PointId> targets;
  std::vector<double> lengths;

  explicit LatticeGraph(const DisplacementField& ddf) {
    const std::vector<Vec3> g = supportPoints(ddf);
    std::vector<std::pair<PointId, PointId>> edges;
    const int n = ddf.raster().steps();
    edges.reserve(static_cast<std::size_t>(3) * n * (n + 1) / 2 * ddf.faceCount());
    for (int f = 0; f < ddf.faceCount(); ++f) {
      auto id = [&](int i, int k) { return ddf.topology().id(f, i, k); };
      for (int k = 0; k < n; ++k) {
        for (int i = 0; i + k < n; ++i) {
          edges.emplace_back(id(i, k), id(i + 1, k));
          edges.emplace_back(id(i, k), id(i, k + 1));
          edges.emplace_back(id(i + 1, k), id(i, k + 1));
        }
      }
    }
    offsets.assign(g.size() + 1, 0);
    for (const auto& [a, b] : edges) ++offsets[a + 1], ++offsets[b + 1];
    for (std::size_t p = 0; p < g.size(); ++p) offsets[p + 1] += offsets[p];
    targets.resize(offsets.back());
    lengths.resize(offsets.back());
    std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
    for (const auto& [a, b] : edges) {
      const double len = (g[a] - g[b]).norm();
      targets[fill[a]] = b, lengths[fill[a]++] = len;
      targets[fill[b]] = a, lengths[fill[b]++] = len;
    }
  }
};

}  // namespace

std::vector<double> latticeDistances(const DisplacementField& ddf,
                                     std::span<const PointId> sources) {
  const LatticeGraph graph(ddf);
  std::vector<double> dist(graph.offsets.size() - 1, std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, PointId>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (const PointId s : sources) {
    if (s >= dist.size())
      throw InvalidInput("latticeDistances: source " + std::to_string(s) + " out of range");
    if (dist[s] > 0.0) queue.emplace(0.0, s);
    dist[s] = 0.0;
  }
  while (!queue.empty()) {
    const auto [d, p] = queue.top();
    queue.pop();
    if (d > dist[p]) continue;
    for (std::size_t e = graph.offsets[p]; e < graph.offsets[p + 1]; ++e) {
      const PointId q = graph.targets[e];
      const double nd = d + graph.lengths[e];
      if (nd < dist[q]) {
        dist[q] = nd;
        queue.emplace(nd, q);
      }
    }
  }
  return dist;
}

std::vector<float> blendWeights(const DisplacementField& ddf, const BlendParams& params) {
  if (!std::isfinite(params.value))
    throw InvalidInput("blendWeights: value " + std::to_string(params.value) + " is not finite");
  const std::vector<char> painted = params.kind == BlendKind::Region
                                        ? paintedFaces(ddf, params.faces)
                                        : std::vector<char>(ddf.faceCount(), 1);
  const std::vector<double> w = pointWeights(ddf, params, painted);
  std::vector<float> out(ddf.allHeights().size());
  forEachCopy(ddf, [&](int f, std::size_t local, PointId id, int, int) {
    out[static_cast<std::size_t>(f) * ddf.pointsPerFace() + local] =
        painted[f] ? static_cast<float>(w[id]) : 0.0f;
  });
  return out;
}

std::vector<int> facesWithinRadius(const DisplacementField& ddf, const Vec3& centreMm,
                                   double radiusMm) {
  if (!(radiusMm >= 0.0) || !std::isfinite(radiusMm) || !centreMm.allFinite())
    throw InvalidInput("facesWithinRadius: radius " + std::to_string(radiusMm) +
                       " mm (must be finite and >= 0) or centre not finite");
  std::vector<int> out;
  const double r2 = radiusMm * radiusMm;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& v = ddf.faceVertices(f);
    const Vec3 c = ddf::closestPointOnTriangle(centreMm, ddf.position(v[0]), ddf.position(v[1]),
                                               ddf.position(v[2]));
    if ((c - centreMm).squaredNorm() <= r2) out.push_back(f);
  }
  return out;
}

}  // namespace ddfcam::planning
