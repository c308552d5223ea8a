// SPDX-License-Identifier: MIT
// ddfcam: section curves of surfaces cut by the plane of a user-drawn line.
#include <ddfcam/planning/surface/cross_section.h>

#include <ddfcam/error.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace ddfcam::planning {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using Polyline = std::vector<Vector2d>;

// Cut points (one per crossed mesh edge) and the segments joining them (one per crossed
// triangle); a graph whose paths are the section polylines.
struct CutGraph {
  std::vector<Vector2d> points;
  std::vector<std::vector<int>> segmentsAt;  // per point: indices into segments
  std::vector<std::array<int, 2>> segments;
};

CutGraph cutMesh(const ddf::TriangleMesh& mesh, const SectionPlane& plane) {
  const auto vertexCount = static_cast<int>(mesh.vertices.size());
  std::vector<double> side(mesh.vertices.size());
  for (std::size_t v = 0; v < side.size(); ++v)
    side[v] = (mesh.vertices[v] - plane.origin).dot(plane.normal);
  CutGraph g;
  std::unordered_map<std::uint64_t, int> pointOfEdge;
  const auto cutPoint = [&](int a, int b) {
    if (a > b) std::swap(a, b);  // the same edge gives the same point from both triangles
    const std::uint64_t key = (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
    const auto [it, inserted] = pointOfEdge.try_emplace(key, int(g.points.size()));
    if (inserted) {
      const double f = side[a] / (side[a] - side[b]);
      const Vector3d p = mesh.vertices[a] + f * (mesh.vertices[b] - mesh.vertices[a]);
      g.points.emplace_back((p - plane.origin).dot(plane.sAxis),
                            (p - plane.origin).dot(plane.tAxis));
      g.segmentsAt.emplace_back();
    }
    return it->second;
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (const int v : tri)
      if (v < 0 || v >= vertexCount)
        throw InvalidInput("sectionCurves: triangle " + std::to_string(t) + " refers to vertex " +
                           std::to_string(v) + " of " + std::to_string(vertexCount));
    std::array<int, 2> seg{};
    int found = 0;
    for (int e = 0; e < 3; ++e) {
      const int a = tri[e], b = tri[(e + 1) % 3];
      // A vertex exactly on the plane counts as positive, so cuts always lie on edges.
      if ((side[a] >= 0.0) != (side[b] >= 0.0) && found < 2) seg[found++] = cutPoint(a, b);
    }
    if (found != 2 || seg[0] == seg[1]) continue;
    const int index = static_cast<int>(g.segments.size());
    g.segments.push_back(seg);
    g.segmentsAt[seg[0]].push_back(index);
    g.segmentsAt[seg[1]].push_back(index);
  }
  return g;
}

// Walks unused segments from @p start as far as possible.
Polyline walk(const CutGraph& g, int start, std::vector<char>& used) {
  Polyline line{g.points[start]};
  int at = start;
  while (true) {
    int next = -1;
    for (const int s : g.segmentsAt[at])
      if (!used[s]) {
        used[s] = 1;
        next = g.segments[s][0] == at ? g.segments[s][1] : g.segments[s][0];
        break;
      }
    if (next < 0) return line;
    line.push_back(g.points[next]);
    at = next;
  }
}

std::vector<Polyline> chain(const CutGraph& g) {
  std::vector<char> used(g.segments.size(), 0);
  std::vector<Polyline> lines;
  // Open chains start at points with an odd number of segments; what remains are loops.
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t p = 0; p < g.points.size(); ++p) {
      if (pass == 0 && g.segmentsAt[p].size() % 2 == 0) continue;
      while (std::any_of(g.segmentsAt[p].begin(), g.segmentsAt[p].end(),
                         [&](int s) { return !used[s]; }))
        lines.push_back(walk(g, static_cast<int>(p), used));
    }
  return lines;
}

// Pieces of @p line with 0 <= s <= length, cut exactly at the bounds.
std::vector<Polyline> clip(const Polyline& line, double length) {
  std::vector<Polyline> out;
  Polyline current;
  const auto inside = [&](const Vector2d& p) { return p.x() >= 0.0 && p.x() <= length; };
  for (std::size_t i = 0; i < line.size(); ++i) {
    const Vector2d& p = line[i];
    if (i > 0) {
      const Vector2d& q = line[i - 1];
      std::vector<double> at;  // parameters along q -> p where a bound is crossed
      for (const double bound : {0.0, length})
        if ((q.x() - bound) * (p.x() - bound) < 0.0)
          at.push_back((bound - q.x()) / (p.x() - q.x()));
      std::sort(at.begin(), at.end());
      bool in = inside(q);
      for (const double f : at) {
        current.push_back(q + f * (p - q));
        if (in) {
          if (current.size() >= 2) out.push_back(current);
          current.clear();
        }
        in = !in;
      }
    }
    if (inside(p)) current.push_back(p);
  }
  if (current.size() >= 2) out.push_back(current);
  return out;
}

}  // namespace

SectionPlane sectionPlaneFromView(const Vector3d& a, const Vector3d& b,
                                  const Vector3d& viewDirection) {
  if (!a.allFinite() || !b.allFinite() || !viewDirection.allFinite())
    throw InvalidInput("sectionPlaneFromView: a point or the view direction is not finite");
  const Vector3d ab = b - a;
  if (ab.norm() < 1e-9) throw InvalidInput("sectionPlaneFromView: the line has no length");
  SectionPlane plane;
  plane.origin = a;
  plane.sAxis = ab.normalized();
  const Vector3d towardsViewer = -(viewDirection - viewDirection.dot(plane.sAxis) * plane.sAxis);
  if (towardsViewer.norm() < 1e-9 * std::max(1.0, viewDirection.norm()))
    throw InvalidInput("sectionPlaneFromView: the view direction is parallel to the line");
  plane.tAxis = towardsViewer.normalized();
  plane.normal = plane.sAxis.cross(plane.tAxis);
  plane.lengthMm = ab.norm();
  return plane;
}

SectionPlane sectionPlaneFromNormal(const Vector3d& a, const Vector3d& b,
                                    const Vector3d& planeNormal) {
  if (!a.allFinite() || !b.allFinite() || !planeNormal.allFinite() || planeNormal.norm() == 0.0)
    throw InvalidInput("sectionPlaneFromNormal: a point or the normal is not finite or zero");
  SectionPlane plane;
  plane.origin = a;
  plane.normal = planeNormal.normalized();
  const Vector3d ab = b - a;
  const Vector3d inPlane = ab - ab.dot(plane.normal) * plane.normal;
  if (inPlane.norm() < 1e-9 * std::max(1.0, ab.norm()))
    throw InvalidInput("sectionPlaneFromNormal: the line is parallel to the normal");
  plane.sAxis = inPlane.normalized();
  plane.tAxis = plane.normal.cross(plane.sAxis);
  plane.lengthMm = inPlane.norm();
  return plane;
}

Vector3d sectionToWorld(const SectionPlane& plane, const Vector2d& st) {
  return plane.origin + st.x() * plane.sAxis + st.y() * plane.tAxis;
}

std::vector<std::vector<Vector2d>> sectionCurves(const ddf::TriangleMesh& mesh,
                                                 const SectionPlane& plane,
                                                 const SectionParams& params) {
  std::vector<Polyline> lines = chain(cutMesh(mesh, plane));
  if (params.clipToSegment) {
    std::vector<Polyline> clipped;
    for (const auto& line : lines)
      for (auto& piece : clip(line, plane.lengthMm)) clipped.push_back(std::move(piece));
    lines = std::move(clipped);
  }
  std::erase_if(lines, [](const Polyline& l) { return l.size() < 2; });
  for (auto& line : lines)
    if (line.back().x() < line.front().x()) std::reverse(line.begin(), line.end());
  std::sort(lines.begin(), lines.end(), [](const Polyline& x, const Polyline& y) {
    return x.front().x() != y.front().x() ? x.front().x() < y.front().x()
                                          : x.front().y() < y.front().y();
  });
  return lines;
}

}  // namespace ddfcam::planning
