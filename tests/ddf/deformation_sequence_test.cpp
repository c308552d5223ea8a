// SPDX-License-Identifier: MIT
// Tests of the deformation sequence (ch. 9, fig. 9.5) against analytic planes, cylinders and
// spheres, and brute-force distances on the shared springback pair.
#include <ddfcam/ddf/crust.h>
#include <ddfcam/ddf/deformation_sequence.h>
#include <ddfcam/ddf/pseudo_normals.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>

#include "../support/brute_force_distance.h"
#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

constexpr double kPi = std::numbers::pi;

TriangleMesh toTriangleMesh(const SupportMesh& mesh) {
  TriangleMesh out;
  for (const auto vh : mesh.vertices()) out.vertices.push_back(toEigen(mesh.point(vh)));
  for (const auto fh : mesh.faces()) {
    std::array<int, 3> t{};
    int c = 0;
    for (const auto vh : mesh.fv_range(fh)) t[c++] = vh.idx();
    out.triangles.push_back(t);
  }
  return out;
}

// Cylinder of radius r around the z axis, z in [z0, z1], @p na x @p nz quads; triangles face
// the axis when @p inward.
TriangleMesh cylinder(double r, int na, int nz, double z0, double z1, bool inward) {
  TriangleMesh mesh;
  for (int z = 0; z <= nz; ++z)
    for (int a = 0; a < na; ++a) {
      const double phi = 2 * kPi * a / na;
      mesh.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), z0 + (z1 - z0) * z / nz);
    }
  auto at = [&](int a, int z) { return z * na + (a % na); };
  for (int z = 0; z < nz; ++z)
    for (int a = 0; a < na; ++a) {
      const std::array<int, 3> t1{at(a, z), at(a, z + 1), at(a + 1, z + 1)};
      const std::array<int, 3> t2{at(a, z), at(a + 1, z + 1), at(a + 1, z)};
      mesh.triangles.push_back(inward ? t1 : std::array<int, 3>{t1[0], t1[2], t1[1]});
      mesh.triangles.push_back(inward ? t2 : std::array<int, 3>{t2[0], t2[2], t2[1]});
    }
  return mesh;
}

// Icosphere of radius r, outward, @p levels subdivisions.
TriangleMesh sphere(double r, int levels) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  TriangleMesh mesh;
  mesh.vertices = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                   {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = mid.find(key); it != mid.end()) return it->second;
      mesh.vertices.push_back((mesh.vertices[a] + mesh.vertices[b]) / 2);
      return mid[key] = static_cast<int>(mesh.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : mesh.triangles) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.insert(next.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
    }
    mesh.triangles = std::move(next);
  }
  for (auto& v : mesh.vertices) v = v.normalized() * r;
  return mesh;
}

TriangleMesh flipped(TriangleMesh mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

// A mould DDF on @p mesh with its pseudo-normals (unit length), resolution m.
DisplacementField mouldOn(const TriangleMesh& mesh, int m) {
  const SupportMesh support = makeSupportMesh(mesh.vertices, mesh.triangles);
  return DisplacementField(support, pseudoNormals(support).normals, m);
}

// Calls fn(index, g, face) for every raster point copy of @p ddf, g its support point.
template <class Fn>
void forEachCopy(const DisplacementField& ddf, Fn&& fn) {
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i)
        fn(f * ddf.pointsPerFace() + ddf.raster().index(i, k),
           ddf.basePoint(f, ddf.rasterBary(i, k)), f);
}

TEST(DeformationSequence, ParallelPlaneIsOneExactStage) {
  const double d = 3.0;
  const SupportMesh grid = test::gridMesh(6, 6, 2.0, 2.0);
  const DisplacementField mould(grid, test::constantVectors(grid, {0, 0, 2}), 4);
  TriangleMesh plane = toTriangleMesh(test::gridMesh(4, 4, 5.0, 5.0));
  for (auto& v : plane.vertices) v += Vec3(-4, -4, d);
  const auto seq = buildDeformationSequence(mould, plane);
  ASSERT_EQ(seq.stages.size(), 1u);
  EXPECT_TRUE(seq.crossingFaces.empty());
  EXPECT_TRUE(seq.unresolvedFaces.empty());
  EXPECT_EQ(seq.missingPoints, 0u);
  EXPECT_EQ(seq.stages[0].fraction, 1.0);
  const DisplacementField& stage = seq.stages[0].ddf;
  EXPECT_NEAR(stage.vector(0).norm(), 1.25 * d, 1e-9);  // automatic reach
  for (const double lambda : {-0.5, 0.0, 0.3, 1.0, 1.7}) {
    const auto morph = morphPositions(seq, lambda);
    forEachCopy(stage, [&](std::size_t i, const Vec3& g, int) {
      EXPECT_LT((morph[i] - (g + Vec3(0, 0, lambda * d))).norm(), 1e-5) << i;
    });
  }
  forEachCopy(stage, [&](std::size_t i, const Vec3& g, int f) {
    EXPECT_LT((seq.deformedPoints[i] - (g + Vec3(0, 0, d))).norm(), 1e-5);
    const float h = stage.allHeights()[i];
    EXPECT_NEAR(h * stage.vectorAt(f, Vec3(1, 0, 0)).norm(), d, 1e-5);
  });
}

// Angle of a point around the z axis.
double angleOf(const Vec3& p) {
  return std::atan2(p.y(), p.x());
}

double angleDiff(double a, double b) {
  return std::remainder(a - b, 2 * kPi);
}

TEST(DeformationSequence, ConcaveCylinderIsSplitAndResolved) {
  const double R = 10.0, r = 1.0, L = 6.0;
  const int na = 48, nDef = 96;
  const DisplacementField mould = mouldOn(cylinder(R, na, 3, 0.0, L, true), 4);
  const TriangleMesh deformed = cylinder(r, nDef, 4, -1.0, L + 1.0, true);
  const auto seq = buildDeformationSequence(mould, deformed);
  // Analytic h0 = R / |v| (the offset triangle collapses onto the axis) and, with the
  // interpolated vector of length |v| |g| / R, h = (|g| - r) R / (|g| |v|): a face crosses
  // when some raster point has 1 - r / |g| > 0.8.
  std::vector<int> expected;
  const DisplacementField& stage0 = seq.stages[0].ddf;
  std::vector<char> crosses(stage0.faceCount(), 0);
  forEachCopy(stage0, [&](std::size_t, const Vec3& g, int f) {
    if (1.0 - r / g.head<2>().norm() > 0.8 + 1e-6) crosses[f] = 1;
  });
  for (int f = 0; f < stage0.faceCount(); ++f)
    if (crosses[f]) expected.push_back(f);
  EXPECT_FALSE(seq.crossingFaces.empty());
  EXPECT_EQ(seq.crossingFaces, expected);
  EXPECT_TRUE(seq.unresolvedFaces.empty());
  EXPECT_GE(seq.stages.size(), 2u);
  EXPECT_EQ(seq.missingPoints, 0u);
  const double sagitta = r * (1 - std::cos(kPi / nDef));
  forEachCopy(stage0, [&](std::size_t i, const Vec3& g, int) {
    const Vec3& q = seq.deformedPoints[i];
    EXPECT_GT(q.head<2>().norm(), r - sagitta - 1e-5) << i;
    EXPECT_LT(q.head<2>().norm(), r + 1e-5) << i;
    EXPECT_LT(std::abs(angleDiff(angleOf(q), angleOf(g))), 1e-4) << i;
    EXPECT_NEAR(q.z(), g.z(), 1e-5);
  });
  // No fold: every face keeps its orientation in (angle, z) coordinates.
  const int n = stage0.raster().steps();
  for (int f = 0; f < stage0.faceCount(); ++f) {
    const std::size_t base = f * stage0.pointsPerFace();
    auto orient = [](const Vec3& a, const Vec3& b, const Vec3& c) {
      const double ab = angleDiff(angleOf(b), angleOf(a)), ac = angleDiff(angleOf(c), angleOf(a));
      return ab * (c.z() - a.z()) - ac * (b.z() - a.z());
    };
    const auto& fv = stage0.faceVertices(f);
    const double before =
        orient(stage0.position(fv[0]), stage0.position(fv[1]), stage0.position(fv[2]));
    const double after = orient(seq.deformedPoints[base + stage0.raster().index(n, 0)],
                                seq.deformedPoints[base + stage0.raster().index(0, 0)],
                                seq.deformedPoints[base + stage0.raster().index(0, n)]);
    EXPECT_GT(before * after, 0.0) << f;
  }
  const auto m0 = morphPositions(seq, 0.0), m1 = morphPositions(seq, 1.0);
  forEachCopy(stage0, [&](std::size_t i, const Vec3& g, int) {
    EXPECT_LT((m0[i] - g).norm(), 1e-9);
    EXPECT_LT((m1[i] - seq.deformedPoints[i]).norm(), 1e-5);
  });
}

TEST(DeformationSequence, ShallowConcaveCylinderNeedsOneStage) {
  const double R = 10.0, r = 3.0;
  const DisplacementField mould = mouldOn(cylinder(R, 48, 3, 0.0, 6.0, true), 3);
  const auto seq = buildDeformationSequence(mould, cylinder(r, 96, 4, -1.0, 7.0, true));
  EXPECT_EQ(seq.stages.size(), 1u);  // 1 - r / |g| <= 0.7 < 0.8 everywhere
  EXPECT_TRUE(seq.crossingFaces.empty());
}

// Deformed points at radius rd within the sagitta of the deformed sphere, in the direction of g
// (the level-1 icosphere's vertices lie on 5- or 2-fold symmetry axes, so its pseudo-normals
// are exactly radial).
void expectConcentric(const DeformationSequence& seq, double rd, double sagitta) {
  EXPECT_TRUE(seq.unresolvedFaces.empty());
  EXPECT_EQ(seq.missingPoints, 0u);
  forEachCopy(seq.stages[0].ddf, [&](std::size_t i, const Vec3& g, int) {
    const Vec3& q = seq.deformedPoints[i];
    EXPECT_GT(q.norm(), rd - sagitta - 1e-4) << i;
    EXPECT_LT(q.norm(), rd + 1e-4) << i;
    EXPECT_GT(q.normalized().dot(g.normalized()), std::cos(1e-4)) << i;
  });
}

TEST(DeformationSequence, ConcentricSpheresBothDirections) {
  const double R = 4.0;
  const DisplacementField mould = mouldOn(sphere(R, 1), 4);
  // Outwards the positive crust is unbounded on a convex support: one stage.
  const double rOut = 9.0;
  const auto out = buildDeformationSequence(mould, sphere(rOut, 4));
  EXPECT_EQ(out.stages.size(), 1u);
  EXPECT_TRUE(out.crossingFaces.empty());
  const double edgeAngle = 0.2;  // > largest edge angle of the level-4 icosphere
  expectConcentric(out, rOut, rOut * (1 - std::cos(edgeAngle)));
  // Inwards beyond 0.8 R the -h crust (h0 = R / |v|) fails: split and resolved.
  const double rIn = 0.4;
  const auto in = buildDeformationSequence(mould, flipped(sphere(rIn, 4)));
  EXPECT_EQ(static_cast<int>(in.crossingFaces.size()), mould.faceCount());
  EXPECT_GE(in.stages.size(), 2u);
  expectConcentric(in, rIn, rIn * (1 - std::cos(edgeAngle)));
}

TEST(DeformationSequence, PerPointLambdasMatchUniformMorph) {
  const DisplacementField mould = mouldOn(sphere(4.0, 1), 3);
  const auto seq = buildDeformationSequence(mould, flipped(sphere(0.4, 3)));
  ASSERT_GE(seq.stages.size(), 2u);
  std::vector<float> lambdas(seq.deformedPoints.size(), 0.25f);
  const auto a = morphPositions(seq, lambdas), b = morphPositions(seq, 0.25);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_LT((a[i] - b[i]).norm(), 1e-12);
  // The path passes through the stage supports at the cumulative times tau_k.
  const double tau1 = seq.stages[0].fraction;
  const auto atTau = morphPositions(seq, tau1);
  forEachCopy(seq.stages[1].ddf,
              [&](std::size_t i, const Vec3& g, int) { EXPECT_LT((atTau[i] - g).norm(), 1e-9); });
}

TEST(DeformationSequence, SharedSpringbackPairLandsOnTheFormedPart) {
  const auto dir =
      std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "springback-deepdrawn";
  if (!std::filesystem::exists(dir / "target_AF_bs.stl"))
    GTEST_SKIP() << "shared springback pair not present";
  SupportMesh target, formedMesh;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(target, (dir / "target_AF_bs.stl").string()));
  ASSERT_TRUE(OpenMesh::IO::read_mesh(formedMesh, (dir / "mesh_ausgerichtet1.stl").string()));
  const TriangleMesh formed = toTriangleMesh(formedMesh);
  const DisplacementField mould(target, pseudoNormals(target).normals, 2);
  // With the default crustSafety 0.8 the pair needs no split (smallest h0 / |h| measured: 2.25,
  // so the formed part stays well inside the unique-projection crust); a strict safety of 0.4
  // forces the staged remedy on real data.
  DeformationSequenceParams params;
  params.crustSafety = 0.4;
  const auto seq = buildDeformationSequence(mould, formed, params);
  // Oracle for the crossing set: stage-0 heights against crustHeights(), face by face.
  const DisplacementField& stage0 = seq.stages[0].ddf;
  std::vector<int> expected;
  for (int f = 0; f < stage0.faceCount(); ++f) {
    const CrustHeights h0 = crustHeights(stage0, f);
    bool crosses = false;
    for (const float h : stage0.heights(f))
      crosses = crosses || (h > 0 && h > 0.4 * h0.positive) || (h < 0 && -h > 0.4 * h0.negative);
    if (crosses) expected.push_back(f);
  }
  EXPECT_EQ(seq.crossingFaces, expected);
  EXPECT_FALSE(seq.crossingFaces.empty());
  EXPECT_GE(seq.stages.size(), 2u);
  EXPECT_TRUE(seq.unresolvedFaces.empty());
  std::printf("[ shared   ] %zu stages, %zu crossing faces, %zu unresolved, %zu missing of %zu\n",
              seq.stages.size(), seq.crossingFaces.size(), seq.unresolvedFaces.size(),
              seq.missingPoints, seq.deformedPoints.size());
  EXPECT_LT(seq.missingPoints, seq.deformedPoints.size() / 20);
  // Brute-force distance of a subset of the deformed points to the formed mesh.
  double worst = 0.0;
  for (std::size_t i = 0; i < seq.deformedPoints.size(); i += 613) {
    if (!std::isfinite(seq.deformedPoints[i].x())) continue;
    worst = std::max(worst, test::meshDistance(formed, seq.deformedPoints[i]));
  }
  EXPECT_LT(worst, 1e-3);
  const auto m0 = morphPositions(seq, 0.0), m1 = morphPositions(seq, 1.0);
  forEachCopy(mould, [&](std::size_t i, const Vec3& g, int) {
    if (!std::isfinite(seq.deformedPoints[i].x())) return;  // NaN by contract
    EXPECT_LT((m0[i] - g).norm(), 1e-9);
    EXPECT_LT((m1[i] - seq.deformedPoints[i]).norm(), 1e-5);
  });
}

TEST(DeformationSequence, BadInputIsRejected) {
  const DisplacementField mould = mouldOn(sphere(4.0, 0), 3);
  const TriangleMesh target = sphere(5.0, 1);
  EXPECT_THROW(buildDeformationSequence(mould, TriangleMesh{}), InvalidInput);
  TriangleMesh broken = target;
  broken.triangles[0][1] = 999;
  EXPECT_THROW(buildDeformationSequence(mould, broken), InvalidInput);
  EXPECT_THROW(buildDeformationSequence(DisplacementField{}, target), InvalidInput);
  for (const double safety : {0.0, -0.1, 1.5}) {
    DeformationSequenceParams params;
    params.crustSafety = safety;
    EXPECT_THROW(buildDeformationSequence(mould, target, params), InvalidInput);
  }
  DeformationSequenceParams params;
  params.maxStages = 0;
  EXPECT_THROW(buildDeformationSequence(mould, target, params), InvalidInput);
  params = {};
  params.reachMm = -1.0;
  EXPECT_THROW(buildDeformationSequence(mould, target, params), InvalidInput);
  params = {};
  params.stallStages = -1;
  EXPECT_THROW(buildDeformationSequence(mould, target, params), InvalidInput);
  params = {};
  params.progress = [](double) { return false; };
  EXPECT_THROW(buildDeformationSequence(mould, target, params), Cancelled);
  const auto seq = buildDeformationSequence(mould, target);
  std::vector<float> wrong(seq.deformedPoints.size() + 1, 0.5f);
  EXPECT_THROW(morphPositions(seq, wrong), InvalidInput);
}

// A dense, rough mould: 0.5 mm cells whose vertices jitter by up to 0.05 mm, so neighbouring
// pseudo-normals cross a few millimetres off the support. A plane 10 mm away lies far beyond
// that crust, each split can carry only a sliver of the deformation and the crossing faces do
// not shrink: the sequence stops after stallStages such splits instead of running to maxStages.
TEST(DeformationSequence, SplitsWithoutHeadwayStopEarly) {
  const TriangleMesh rough =
      test::heightFieldMesh(0.0, 20.0, 0.0, 20.0, 40, 40, [](double x, double y) {
        const double s = std::sin(12.9898 * x + 78.233 * y) * 43758.5453;
        return 0.1 * (s - std::floor(s) - 0.5);
      });
  const DisplacementField mould = mouldOn(rough, 2);
  const TriangleMesh plane =
      test::heightFieldMesh(-5.0, 25.0, -5.0, 25.0, 6, 6, [](double, double) { return 10.0; });
  const auto seq = buildDeformationSequence(mould, plane);
  std::printf("[ stall    ] %zu stages, %zu crossing at stage 0, %zu unresolved of %d faces\n",
              seq.stages.size(), seq.crossingFaces.size(), seq.unresolvedFaces.size(),
              mould.faceCount());
  EXPECT_TRUE(seq.stalled);
  EXPECT_EQ(seq.stages.size(), 3u);  // stage 0 and two splits without headway
  EXPECT_FALSE(seq.unresolvedFaces.empty());
  for (std::size_t s = 0; s + 1 < seq.stages.size(); ++s) EXPECT_LT(seq.stages[s].fraction, 0.25);
  // Without the stop it keeps splitting to the stage limit and still leaves faces unresolved.
  DeformationSequenceParams params;
  params.stallStages = 0;
  params.maxStages = 6;
  const auto all = buildDeformationSequence(mould, plane, params);
  EXPECT_FALSE(all.stalled);
  EXPECT_EQ(all.stages.size(), 6u);
  EXPECT_FALSE(all.unresolvedFaces.empty());
}

}  // namespace
}  // namespace ddfcam::ddf
