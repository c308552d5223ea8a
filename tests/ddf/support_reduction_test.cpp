// SPDX-License-Identifier: MIT
// Support reduction by constrained edge contraction (dissertation sec. 6.1-6.2): each
// constraint refuses a constructed contraction, and switching it off lets it through.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/pseudo_normals.h>
#include <ddfcam/ddf/support_reduction.h>
#include <ddfcam/ddf/v_shooting.h>
#include <ddfcam/ddf/validation.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>

#include "../support/brute_force_distance.h"
#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

TriangleMesh toTriangleMesh(const SupportMesh& mesh) {
  TriangleMesh out;
  for (const auto vh : mesh.vertices()) out.vertices.push_back(toEigen(mesh.point(vh)));
  for (const auto fh : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (const auto vh : mesh.fv_range(fh)) t[k++] = vh.idx();
    out.triangles.push_back(t);
  }
  return out;
}

SupportMesh toSupport(const TriangleMesh& mesh) {
  return makeSupportMesh(mesh.vertices, mesh.triangles);
}

/// Every constraint off: the plain contraction of sec. 6.1 (critical, boundary and fold-over
/// refusals stay).
SupportReductionParams unconstrained(int m = 10) {
  SupportReductionParams p;
  p.resolution = m;
  p.requireInputCoverage = p.requireRayCoverage = p.requireContainment = false;
  p.requireUniqueProjection = p.requireAngleBound = false;
  p.featureAngleDeg = 180.0;
  return p;
}

std::vector<Vec3> normalsOf(const SupportMesh& mesh) {
  return pseudoNormals(mesh).normals;
}

/// z = f(x, y) on [0, size]^2 as a grid of n x n cells, with unit pseudo-normals.
struct Sheet {
  SupportMesh mesh;
  std::vector<Vec3> vectors;
};
Sheet sheet(int n, double size, const std::function<double(double, double)>& f) {
  Sheet s;
  s.mesh = toSupport(test::heightFieldMesh(0, size, 0, size, n, n, f));
  s.vectors = normalsOf(s.mesh);
  return s;
}

std::vector<Vec3> scaled(std::vector<Vec3> v, double length) {
  for (Vec3& x : v) x = x.normalized() * length;
  return v;
}

/// Brute-force oracle of constraint (a): every input triangle is a nearest hit (|h| <= 1, ties
/// within 1e-9 all count) of some V-ray from a raster point of the reduced support; with
/// @p anyHit, every hit within the crust counts (the item sets of sec. 6.2).
int unhitInputTriangles(const SupportReductionResult& r, const TriangleMesh& input, int m,
                        bool anyHit = false) {
  const DisplacementField ddf(r.support, r.vectors, m);
  std::vector<char> hit(input.triangles.size(), 0);
  const int n = m - 1;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        std::vector<double> h(input.triangles.size(), 2.0);
        for (std::size_t t = 0; t < input.triangles.size(); ++t) {
          const auto& tri = input.triangles[t];
          const auto shot = vShoot(ddf, f, ddf.rasterBary(i, k), input.vertices[tri[0]],
                                   input.vertices[tri[1]], input.vertices[tri[2]]);
          if (shot && shot->lambda.minCoeff() >= -1e-7 && std::abs(shot->h) <= 1.0)
            h[t] = std::abs(shot->h);
        }
        const double best = *std::min_element(h.begin(), h.end());
        for (std::size_t t = 0; t < h.size(); ++t)
          hit[t] |= best <= 1.0 && h[t] <= (anyHit ? 1.0 : best + 1e-9);
      }
  return static_cast<int>(std::count(hit.begin(), hit.end(), 0));
}

TEST(SupportReduction, RejectsBadInput) {
  const SupportMesh grid = test::gridMesh(2, 2);
  EXPECT_THROW(reduceSupport(grid, std::vector<Vec3>(3, Vec3::UnitZ())), InvalidInput);
  EXPECT_THROW(reduceSupport(grid, test::constantVectors(grid), std::vector<int>{1, 2}),
               InvalidInput);
  SupportReductionParams p;
  p.resolution = 1;
  EXPECT_THROW(reduceSupport(grid, test::constantVectors(grid), {}, p), InvalidInput);
  p = {};
  p.progress = [](double) { return false; };
  EXPECT_THROW(reduceSupport(grid, test::constantVectors(grid), {}, p), Cancelled);
}

TEST(SupportReduction, TetrahedronEdgesAreCriticalAndNeverContracted) {
  const SupportMesh tet = makeSupportMesh({{-1, -1, -1}, {3, -1, -1}, {-1, 3, -1}, {-1, -1, 3}},
                                          {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  const auto r = reduceSupport(tet, test::radialVectors(tet), {}, unconstrained());
  EXPECT_EQ(r.report.contractions, 0);
  EXPECT_EQ(r.report.rejectedCritical, 6);
  EXPECT_EQ(r.support.n_faces(), 4u);
}

TEST(SupportReduction, PyramidBaseEdgesAreCritical) {
  // One grid triangle (a, b, c) split at a raised apex x (fig. 6.5): a-b-c is now a 3-cycle
  // that is no face, so contracting a base edge would make two side triangles coincide.
  TriangleMesh g = test::heightFieldMesh(0, 6, 0, 6, 6, 6, [](double, double) { return 0.0; });
  const int split = 2 * (2 * 6 + 2);
  const auto tri = g.triangles[split];
  g.vertices.push_back((g.vertices[tri[0]] + g.vertices[tri[1]] + g.vertices[tri[2]]) / 3.0 +
                       Vec3(0, 0, 3.0));
  const int x = static_cast<int>(g.vertices.size()) - 1;
  g.triangles[split] = {tri[0], tri[1], x};
  g.triangles.push_back({tri[1], tri[2], x});
  g.triangles.push_back({tri[2], tri[0], x});
  const SupportMesh mesh = toSupport(g);
  // Every other edge is refused for its length, so nothing else changes the configuration.
  auto p = unconstrained();
  p.maxEdgeMm = 0.5;
  const auto r = reduceSupport(mesh, normalsOf(mesh), {}, p);
  EXPECT_EQ(r.report.rejectedCritical, 3);
  EXPECT_EQ(r.report.contractions, 0);
  for (const auto vh : r.support.vertices()) EXPECT_TRUE(r.support.is_manifold(vh));
  const auto report = validate(DisplacementField(r.support, r.vectors, 2), [] {
    ValidationParams v;
    v.checkNonAdjacent = false;
    v.minCrustHeight = 0.0;
    return v;
  }());
  EXPECT_EQ(report.count(1), 0) << "no fold-over or degenerate face";
}

TEST(SupportReduction, BoundaryAndLabelBordersAreKeptExactly) {
  const SupportMesh grid = test::gridMesh(8, 8, 1.0, 1.0);
  std::vector<int> labels;
  for (const auto fh : grid.faces()) {
    Vec3 c = Vec3::Zero();
    for (const auto vh : grid.fv_range(fh)) c += toEigen(grid.point(vh)) / 3.0;
    labels.push_back(c.x() < 4.0 ? 0 : 1);
  }
  const auto r = reduceSupport(grid, test::constantVectors(grid), labels, unconstrained());
  EXPECT_LT(r.support.n_faces(), grid.n_faces());
  EXPECT_GT(r.report.rejectedBoundary, 0);
  std::set<std::array<double, 3>> kept;
  for (const auto vh : r.support.vertices()) {
    const auto p = r.support.point(vh);
    kept.insert({p[0], p[1], p[2]});
  }
  for (const auto vh : grid.vertices()) {
    const auto p = grid.point(vh);
    const bool border = grid.is_boundary(vh) || p[0] == 4.0;
    if (border) {
      EXPECT_TRUE(kept.count({p[0], p[1], p[2]})) << p[0] << " " << p[1];
    }
  }
  ASSERT_EQ(r.faceLabels.size(), r.support.n_faces());
  for (const auto fh : r.support.faces()) {
    Vec3 c = Vec3::Zero();
    for (const auto vh : r.support.fv_range(fh)) c += toEigen(r.support.point(vh)) / 3.0;
    EXPECT_EQ(r.faceLabels[fh.idx()], c.x() < 4.0 ? 0 : 1);
  }
}

TEST(SupportReduction, InputCoverageKeepsEveryInputTriangleHit) {
  // At m = 4 each input triangle is hit only by its own centroid at first; a coarser support
  // samples the plane more sparsely and would skip small triangles.
  Sheet s = sheet(8, 8.0, [](double, double) { return 0.0; });
  auto p = unconstrained(4);
  p.requireInputCoverage = true;
  const auto on = reduceSupport(s.mesh, s.vectors, {}, p);
  EXPECT_GT(on.report.rejectedInputCoverage, 0);
  const TriangleMesh input = toTriangleMesh(s.mesh);
  EXPECT_EQ(unhitInputTriangles(on, input, 4), 0);
  const auto off = reduceSupport(s.mesh, s.vectors, {}, unconstrained(4));
  EXPECT_GT(off.report.contractions, on.report.contractions);
  EXPECT_GT(unhitInputTriangles(off, input, 4), 0) << "the oracle sees what (a) prevents";
}

TEST(SupportReduction, InputCoverageHoldsOnACurvedSheetAtCoarseRasters) {
  // A saddle at m = 5: the faces grow to many input triangles each, and the culling of rows
  // and points per item must keep every hit the brute-force V-shooting finds.
  Sheet s = sheet(10, 10.0, [](double x, double y) { return 0.08 * (x - 5.0) * (y - 5.0); });
  s.vectors = scaled(s.vectors, 0.6);
  auto p = unconstrained(5);
  p.requireInputCoverage = true;
  const auto on = reduceSupport(s.mesh, s.vectors, {}, p);
  EXPECT_GT(on.report.rejectedInputCoverage, 0);
  EXPECT_GT(on.report.contractions, 0);
  EXPECT_EQ(unhitInputTriangles(on, toTriangleMesh(s.mesh), 5, true), 0);
}

TEST(SupportReduction, RayCoverageRefusesRaysFallingShortOfTheInput) {
  // Short vectors on a curved sheet: the raster points of a chord face lie further below the
  // input than one vector length, so their V-rays end (|h| = 1) before they reach it.
  Sheet s = sheet(6, 6.0, [](double x, double y) { return 0.3 * (x * x + y * y) / 6.0; });
  s.vectors = scaled(s.vectors, 0.02);
  auto p = unconstrained();
  p.requireRayCoverage = true;
  const auto on = reduceSupport(s.mesh, s.vectors, {}, p);
  EXPECT_GT(on.report.rejectedRayCoverage, 0);
  const auto off = reduceSupport(s.mesh, s.vectors, {}, unconstrained());
  EXPECT_GT(off.report.contractions, on.report.contractions);
  // The oracle: every raster point of the result reaches the input (fill misses none).
  DisplacementField ddf(on.support, on.vectors, p.resolution);
  EXPECT_EQ(fillFromMesh(ddf, CrustHash(ddf), toTriangleMesh(s.mesh)).missing, 0u);
}

TEST(SupportReduction, ContainmentRefusesItemsOutsideTheCrust) {
  // Short vectors on a curved sheet: the chord of a contraction lies further from the input
  // than one vector length, so input vertices V-project outside the +-1 crust.
  Sheet s = sheet(6, 6.0, [](double x, double y) { return 0.3 * (x * x + y * y) / 6.0; });
  s.vectors = scaled(s.vectors, 0.02);
  auto p = unconstrained();
  p.requireContainment = true;
  const auto on = reduceSupport(s.mesh, s.vectors, {}, p);
  EXPECT_GT(on.report.rejectedContainment, 0);
  const auto off = reduceSupport(s.mesh, s.vectors, {}, unconstrained());
  EXPECT_GT(off.report.contractions, on.report.contractions);
}

TEST(SupportReduction, UniqueProjectionRefusesCrustsReachingTheOtherSheet) {
  // A thin closed slab: the two big sheets are 0.2 mm apart, far apart in the mesh.
  // Refine the top and bottom by a grid each; the sides stay coarse.
  TriangleMesh slab;
  const int n = 6;
  const auto at = [&](int i, int j, int z) { return z * (n + 1) * (n + 1) + j * (n + 1) + i; };
  for (int z = 0; z < 2; ++z)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) slab.vertices.emplace_back(i, j, 0.2 * z);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      slab.triangles.push_back({at(i, j, 1), at(i + 1, j, 1), at(i + 1, j + 1, 1)});
      slab.triangles.push_back({at(i, j, 1), at(i + 1, j + 1, 1), at(i, j + 1, 1)});
      slab.triangles.push_back({at(i, j, 0), at(i + 1, j + 1, 0), at(i + 1, j, 0)});
      slab.triangles.push_back({at(i, j, 0), at(i, j + 1, 0), at(i + 1, j + 1, 0)});
    }
  const auto side = [&](int a0, int a1, int b0, int b1) {  // quad a0 a1 (bottom), b1 b0 (top)
    slab.triangles.push_back({a0, a1, b1});
    slab.triangles.push_back({a0, b1, b0});
  };
  for (int i = 0; i < n; ++i) {
    side(at(i, 0, 0), at(i + 1, 0, 0), at(i, 0, 1), at(i + 1, 0, 1));
    side(at(i + 1, n, 0), at(i, n, 0), at(i + 1, n, 1), at(i, n, 1));
    side(at(0, i + 1, 0), at(0, i, 0), at(0, i + 1, 1), at(0, i, 1));
    side(at(n, i, 0), at(n, i + 1, 0), at(n, i, 1), at(n, i + 1, 1));
  }
  const SupportMesh mesh = toSupport(slab);
  auto p = unconstrained();
  p.requireUniqueProjection = true;
  const auto on = reduceSupport(mesh, normalsOf(mesh), {}, p);
  EXPECT_GT(on.report.rejectedUniqueProjection, 0);
  const DisplacementField ddf(on.support, on.vectors, 2);
  EXPECT_TRUE(validate(ddf).ok()) << validate(ddf).issues.front().message;
  // Without the constraint the given unit vectors are averaged and kept: crusts cross.
  const auto off = reduceSupport(mesh, normalsOf(mesh), {}, unconstrained());
  EXPECT_GT(off.report.contractions, on.report.contractions);
}

TEST(SupportReduction, AngleBoundRefusesSteepFlanks) {
  // A roof: two flanks at 50 degrees meeting at the ridge x = 3. The ridge vertices' vectors
  // are vertical, 50 degrees off the flank normals.
  Sheet s = sheet(
      6, 6.0, [](double x, double) { return -std::tan(50.0 * M_PI / 180) * std::abs(x - 3.0); });
  s.vectors = scaled(s.vectors, 0.5);
  auto p = unconstrained();
  p.requireAngleBound = true;
  const auto on = reduceSupport(s.mesh, s.vectors, {}, p);
  EXPECT_GT(on.report.rejectedAngle, 0);
  const auto off = reduceSupport(s.mesh, s.vectors, {}, unconstrained());
  EXPECT_GT(off.report.contractions, on.report.contractions);
}

TEST(SupportReduction, FeatureEdgesAreKeptLikeBorders) {
  // The same roof: its ridge is a 100 degree crease. With the feature rule every ridge vertex
  // survives in place; without it the ridge is contracted away.
  const Sheet s = sheet(
      6, 6.0, [](double x, double) { return -std::tan(50.0 * M_PI / 180) * std::abs(x - 3.0); });
  const auto ridgeVerticesKept = [&](const SupportReductionResult& r) {
    int kept = 0;
    for (int j = 0; j <= 6; ++j) {
      const Vec3 ridge(3.0, j, 0.0);
      for (const auto vh : r.support.vertices())
        if ((toEigen(r.support.point(vh)) - ridge).norm() < 1e-12) ++kept;
    }
    return kept;
  };
  auto p = unconstrained();
  p.featureAngleDeg = 40.0;
  const auto on = reduceSupport(s.mesh, s.vectors, {}, p);
  EXPECT_EQ(ridgeVerticesKept(on), 7);
  const auto off = reduceSupport(s.mesh, s.vectors, {}, unconstrained());
  EXPECT_LT(ridgeVerticesKept(off), 7);
  EXPECT_GT(off.report.contractions, on.report.contractions);
}

/// The reduced sphere with heights filled from the input represents the input and is valid.
TEST(SupportReduction, ReducedSphereRepresentsTheInput) {
  SphereParams sp;
  sp.subdivisions = 3;
  sp.m = 2;
  const GeneratedSurface sphere = spherePart(sp);
  const SupportMesh& input = sphere.ddf.support();
  const int m = 10;
  SupportReductionParams p;
  p.resolution = m;
  const auto r = reduceSupport(input, normalsOf(input), {}, p);
  EXPECT_LT(r.report.supportFaces, static_cast<int>(input.n_faces()) / 2);
  EXPECT_GT(r.report.contractions, 0);
  DisplacementField ddf(r.support, r.vectors, m);
  const TriangleMesh surface = toTriangleMesh(input);
  const FillReport fill = fillFromMesh(ddf, CrustHash(ddf), surface);
  EXPECT_EQ(fill.missing, 0u);
  double worst = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k < m; ++k)
      for (int i = 0; i < m - k; ++i)
        worst = std::max(worst, test::meshDistance(surface, ddf.surfacePoint(f, i, k)));
  EXPECT_LT(worst, 1e-4 * sp.radiusMm);
  const auto report = validate(ddf);
  EXPECT_TRUE(report.ok()) << (report.issues.empty() ? "" : report.issues[0].message);
  EXPECT_EQ(unhitInputTriangles(r, surface, m), 0);
}

}  // namespace
}  // namespace ddfcam::ddf
