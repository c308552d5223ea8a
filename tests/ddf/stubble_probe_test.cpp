// SPDX-License-Identifier: MIT
// Tests of the dry-run stubble probe against analytic entry and exit heights on a z-map.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/stubble_probe.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <type_traits>

namespace ddfcam::ddf {
namespace {

/// An axis-aligned box [lo, hi] as a closed outward mesh (12 triangles).
TriangleMesh box(const Vec3& lo, const Vec3& hi) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                            i & 4 ? hi.z() : lo.z());
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

struct ZMap {
  // Support z = 0 over 10 x 10 mm, vectors (0, 0, 2): h = z / 2; surface at z = 0.5.
  GeneratedSurface plane = planePatch({.origin = {0.0, 0.0},
                                       .size = {10.0, 10.0},
                                       .cellsX = 5,
                                       .cellsY = 5,
                                       .m = 9,
                                       .planeZMm = 0.5,
                                       .vectorLengthMm = 2.0});
  CrustHash hash{plane.ddf};
};

TEST(StubbleProbe, BoxGivesItsBottomAndTopAsEntryAndExit) {
  const ZMap z;
  const TriangleMesh b = box({2.1, 3.1, -0.6}, {5.9, 6.9, 1.2});  // h in [-0.3, 0.6]
  const StubbleProbe probe = probeStubbles(z.plane.ddf, z.hash, b, Eigen::Isometry3d::Identity());
  ASSERT_FALSE(probe.crossings.empty());
  std::size_t inside = 0;
  for (int f = 0; f < z.plane.ddf.faceCount(); ++f)
    for (int k = 0; k < 9; ++k)
      for (int i = 0; i + k < 9; ++i) {
        const Vec3 g = z.plane.ddf.basePoint(f, z.plane.ddf.rasterBary(i, k));
        inside += g.x() > 2.1 && g.x() < 5.9 && g.y() > 3.1 && g.y() < 6.9;
      }
  EXPECT_EQ(probe.crossings.size(), inside);  // stored copies, brute force
  for (const StubbleCrossing& c : probe.crossings) {
    EXPECT_NEAR(c.entry, -0.3, 1e-6);
    EXPECT_NEAR(c.exit, 0.6, 1e-6);
    EXPECT_EQ(c.intervals, 1);
    EXPECT_FLOAT_EQ(c.height, 0.25f);
  }
}

TEST(StubbleProbe, ClampsToTheCrustAndSeesSegmentsInsideTheMesh) {
  const ZMap z;
  // A box through the whole crust (z from -5 to 5): no crossing on the segment, yet inside.
  const TriangleMesh tall = box({4.05, 4.05, -5.0}, {5.95, 5.95, 5.0});
  const StubbleProbe through =
      probeStubbles(z.plane.ddf, z.hash, tall, Eigen::Isometry3d::Identity());
  EXPECT_GT(through.crossings.size(), 40u);  // 1.9 x 1.9 mm over 0.25 mm raster steps
  for (const StubbleCrossing& c : through.crossings) {
    EXPECT_EQ(c.entry, -1.0f);
    EXPECT_EQ(c.exit, 1.0f);
  }
  // Two stacked boxes: two intervals, the lowest reported.
  TriangleMesh two = box({1.05, 1.05, -1.0}, {2.95, 2.95, -0.2});
  const TriangleMesh upper = box({1.05, 1.05, 0.6}, {2.95, 2.95, 1.4});
  for (auto t : upper.triangles) two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  two.vertices.insert(two.vertices.end(), upper.vertices.begin(), upper.vertices.end());
  const StubbleProbe probe = probeStubbles(z.plane.ddf, z.hash, two, Eigen::Isometry3d::Identity());
  ASSERT_FALSE(probe.crossings.empty());
  for (const StubbleCrossing& c : probe.crossings) {
    EXPECT_EQ(c.intervals, 2);
    EXPECT_NEAR(c.entry, -0.5, 1e-6);
    EXPECT_NEAR(c.exit, -0.1, 1e-6);
  }
}

TEST(StubbleProbe, BallCapMatchesTheSphereAndLeavesHeightsAlone) {
  const ZMap z;
  const TriangleMesh ball = planning::makeSphereTool(1.5, 24, 48);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Vec3(5.03, 4.97, 0.0);
  const std::vector<float> before = z.plane.ddf.allHeights();
  const StubbleProbe probe = probeStubbles(z.plane.ddf, z.hash, ball, pose);
  EXPECT_TRUE(z.plane.ddf.allHeights() == before);
  ASSERT_GT(probe.crossings.size(), 100u);
  const double facet = 1.5 * (1.0 - std::cos(M_PI / 24.0)) + 1e-6;
  for (const StubbleCrossing& c : probe.crossings) {
    EXPECT_LE(c.entry, c.exit);
    EXPECT_EQ(c.intervals, 1);
  }
  // Centre stubble (5, 5) is nearest the centre: entry about -1.5 / 2 = -0.75 (h units).
  double lowest = 1.0;
  for (const StubbleCrossing& c : probe.crossings) lowest = std::min(lowest, double(c.entry));
  EXPECT_NEAR(lowest, -std::sqrt(1.5 * 1.5 - 0.03 * 0.03 - 0.03 * 0.03) / 2.0, facet);
}

// Brute-force reference: every stubble of every face against every triangle, the hit rules of
// the header (barycentric edge tolerance 1e-9, near-parallel lines skipped, same-direction hits
// within the merge tolerance counted once, a segment without hits inside iff the first hit
// above it is an exit).
struct RefHit {
  double h;
  bool entry;
};

std::vector<RefHit> refHits(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, const Vec3& g,
                            const Vec3& v, double hMin, double hMax) {
  const bool flip = mesh.signedVolume() < 0.0;
  std::vector<RefHit> hits;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = pose * mesh.vertices[t[0]];
    const Vec3 e1 = pose * mesh.vertices[t[flip ? 2 : 1]] - a;
    const Vec3 e2 = pose * mesh.vertices[t[flip ? 1 : 2]] - a;
    const Vec3 pv = v.cross(e2);
    const double det = e1.dot(pv);
    if (std::abs(det) <= 1e-12 * e1.norm() * e2.norm() * v.norm()) continue;
    const Vec3 tv = g - a, qv = tv.cross(e1);
    const double u = tv.dot(pv) / det, w = v.dot(qv) / det, h = e2.dot(qv) / det;
    if (u < -1e-9 || u > 1.0 + 1e-9 || w < -1e-9 || u + w > 1.0 + 1e-9) continue;
    if (h > hMin && h <= hMax) hits.push_back({h, det > 0.0});
  }
  std::sort(hits.begin(), hits.end(), [](const RefHit& x, const RefHit& y) { return x.h < y.h; });
  std::vector<RefHit> merged;
  for (const RefHit& hit : hits) {
    bool duplicate = false;
    for (auto it = merged.rbegin(); it != merged.rend() && hit.h - it->h <= 1e-7; ++it)
      duplicate = duplicate || it->entry == hit.entry;
    if (!duplicate) merged.push_back(hit);
  }
  return merged;
}

std::vector<StubbleCrossing> referenceProbe(const DisplacementField& ddf, const TriangleMesh& mesh,
                                            const Eigen::Isometry3d& pose) {
  std::vector<StubbleCrossing> out;
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const Vec3 g = ddf.basePoint(f, ddf.rasterBary(i, k));
        const Vec3 v = ddf.vectorAt(f, ddf.rasterBary(i, k));
        StubbleCrossing c{f,
                          static_cast<std::uint32_t>(ddf.raster().index(i, k)),
                          ddf.topology().id(f, i, k),
                          0.0f,
                          0.0f,
                          0.0f,
                          0};
        c.height = ddf.heights(f)[c.index];
        const auto hits = refHits(mesh, pose, g, v, -1.0 - 1e-12, 1.0);
        if (hits.empty()) {
          const auto above =
              refHits(mesh, pose, g, v, 1.0, std::numeric_limits<double>::infinity());
          if (above.empty() || above.front().entry) continue;
          c.entry = -1.0f, c.exit = 1.0f, c.intervals = 1;
          out.push_back(c);
          continue;
        }
        bool inside = !hits.front().entry;
        double start = -1.0;
        for (const RefHit& hit : hits) {
          if (hit.entry && !inside) {
            start = hit.h, inside = true;
          } else if (!hit.entry && inside) {
            if (c.intervals++ == 0) c.entry = float(start), c.exit = float(hit.h);
            inside = false;
          }
        }
        if (inside && c.intervals++ == 0) c.entry = float(start), c.exit = 1.0f;
        if (c.intervals > 0) out.push_back(c);
      }
  return out;
}

/// Probes @p tool at @p poses on @p part and compares every crossing with the reference.
void expectSameAsReference(const GeneratedSurface& part, const TriangleMesh& tool,
                           const std::vector<Eigen::Isometry3d>& poses) {
  const CrustHash hash(part.ddf);
  std::size_t total = 0, multiple = 0, through = 0;
  for (std::size_t p = 0; p < poses.size(); ++p) {
    const auto ref = referenceProbe(part.ddf, tool, poses[p]);
    for (bool parallel : {false, true}) {
      const auto fast = probeStubbles(part.ddf, hash, tool, poses[p], {.parallel = parallel});
      ASSERT_EQ(fast.crossings.size(), ref.size()) << "pose " << p;
      for (std::size_t i = 0; i < ref.size(); ++i) {
        const StubbleCrossing &a = fast.crossings[i], &b = ref[i];
        ASSERT_TRUE(a.face == b.face && a.index == b.index && a.point == b.point &&
                    a.height == b.height && a.entry == b.entry && a.exit == b.exit &&
                    a.intervals == b.intervals)
            << "pose " << p << " face " << b.face << " index " << b.index << ": entry " << a.entry
            << " vs " << b.entry << ", exit " << a.exit << " vs " << b.exit;
      }
    }
    total += ref.size();
    for (const auto& c : ref) multiple += c.intervals > 1, through += c.entry == -1.0f;
  }
  EXPECT_GT(total, 50 * poses.size());  // the poses really cut into the crust
  std::printf("%zu crossings, %zu multiple, %zu through the crust\n", total, multiple, through);
}

/// Random poses: a random rotation, the origin at a random point at distance [dMin, dMax] from
/// @p centre in a random direction (deterministic seed).
std::vector<Eigen::Isometry3d> randomPoses(int count, const Vec3& centre, double dMin, double dMax,
                                           unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(dMin, dMax);
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < count; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    const Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    pose.linear() = q.normalized().toRotationMatrix();
    const Vec3 dir(normal(rng), normal(rng), normal(rng));
    pose.translation() = centre + uniform(rng) * dir.normalized();
    poses.push_back(pose);
  }
  return poses;
}

TEST(StubbleProbe, GridLocalizationEqualsBruteForceForARollOnASphere) {
  // Sphere R = 10 with crust radii [5, 15]; the 200-triangle roll (r 5, width 10) straddles it.
  const GeneratedSurface sphere = spherePart({.radiusMm = 10.0, .subdivisions = 1, .m = 11});
  const TriangleMesh roll = planning::makeCylinderTool({.radiusMm = 5.0, .widthMm = 10.0});
  expectSameAsReference(sphere, roll, randomPoses(6, Vec3::Zero(), 9.0, 16.0, 7u));
}

TEST(StubbleProbe, GridLocalizationEqualsBruteForceForABallAndTwoRollsOnASaddle) {
  const GeneratedSurface saddle = saddlePatch({.grid = {.cellsX = 10, .cellsY = 10, .m = 9}});
  const TriangleMesh ball = planning::makeSphereTool(3.0, 12, 24);
  // Two parallel rolls 3 mm apart (a non-convex mesh): stubbles may enter it twice.
  TriangleMesh rolls = planning::makeCylinderTool({.radiusMm = 1.2, .widthMm = 12.0});
  const std::size_t n = rolls.vertices.size();
  for (std::size_t i = 0; i < n; ++i) rolls.vertices.push_back(rolls.vertices[i] + Vec3(0, 0, 3));
  for (std::size_t t = 0, count = rolls.triangles.size(); t < count; ++t) {
    auto tri = rolls.triangles[t];
    for (auto& v : tri) v += static_cast<std::remove_reference_t<decltype(v)>>(n);
    rolls.triangles.push_back(tri);
  }
  expectSameAsReference(saddle, ball, randomPoses(3, Vec3::Zero(), 0.0, 5.0, 11u));
  expectSameAsReference(saddle, rolls, randomPoses(4, Vec3::Zero(), 0.0, 3.0, 13u));
}

}  // namespace
}  // namespace ddfcam::ddf
