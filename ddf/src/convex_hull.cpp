// SPDX-License-Identifier: MIT
// ddfcam: quickhull in 3D with conflict lists and a horizon found by depth-first search.
#include <ddfcam/ddf/convex_hull.h>
#include <ddfcam/error.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

namespace ddfcam::ddf {
namespace {

using Vec = Eigen::Vector3d;

struct HullFace {
  std::array<int, 3> v;          // counter-clockwise seen from outside
  std::array<int, 3> neighbour;  // face across edge v[e] -> v[(e + 1) % 3]
  Vec normal;                    // unit outward normal
  double offset = 0.0;           // normal . x for x on the plane
  std::vector<int> outside;      // points above the plane by more than the tolerance
  bool alive = true;
  bool visible = false;
};

struct HorizonEdge {
  int a, b;       // directed as in the visible face that owns it
  int otherFace;  // the face that stays
};

class QuickHull {
 public:
  QuickHull(std::span<const Vec> points, double tolerance) : p_(points), eps_(tolerance) {}

  TriangleMesh run() {
    buildSimplex();
    for (;;) {
      const int f = faceWithOutsidePoints();
      if (f < 0) break;
      addPoint(f);
    }
    return extract();
  }

 private:
  double distance(const HullFace& f, int i) const { return f.normal.dot(p_[i]) - f.offset; }

  int makeFace(int a, int b, int c) {
    HullFace f;
    f.v = {a, b, c};
    f.neighbour = {-1, -1, -1};
    const Vec n = (p_[b] - p_[a]).cross(p_[c] - p_[a]);
    f.normal = n.normalized();
    f.offset = f.normal.dot(p_[a]);
    faces_.push_back(std::move(f));
    return static_cast<int>(faces_.size()) - 1;
  }

  void buildSimplex();
  void assignOutside(const std::vector<int>& candidates, const std::vector<int>& newFaces);
  int faceWithOutsidePoints() {
    for (; cursor_ < static_cast<int>(faces_.size()); ++cursor_)
      if (faces_[cursor_].alive && !faces_[cursor_].outside.empty()) return cursor_;
    return -1;
  }
  void collectHorizon(int face, int eye, std::vector<HorizonEdge>& horizon,
                      std::vector<int>& visibleFaces);
  void addPoint(int face);
  void link(int f, int e, int g);
  TriangleMesh extract() const;

  std::span<const Vec> p_;
  double eps_;
  std::vector<HullFace> faces_;
  int cursor_ = 0;
};

int edgeOf(const HullFace& f, int a, int b) {
  for (int e = 0; e < 3; ++e)
    if (f.v[e] == a && f.v[(e + 1) % 3] == b) return e;
  return -1;
}

void QuickHull::link(int f, int e, int g) {
  faces_[f].neighbour[e] = g;
  const int a = faces_[f].v[e], b = faces_[f].v[(e + 1) % 3];
  const int ge = edgeOf(faces_[g], b, a);
  if (ge < 0) throw Error("convexHull: inconsistent hull topology");
  faces_[g].neighbour[ge] = f;
}

void QuickHull::buildSimplex() {
  const int n = static_cast<int>(p_.size());
  // Two points far apart along the axis of largest extent, the point farthest from their line,
  // the point farthest from their plane.
  int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      if (p_[i][a] < p_[lo[a]][a]) lo[a] = i;
      if (p_[i][a] > p_[hi[a]][a]) hi[a] = i;
    }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (p_[hi[a]][a] - p_[lo[a]][a] > p_[hi[axis]][axis] - p_[lo[axis]][axis]) axis = a;
  const int i0 = lo[axis], i1 = hi[axis];
  const Vec dir = (p_[i1] - p_[i0]).normalized();
  int i2 = -1;
  double best = eps_;
  for (int i = 0; i < n; ++i) {
    const double d = (p_[i] - p_[i0]).cross(dir).norm();
    if (d > best) best = d, i2 = i;
  }
  if (i2 < 0 || (p_[i1] - p_[i0]).norm() <= eps_)
    throw InvalidInput("convexHull: the " + std::to_string(n) + " points are collinear");
  const Vec pn = (p_[i1] - p_[i0]).cross(p_[i2] - p_[i0]).normalized();
  int i3 = -1;
  best = eps_;
  for (int i = 0; i < n; ++i) {
    const double d = std::abs(pn.dot(p_[i] - p_[i0]));
    if (d > best) best = d, i3 = i;
  }
  if (i3 < 0) throw InvalidInput("convexHull: the " + std::to_string(n) + " points are coplanar");
  // Orient so that i3 lies below the base face (i0, i1, i2).
  int a = i0, b = i1, c = i2;
  if (pn.dot(p_[i3] - p_[i0]) > 0.0) std::swap(b, c);
  const int f0 = makeFace(a, b, c), f1 = makeFace(a, i3, b), f2 = makeFace(b, i3, c),
            f3 = makeFace(c, i3, a);
  link(f0, 0, f1), link(f0, 1, f2), link(f0, 2, f3);
  link(f1, 1, f2), link(f2, 1, f3), link(f3, 1, f1);
  std::vector<int> all;
  all.reserve(n);
  for (int i = 0; i < n; ++i)
    if (i != i0 && i != i1 && i != i2 && i != i3) all.push_back(i);
  assignOutside(all, {f0, f1, f2, f3});
}

void QuickHull::assignOutside(const std::vector<int>& candidates,
                              const std::vector<int>& newFaces) {
  for (int i : candidates)
    for (int f : newFaces)
      if (distance(faces_[f], i) > eps_) {
        faces_[f].outside.push_back(i);
        break;
      }
}

// Walk over the faces the eye sees (a connected cap); the edges to faces it does not see form
// the horizon. Their order does not matter: the fan is linked through the horizon vertices.
void QuickHull::collectHorizon(int face, int eye, std::vector<HorizonEdge>& horizon,
                               std::vector<int>& visibleFaces) {
  faces_[face].visible = true;
  visibleFaces.push_back(face);
  std::vector<int> stack{face};
  while (!stack.empty()) {
    const int fi = stack.back();
    stack.pop_back();
    for (int e = 0; e < 3; ++e) {
      const int g = faces_[fi].neighbour[e];
      if (faces_[g].visible) continue;
      if (distance(faces_[g], eye) > eps_) {
        faces_[g].visible = true;
        visibleFaces.push_back(g);
        stack.push_back(g);
      } else {
        horizon.push_back({faces_[fi].v[e], faces_[fi].v[(e + 1) % 3], g});
      }
    }
  }
}

void QuickHull::addPoint(int face) {
  HullFace& f = faces_[face];
  int eye = f.outside.front();
  double far = distance(f, eye);
  for (int i : f.outside)
    if (const double d = distance(f, i); d > far) far = d, eye = i;
  std::vector<HorizonEdge> horizon;
  std::vector<int> visibleFaces;
  collectHorizon(face, eye, horizon, visibleFaces);
  std::vector<int> orphans;
  for (int v : visibleFaces) {
    faces_[v].alive = false;
    for (int i : faces_[v].outside)
      if (i != eye) orphans.push_back(i);
    faces_[v].outside.clear();
    faces_[v].outside.shrink_to_fit();
  }
  std::vector<int> fan;
  for (const HorizonEdge& h : horizon) {
    fan.push_back(makeFace(h.a, h.b, eye));
    link(fan.back(), 0, h.otherFace);
  }
  // The horizon is short, so the fan is linked by a linear search for the face that starts
  // where this one's horizon edge ends: edge (b, eye) against edge (eye, b) of that face.
  for (int nf : fan) {
    int next = -1;
    for (int other : fan)
      if (faces_[other].v[0] == faces_[nf].v[1]) {
        if (next >= 0) throw Error("convexHull: horizon is not a simple cycle");
        next = other;
      }
    if (next < 0) throw Error("convexHull: horizon is not closed");
    faces_[nf].neighbour[1] = next;
    faces_[next].neighbour[2] = nf;
  }
  assignOutside(orphans, fan);
}

TriangleMesh QuickHull::extract() const {
  TriangleMesh mesh;
  std::unordered_map<int, int> index;
  for (const HullFace& f : faces_) {
    if (!f.alive) continue;
    std::array<int, 3> t;
    for (int c = 0; c < 3; ++c) {
      const auto [it, inserted] = index.emplace(f.v[c], static_cast<int>(mesh.vertices.size()));
      if (inserted) mesh.vertices.push_back(p_[f.v[c]]);
      t[c] = it->second;
    }
    mesh.triangles.push_back(t);
  }
  return mesh;
}

}  // namespace

TriangleMesh convexHull(std::span<const Eigen::Vector3d> points, const ConvexHullParams& params) {
  if (points.size() < 4)
    throw InvalidInput("convexHull: needs at least 4 points, got " + std::to_string(points.size()));
  Eigen::AlignedBox3d box;
  for (const Vec& p : points) box.extend(p);
  const double diagonal = box.diagonal().norm();
  const double tolerance = std::max(params.relativeTolerance * diagonal,
                                    1e-14 * std::max(1.0, box.max().cwiseAbs().maxCoeff()));
  return QuickHull(points, tolerance).run();
}

}  // namespace ddfcam::ddf
