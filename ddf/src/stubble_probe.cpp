// SPDX-License-Identifier: MIT
// ddfcam: dry-run V-shooting of a closed mesh against the stubbles of a DDF.
#include <ddfcam/ddf/stubble_probe.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ddfcam::ddf {
namespace {

struct ProbeTriangle {
  Vec3 a, e1, e2;
  Eigen::AlignedBox3d box;
  double scale = 0.0;  // |e1| |e2|
};

struct Hit {
  double h;
  bool entry;
};

struct ProbeMesh {
  std::vector<ProbeTriangle> triangles;
  Eigen::AlignedBox3d box;
  // Slack of the localization grid, mm: covers the barycentric edge tolerance of the hit test
  // and rounding, so the grid never drops a triangle the exhaustive test would accept.
  double margin = 0.0;
};

ProbeMesh placeMesh(const TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  const bool flip = mesh.signedVolume() < 0.0;
  ProbeMesh out;
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Vec3 a = pose * mesh.vertices[t[0]];
    const Vec3 b = pose * mesh.vertices[t[flip ? 2 : 1]];
    const Vec3 c = pose * mesh.vertices[t[flip ? 1 : 2]];
    ProbeTriangle pt{a, b - a, c - a, {}, (b - a).norm() * (c - a).norm()};
    pt.box.extend(a), pt.box.extend(b), pt.box.extend(c);
    out.box.extend(pt.box);
    out.triangles.push_back(pt);
  }
  out.margin = 1e-6 * out.box.diagonal().norm() + 1e-9;
  return out;
}

// Hit of the line g + h v with triangle @p t for h in (hMin, hMax], if any.
bool triangleHit(const ProbeTriangle& t, const Vec3& g, const Vec3& v, double vLength, double hMin,
                 double hMax, Hit& hit) {
  constexpr double kEdge = 1e-9;
  const Vec3 pv = v.cross(t.e2);
  const double det = t.e1.dot(pv);
  // A line (nearly) parallel to the triangle's plane: u and w would be ratios of rounding
  // noise, so it does not cross it (it meets the neighbouring faces instead).
  if (std::abs(det) <= 1e-12 * t.scale * vLength) return false;
  const Vec3 tv = g - t.a;
  const double u = tv.dot(pv) / det;
  if (u < -kEdge || u > 1.0 + kEdge) return false;
  const Vec3 qv = tv.cross(t.e1);
  const double w = v.dot(qv) / det;
  if (w < -kEdge || u + w > 1.0 + kEdge) return false;
  const double h = t.e2.dot(qv) / det;
  // det > 0 <=> v . ((q2 - q1) x (q3 - q1)) < 0: the line enters the mesh here.
  hit = {h, det > 0.0};
  return h > hMin && h <= hMax;
}

// Largest h at which the line g + h v is still in @p box (the exit of its slab test); no
// triangle of the mesh is met beyond it.
double boxExit(const Eigen::AlignedBox3d& box, const Vec3& g, const Vec3& v) {
  double exit = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (v[a] == 0.0) continue;
    exit = std::min(exit, ((v[a] > 0.0 ? box.max()[a] : box.min()[a]) - g[a]) / v[a]);
  }
  return exit;
}

/// Orthonormal axes of the plane perpendicular to a direction.
struct Frame {
  explicit Frame(const Vec3& d) : u(d.normalized().unitOrthogonal()), w(d.normalized().cross(u)) {}
  Eigen::Vector2d project(const Vec3& p) const { return {p.dot(u), p.dot(w)}; }
  Vec3 u, w;
};

struct Stubble {
  int i, k;
  Vec3 g, v;
  double vLength;
  Eigen::AlignedBox3d segment;  // g + h v, h in [-1, 1]
  Eigen::AlignedBox3d query;    // only triangles whose box meets it are tested
  double top;                   // triangles are gathered along h in [-1, top]
};

struct StubbleHit {
  int stubble, triangle;
  Hit hit;
};

// Stubbles of face @p f whose segment box meets the mesh box.
std::vector<Stubble> nearStubbles(const DisplacementField& ddf, int f, const ProbeMesh& mesh) {
  const Raster& raster = ddf.raster();
  std::vector<Stubble> out;
  out.reserve(raster.pointCount());
  for (int k = 0; k <= raster.steps(); ++k) {
    // g and v are affine along a row: its segments lie in the box of its end segments (grown
    // for rounding), so a row whose box misses the mesh box holds no candidate.
    Eigen::AlignedBox3d row;
    for (int i : {0, raster.rowLength(k) - 1}) {
      const Vec3 g = ddf.basePoint(f, ddf.rasterBary(i, k)),
                 v = ddf.vectorAt(f, ddf.rasterBary(i, k));
      row.extend(g - v), row.extend(g + v);
    }
    row.min().array() -= mesh.margin, row.max().array() += mesh.margin;
    if (!row.intersects(mesh.box)) continue;
    for (int i = 0; i < raster.rowLength(k); ++i) {
      const Vec3 bary = ddf.rasterBary(i, k);
      Stubble s{i, k, ddf.basePoint(f, bary), ddf.vectorAt(f, bary), 0.0, {}, {}, 1.0};
      s.segment = Eigen::AlignedBox3d(s.g - s.v);
      s.segment.extend(s.g + s.v);
      s.query = s.segment;  // as the exhaustive test filters segment hits
      if (!s.segment.intersects(mesh.box)) continue;
      s.vLength = s.v.norm();
      out.push_back(s);
    }
  }
  return out;
}

// x extent [x0, x1] of the projected triangle @p t within the band y0 <= y <= y1: its vertices
// in the band and its edges' crossings of the band's borders. False when it misses the band.
bool rowSpan(const Eigen::Vector2d (&t)[3], double y0, double y1, double& x0, double& x1) {
  x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
  for (int e = 0; e < 3; ++e) {
    const Eigen::Vector2d &p = t[e], &q = t[(e + 1) % 3];
    if (p.y() >= y0 && p.y() <= y1) x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
    for (double y : {y0, y1}) {
      if ((p.y() - y) * (q.y() - y) >= 0.0) continue;
      const double x = p.x() + (y - p.y()) / (q.y() - p.y()) * (q.x() - p.x());
      x0 = std::min(x0, x), x1 = std::max(x1, x);
    }
  }
  return x0 <= x1;
}

// The raster of one face seen along its mean vector: base points project affinely in (i, k),
// so a triangle's projection is scan-converted row by row over the raster (as the depth buffer
// does), grown by how far a segment g + h v, |h| <= hMax, strays from its base point's
// projection. A line meets a triangle only where their projections meet.
struct RasterScan {
  Frame frame;
  Eigen::Vector2d origin;
  Eigen::Matrix2d toRaster;             // plane offset from origin -> (i, k)
  double perp = 0.0;                    // largest |v| across the view direction over the face, mm
  Vec3 d;                               // unit view direction
  double g0 = 0.0, g1 = 0.0, w0 = 0.0;  // range of g . d, least v . d over the face
  double margin = 0.0;
  int n = 1;
  bool valid = false;

  RasterScan(const DisplacementField& ddf, int f, const Vec3& direction, double slack)
      : frame(direction), margin(slack), n(ddf.raster().steps()) {
    d = direction.normalized();
    Vec3 p[3];
    g0 = w0 = std::numeric_limits<double>::infinity(), g1 = -g0;
    for (int j = 0; j < 3; ++j) {
      p[j] = ddf.basePoint(f, Vec3::Unit(j));
      const Vec3 v = ddf.vectorAt(f, Vec3::Unit(j));
      perp = std::max(perp, (v - v.dot(d) * d).norm());
      g0 = std::min(g0, p[j].dot(d)), g1 = std::max(g1, p[j].dot(d)), w0 = std::min(w0, v.dot(d));
    }
    origin = frame.project(p[1]);
    Eigen::Matrix2d m;
    m.col(0) = frame.project(p[0] - p[1]) / n;
    m.col(1) = frame.project(p[2] - p[1]) / n;
    valid = std::abs(m.determinant()) > 1e-9 * m.col(0).norm() * m.col(1).norm();
    if (valid) toRaster = m.inverse();
  }

  // Calls @p visit(i, k) once for each raster point whose segment, |h| <= hMax, may meet @p t.
  template <class Visit>
  void forEachPoint(const ProbeTriangle& t, double hMax, const std::vector<Eigen::Vector2i>& rows,
                    Visit visit) const {
    // A hit at h lies at depth g . d + h v . d within the triangle's depth range along d.
    const double a = t.a.dot(d), b = (t.a + t.e1).dot(d), c = (t.a + t.e2).dot(d);
    const double t0 = std::min({a, b, c}) - margin, t1 = std::max({a, b, c}) + margin;
    if (w0 > 0.0) hMax = std::min(hMax, std::max(std::abs(t1 - g0), std::abs(t0 - g1)) / w0);
    const double grow = hMax * perp + 2.0 * margin;
    const Eigen::Vector2d q[3] = {toRaster * (frame.project(t.a) - origin),
                                  toRaster * (frame.project(t.a + t.e1) - origin),
                                  toRaster * (frame.project(t.a + t.e2) - origin)};
    const double di = grow * toRaster.row(0).norm(), dk = grow * toRaster.row(1).norm();
    const double kLo = std::min({q[0].y(), q[1].y(), q[2].y()}) - dk;
    const double kHi = std::max({q[0].y(), q[1].y(), q[2].y()}) + dk;
    const int k0 = static_cast<int>(std::ceil(std::clamp(kLo, 0.0, n + 1.0)));
    const int k1 = static_cast<int>(std::floor(std::clamp(kHi, -1.0, static_cast<double>(n))));
    for (int k = k0; k <= k1; ++k) {
      double x0, x1;
      if (rows[k].x() > rows[k].y() || !rowSpan(q, k - dk, k + dk, x0, x1)) continue;
      const int i0 =
          std::max(rows[k].x(), static_cast<int>(std::ceil(std::clamp(x0 - di, 0.0, n + 1.0))));
      const int i1 = std::min(
          rows[k].y(), static_cast<int>(std::floor(std::clamp(x1 + di, -1.0, double(n - k)))));
      for (int i = i0; i <= i1; ++i) visit(i, k);
    }
  }
};

// Every hit of the stubble lines g + h v (gathered for h in [-1, top]) with the mesh, grouped
// by stubble (group s is out[first[s] .. first[s + 1])), each group in triangle order as an
// exhaustive loop finds them. @p slot maps raster index -> stubble (-1: not probed).
void gatherHits(const std::vector<Stubble>& stubbles, const std::vector<int>& slot,
                const RasterScan& scan, const Raster& raster, const ProbeMesh& mesh,
                std::vector<StubbleHit>& out, std::vector<int>& first) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<StubbleHit> hits;
  hits.reserve(4 * stubbles.size());
  auto test = [&](int s, int id) {
    const Stubble& st = stubbles[s];
    if (!st.query.intersects(mesh.triangles[id].box)) return;
    Hit hit{};
    if (triangleHit(mesh.triangles[id], st.g, st.v, st.vLength, -1.0 - 1e-12, kInf, hit))
      hits.push_back({s, id, hit});
  };
  const int count = static_cast<int>(stubbles.size());
  double hMax = 1.0;
  Eigen::AlignedBox3d reach;  // every queried segment, grown by the margin
  for (const Stubble& s : stubbles) {
    hMax = std::max(hMax, s.top);
    reach.extend(s.g - s.v), reach.extend(s.g + s.top * s.v);
  }
  reach.min().array() -= mesh.margin, reach.max().array() += mesh.margin;
  std::vector<Eigen::Vector2i> rows(raster.steps() + 1, Eigen::Vector2i(raster.m, -1));  // i range
  for (const Stubble& s : stubbles)
    rows[s.k] = Eigen::Vector2i(std::min(rows[s.k].x(), s.i), std::max(rows[s.k].y(), s.i));
  for (int id = 0; id < static_cast<int>(mesh.triangles.size()); ++id) {
    if (!scan.valid || !std::isfinite(hMax)) {
      for (int s = 0; s < count; ++s) test(s, id);
    } else if (reach.intersects(mesh.triangles[id].box)) {
      scan.forEachPoint(mesh.triangles[id], hMax, rows, [&](int i, int k) {
        if (const int s = slot[raster.index(i, k)]; s >= 0) test(s, id);
      });
    }
  }
  // Stable counting sort by stubble keeps the triangle order within each group.
  first.assign(stubbles.size() + 1, 0);
  for (const StubbleHit& h : hits) ++first[h.stubble + 1];
  for (int s = 0; s < count; ++s) first[s + 1] += first[s];
  out.resize(hits.size());
  std::vector<int> cursor(first.begin(), first.end() - 1);
  for (const StubbleHit& h : hits) out[cursor[h.stubble]++] = h;
}

// Sorts @p hits by h and counts same-direction hits closer than @p merge (a line through a
// shared edge) once.
void sortAndMerge(std::vector<Hit>& hits, double merge, std::vector<Hit>& merged) {
  std::sort(hits.begin(), hits.end(), [](const Hit& x, const Hit& y) { return x.h < y.h; });
  merged.clear();
  for (const Hit& hit : hits) {
    bool duplicate = false;
    for (auto it = merged.rbegin(); it != merged.rend() && hit.h - it->h <= merge; ++it)
      duplicate = duplicate || it->entry == hit.entry;
    if (!duplicate) merged.push_back(hit);
  }
}

// Fills the interval fields of @p c from the sorted, merged, non-empty hits on the segment.
bool intervalsOf(const std::vector<Hit>& merged, StubbleCrossing& c) {
  bool inside = !merged.front().entry;
  double start = -1.0;
  c.intervals = 0;
  auto close = [&](double end) {
    if (c.intervals++ == 0) c.entry = static_cast<float>(start), c.exit = static_cast<float>(end);
  };
  for (const Hit& hit : merged) {
    if (hit.entry && !inside)
      start = hit.h, inside = true;
    else if (!hit.entry && inside)
      close(hit.h), inside = false;
  }
  if (inside) close(1.0);
  return c.intervals > 0;
}

// @p s extended to the ray g + h v, h in [-1, top], up to where it leaves the mesh box (grown by
// the margin; no triangle lies beyond): hits above the segment count from every triangle.
Stubble rayOf(const Stubble& s, const ProbeMesh& mesh) {
  Eigen::AlignedBox3d grown = mesh.box;
  grown.min().array() -= mesh.margin, grown.max().array() += mesh.margin;
  Stubble ray = s;
  ray.top = std::max(1.0, boxExit(grown, s.g, s.v));
  ray.query = Eigen::AlignedBox3d(s.g - s.v);
  ray.query.extend(s.g + ray.top * s.v);
  ray.query.min().array() -= mesh.margin, ray.query.max().array() += mesh.margin;
  if (!std::isfinite(ray.top)) ray.query = grown;
  return ray;
}

// Crossings of the stubbles of face @p f in raster order. Segment hits count only from triangles
// whose box meets the segment's. A segment without hits whose base point lies in the mesh box
// is inside iff the first hit above it is an exit: those lines are gathered up to the mesh box
// in a second pass (no triangle lies beyond it).
void probeFace(const DisplacementField& ddf, int f, const ProbeMesh& mesh, double merge,
               std::vector<StubbleCrossing>& out) {
  std::vector<Stubble> stubbles = nearStubbles(ddf, f, mesh);
  if (stubbles.empty()) return;
  const Raster& raster = ddf.raster();
  const RasterScan scan(ddf, f, ddf.vectorAt(f, Vec3::Constant(1.0 / 3.0)), mesh.margin);
  std::vector<int> slot(raster.pointCount(), -1);
  for (std::size_t s = 0; s < stubbles.size(); ++s)
    slot[raster.index(stubbles[s].i, stubbles[s].k)] = static_cast<int>(s);
  std::vector<StubbleHit> hits;
  std::vector<int> first;
  gatherHits(stubbles, slot, scan, raster, mesh, hits, first);
  std::vector<StubbleCrossing> found(stubbles.size());
  std::vector<char> crossed(stubbles.size(), 0);
  std::vector<Stubble> rays;
  std::vector<int> rayStubble;
  std::vector<Hit> list, merged;
  std::fill(slot.begin(), slot.end(), -1);
  for (std::size_t s = 0; s < stubbles.size(); ++s) {
    list.clear();
    for (int q = first[s]; q < first[s + 1]; ++q)
      if (hits[q].hit.h <= 1.0) list.push_back(hits[q].hit);
    sortAndMerge(list, merge, merged);
    if (!merged.empty()) {
      crossed[s] = intervalsOf(merged, found[s]);
    } else if (mesh.box.contains(stubbles[s].g)) {
      slot[raster.index(stubbles[s].i, stubbles[s].k)] = static_cast<int>(rays.size());
      rays.push_back(rayOf(stubbles[s], mesh));
      rayStubble.push_back(static_cast<int>(s));
    }
  }
  if (!rays.empty()) gatherHits(rays, slot, scan, raster, mesh, hits, first);
  for (std::size_t r = 0; r < rays.size(); ++r) {
    list.clear();
    for (int q = first[r]; q < first[r + 1]; ++q)
      if (hits[q].hit.h > 1.0) list.push_back(hits[q].hit);
    sortAndMerge(list, merge, merged);
    if (merged.empty() || merged.front().entry) continue;
    StubbleCrossing& c = found[rayStubble[r]];
    c.entry = -1.0f, c.exit = 1.0f, c.intervals = 1;
    crossed[rayStubble[r]] = 1;
  }
  const auto heights = ddf.heights(f);
  for (std::size_t s = 0; s < stubbles.size(); ++s) {
    if (!crossed[s]) continue;
    StubbleCrossing c = found[s];
    c.face = f;
    c.index = static_cast<std::uint32_t>(ddf.raster().index(stubbles[s].i, stubbles[s].k));
    c.point = ddf.topology().id(f, stubbles[s].i, stubbles[s].k);
    c.height = heights[c.index];
    out.push_back(c);
  }
}

}  // namespace

StubbleProbe probeStubbles(const DisplacementField& ddf, const CrustHash& hash,
                           const TriangleMesh& mesh, const Eigen::Isometry3d& pose,
                           const StubbleProbeParams& params) {
  StubbleProbe result;
  if (mesh.triangles.empty()) return result;
  const ProbeMesh placed = placeMesh(mesh, pose);
  std::vector<int> candidates, faces;
  hash.queryBox(placed.box, candidates);
  for (int f : candidates)
    if (CrustHash::crustBox(ddf, f).intersects(placed.box)) faces.push_back(f);
  result.candidateFaces = faces.size();
  std::vector<std::vector<StubbleCrossing>> perFace(faces.size());
  auto run = [&](std::size_t i) {
    probeFace(ddf, faces[i], placed, params.mergeTolerance, perFace[i]);
  };
  if (params.parallel && faces.size() > 1) {
    tbb::parallel_for(std::size_t{0}, faces.size(), run);
  } else {
    for (std::size_t i = 0; i < faces.size(); ++i) run(i);
  }
  for (auto& list : perFace)
    result.crossings.insert(result.crossings.end(), list.begin(), list.end());
  return result;
}

}  // namespace ddfcam::ddf
