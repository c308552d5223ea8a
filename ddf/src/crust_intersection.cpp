// SPDX-License-Identifier: MIT
// ddfcam: exact-enough intersection test of two support-triangle crusts (constraint 3).
#include <ddfcam/ddf/crust.h>
#include <ddfcam/ddf/v_projection.h>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace ddfcam::ddf {
namespace {

using Box = Eigen::AlignedBox3d;

/// Six times the signed volume of tetrahedron (a, b, c, d).
double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a);
}

bool segmentHitsTriangle(const Vec3& p, const Vec3& q, const SpaceTriangle& t) {
  const double dp = orient(t[0], t[1], t[2], p), dq = orient(t[0], t[1], t[2], q);
  if ((dp > 0.0 && dq > 0.0) || (dp < 0.0 && dq < 0.0)) return false;
  if (dp == 0.0 && dq == 0.0) return false;  // coplanar: not handled (measure zero)
  const double s1 = orient(p, q, t[0], t[1]);
  const double s2 = orient(p, q, t[1], t[2]);
  const double s3 = orient(p, q, t[2], t[0]);
  return (s1 >= 0.0 && s2 >= 0.0 && s3 >= 0.0) || (s1 <= 0.0 && s2 <= 0.0 && s3 <= 0.0);
}

Box boxOf(const SpaceTriangle& t) {
  Box b(t[0]);
  b.extend(t[1]);
  b.extend(t[2]);
  return b;
}

/// The crust's corners p_i - H v_i (0..2) and p_i + H v_i (3..5): the crust lies in their hull,
/// because p(mu) + h v(mu) = sum mu_i ((1-h/H)/2 (p_i - H v_i) + (1+h/H)/2 (p_i + H v_i)).
std::array<Vec3, 6> crustCorners(const DisplacementField& ddf, int face, double height) {
  const auto& fv = ddf.faceVertices(face);
  std::array<Vec3, 6> c;
  for (int i = 0; i < 3; ++i) {
    c[i] = ddf.position(fv[i]) - height * ddf.vector(fv[i]);
    c[i + 3] = ddf.position(fv[i]) + height * ddf.vector(fv[i]);
  }
  return c;
}

/// Candidate separating directions of one crust: support normal, in-plane edge normals and
/// the normals of the (planar-approximated) side walls; also its edge directions.
void crustAxes(const DisplacementField& ddf, int face, std::vector<Vec3>& axes,
               std::array<Vec3, 3>& edges) {
  const auto& fv = ddf.faceVertices(face);
  const Vec3 n =
      (ddf.position(fv[1]) - ddf.position(fv[0])).cross(ddf.position(fv[2]) - ddf.position(fv[0]));
  axes.push_back(n);
  for (int i = 0; i < 3; ++i) {
    const int a = fv[i], b = fv[(i + 1) % 3];
    edges[i] = ddf.position(b) - ddf.position(a);
    axes.push_back(n.cross(edges[i]));
    axes.push_back(edges[i].cross(ddf.vector(a) + ddf.vector(b)));
  }
}

bool separated(const std::array<Vec3, 6>& a, const std::array<Vec3, 6>& b, const Vec3& axis) {
  if (!(axis.squaredNorm() > 0.0)) return false;
  double amin = a[0].dot(axis), amax = amin, bmin = b[0].dot(axis), bmax = bmin;
  for (int i = 1; i < 6; ++i) {
    const double x = a[i].dot(axis), y = b[i].dot(axis);
    amin = std::min(amin, x), amax = std::max(amax, x);
    bmin = std::min(bmin, y), bmax = std::max(bmax, y);
  }
  return amax < bmin || bmax < amin;
}

bool hullsSeparated(const DisplacementField& ddf, int s, int t, const std::array<Vec3, 6>& cs,
                    const std::array<Vec3, 6>& ct) {
  std::vector<Vec3> axes;
  std::array<Vec3, 3> es, et;
  crustAxes(ddf, s, axes, es);
  crustAxes(ddf, t, axes, et);
  for (const Vec3& a : es)
    for (const Vec3& b : et) axes.push_back(a.cross(b));
  return std::any_of(axes.begin(), axes.end(),
                     [&](const Vec3& axis) { return separated(cs, ct, axis); });
}

Box boxOf(const std::array<Vec3, 6>& corners) {
  Box b(corners[0]);
  for (const Vec3& c : corners) b.extend(c);
  return b;
}

bool boundariesIntersect(const DisplacementField& ddf, int s, int t,
                         const CrustIntersectionParams& params, const Box& boxS, const Box& boxT) {
  const auto bs = crustBoundary(ddf, s, params.height, params.edgeSteps);
  const auto bt = crustBoundary(ddf, t, params.height, params.edgeSteps);
  std::vector<std::pair<SpaceTriangle, Box>> nearT;
  for (const auto& tri : bt) {
    const Box b = boxOf(tri);
    if (b.intersects(boxS)) nearT.emplace_back(tri, b);
  }
  for (const auto& tri : bs) {
    const Box b = boxOf(tri);
    if (!b.intersects(boxT)) continue;
    for (const auto& [other, otherBox] : nearT)
      if (b.intersects(otherBox) && trianglesIntersect(tri, other)) return true;
  }
  return false;
}

const Vec3 kCentroid = Vec3::Constant(1.0 / 3.0);

}  // namespace

bool trianglesIntersect(const SpaceTriangle& a, const SpaceTriangle& b) {
  if (!boxOf(a).intersects(boxOf(b))) return false;
  for (int i = 0; i < 3; ++i) {
    if (segmentHitsTriangle(a[i], a[(i + 1) % 3], b)) return true;
    if (segmentHitsTriangle(b[i], b[(i + 1) % 3], a)) return true;
  }
  return false;
}

std::vector<SpaceTriangle> crustBoundary(const DisplacementField& ddf, int face, double height,
                                         int edgeSteps) {
  const auto c = crustCorners(ddf, face, height);
  const auto& fv = ddf.faceVertices(face);
  std::vector<SpaceTriangle> out = {{c[0], c[2], c[1]}, {c[3], c[4], c[5]}};
  const int steps = std::max(1, edgeSteps);
  const std::array<double, 3> hs = {-height, 0.0, height};
  for (int e = 0; e < 3; ++e) {
    const int a = fv[e], b = fv[(e + 1) % 3];
    auto at = [&](int step, int row) {
      const double t = static_cast<double>(step) / steps;
      return Vec3((1.0 - t) * (ddf.position(a) + hs[row] * ddf.vector(a)) +
                  t * (ddf.position(b) + hs[row] * ddf.vector(b)));
    };
    for (int k = 0; k < steps; ++k)
      for (int r = 0; r < 2; ++r) {
        out.push_back({at(k, r), at(k + 1, r), at(k + 1, r + 1)});
        out.push_back({at(k, r), at(k + 1, r + 1), at(k, r + 1)});
      }
  }
  return out;
}

bool crustContains(const DisplacementField& ddf, int face, const Vec3& x, double height) {
  const auto sols = vProject(ddf, face, x);
  return std::any_of(sols.begin(), sols.end(), [&](const VProjection& p) {
    return p.inside && std::abs(p.h) <= height * (1.0 + 1e-9);
  });
}

bool crustsIntersect(const DisplacementField& ddf, int s, int t,
                     const CrustIntersectionParams& params) {
  const auto cs = crustCorners(ddf, s, params.height);
  const auto ct = crustCorners(ddf, t, params.height);
  const Box boxS = boxOf(cs), boxT = boxOf(ct);
  if (!boxS.intersects(boxT)) return false;
  if (hullsSeparated(ddf, s, t, cs, ct)) return false;
  if (boundariesIntersect(ddf, s, t, params, boxS, boxT)) return true;
  // No boundary crossing: the crusts are disjoint or one holds the other whole. Points on the
  // stubble of each centroid at three heights also catch crusts whose side walls are exactly
  // coplanar (stacked sheets with aligned triangulations), where crossing tests are blind.
  for (double h : {0.0, -params.height, params.height}) {
    if (crustContains(ddf, s, ddf.pointAt(t, kCentroid, h), params.height)) return true;
    if (crustContains(ddf, t, ddf.pointAt(s, kCentroid, h), params.height)) return true;
  }
  return false;
}

bool facesShareVertex(const DisplacementField& ddf, int s, int t,
                      std::span<const int> vertexClasses) {
  std::array<int, 3> a = ddf.faceVertices(s), b = ddf.faceVertices(t);
  if (!vertexClasses.empty())
    for (int i = 0; i < 3; ++i) a[i] = vertexClasses[a[i]], b[i] = vertexClasses[b[i]];
  return std::any_of(a.begin(), a.end(),
                     [&](int v) { return std::find(b.begin(), b.end(), v) != b.end(); });
}

std::vector<std::array<int, 2>> findCrustConflicts(const DisplacementField& ddf,
                                                   const CrustHash& hash,
                                                   std::span<const int> faces,
                                                   const CrustIntersectionParams& params,
                                                   std::span<const int> vertexClasses) {
  tbb::enumerable_thread_specific<std::vector<std::array<int, 2>>> found;
  tbb::enumerable_thread_specific<std::vector<int>> scratch;
  tbb::parallel_for(std::size_t{0}, faces.size(), [&](std::size_t i) {
    const int s = faces[i];
    auto& candidates = scratch.local();
    hash.queryCrust(s, candidates);
    for (int t : candidates) {
      if (facesShareVertex(ddf, s, t, vertexClasses) || !crustsIntersect(ddf, s, t, params))
        continue;
      found.local().push_back({std::min(s, t), std::max(s, t)});
    }
  });
  std::vector<std::array<int, 2>> out;
  for (const auto& local : found) out.insert(out.end(), local.begin(), local.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::array<int, 2>> findAllCrustConflicts(const DisplacementField& ddf,
                                                      const CrustHash& hash,
                                                      const CrustIntersectionParams& params,
                                                      std::span<const int> vertexClasses) {
  std::vector<int> all(ddf.faceCount());
  std::iota(all.begin(), all.end(), 0);
  return findCrustConflicts(ddf, hash, all, params, vertexClasses);
}

}  // namespace ddfcam::ddf
