// SPDX-License-Identifier: MIT
// Tests of manual region editing against brute-force oracles on analytic parts.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/region_editing.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

ddf::GeneratedSurface plane() {
  return ddf::planePatch({.cellsX = 10, .cellsY = 6, .m = 5});
}

Region region(const std::string& name, std::vector<int> faces) {
  Region r;
  r.name = name;
  r.faces = std::move(faces);
  return r;
}

// Base-plane centroid of face f (the plane patch's support lies in z = 0).
Vec3 supportCentroid(const ddf::DisplacementField& ddf, int f) {
  const auto& v = ddf.faceVertices(f);
  return (ddf.position(v[0]) + ddf.position(v[1]) + ddf.position(v[2])) / 3.0;
}

// Connected parts by brute force: faces are adjacent when they share two vertex indices.
std::vector<std::set<int>> bruteParts(const ddf::DisplacementField& ddf,
                                      const std::vector<int>& faces) {
  std::vector<int> parent(ddf.faceCount());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x];
    return x;
  };
  for (int a : faces)
    for (int b : faces) {
      int shared = 0;
      for (int va : ddf.faceVertices(a))
        for (int vb : ddf.faceVertices(b)) shared += va == vb;
      if (a != b && shared == 2) parent[find(a)] = find(b);
    }
  std::map<int, std::set<int>> parts;
  for (int f : faces) parts[find(f)].insert(f);
  std::vector<std::set<int>> out;
  for (auto& [root, part] : parts) out.push_back(part);
  return out;
}

TEST(RegionEditing, FaceIndexAndFieldMatchMembership) {
  const auto part = plane();
  const int F = part.ddf.faceCount();
  const std::vector<Region> regions = {region("a", {0, 3, 5}), region("b", {1, 7})};
  const std::vector<int> index = faceRegionIndex(regions, F);
  ASSERT_EQ(static_cast<int>(index.size()), F);
  for (int f = 0; f < F; ++f) {
    const int expected = (f == 0 || f == 3 || f == 5) ? 0 : (f == 1 || f == 7) ? 1 : -1;
    EXPECT_EQ(index[f], expected) << f;
  }
  const ScalarField field = regionIndexField(part.ddf, regions);
  ASSERT_EQ(field.values.size(), part.ddf.allHeights().size());
  const std::size_t per = part.ddf.pointsPerFace();
  for (std::size_t p = 0; p < field.values.size(); ++p) {
    const int f = static_cast<int>(p / per);
    if (index[f] < 0)
      EXPECT_TRUE(std::isnan(field.values[p]));
    else
      EXPECT_EQ(field.values[p], static_cast<float>(index[f]));
  }
  EXPECT_THROW(faceRegionIndex({region("a", {2}), region("b", {2})}, F), InvalidInput);
  EXPECT_THROW(faceRegionIndex({region("a", {F})}, F), InvalidInput);
}

TEST(RegionEditing, AssignMovesFacesAndCreatesRegions) {
  const auto part = plane();
  const int F = part.ddf.faceCount();
  const std::vector<Region> before = {region("a", {0, 1, 2, 3}), region("b", {4, 5, 6})};
  const std::vector<int> moving = {6, 2, 2, 9, 30};
  const auto after = assignFaces(before, 0, moving, F);
  ASSERT_EQ(after.size(), 2u);
  EXPECT_EQ(after[0].faces, (std::vector<int>{0, 1, 2, 3, 6, 9, 30}));
  EXPECT_EQ(after[1].faces, (std::vector<int>{4, 5}));
  EXPECT_EQ(after[1].name, "b");
  // A new region: appended, named, coloured unlike the others.
  const auto created = assignFaces(before, 2, std::vector<int>{3, 4}, F, "painted");
  ASSERT_EQ(created.size(), 3u);
  EXPECT_EQ(created[2].name, "painted");
  EXPECT_EQ(created[2].faces, (std::vector<int>{3, 4}));
  EXPECT_EQ(created[0].faces, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(created[1].faces, (std::vector<int>{5, 6}));
  EXPECT_NE(created[2].color, created[0].color);
  EXPECT_NE(created[2].color, created[1].color);
  // The eraser empties a region but keeps it in place.
  const auto erased = assignFaces(before, -1, std::vector<int>{4, 5, 6}, F);
  ASSERT_EQ(erased.size(), 2u);
  EXPECT_TRUE(erased[1].faces.empty());
  EXPECT_EQ(erased[0], before[0]);
  EXPECT_THROW(assignFaces(before, 3, moving, F), InvalidInput);
  EXPECT_THROW(assignFaces(before, 2, moving, F, ""), InvalidInput);
  EXPECT_THROW(assignFaces(before, 0, std::vector<int>{F}, F), InvalidInput);
}

TEST(RegionEditing, BrushGridMatchesBruteForce) {
  const auto part = ddf::sinSinPatch(
      {.grid = {.origin = {-3.0, -3.0}, .size = {6.0, 6.0}, .cellsX = 12, .cellsY = 12, .m = 6}});
  const ddf::DisplacementField& ddf = part.ddf;
  const int n = ddf.raster().steps();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> xy(-3.5, 3.5), z(-1.2, 1.2), radius(0.0, 2.5);
  for (double cell : {0.0, 0.2, 3.0}) {
    const SurfacePointGrid grid(ddf, cell);
    for (int trial = 0; trial < 60; ++trial) {
      const Vec3 centre(xy(rng), xy(rng), z(rng));
      const double r = trial == 0 ? 100.0 : radius(rng);
      std::vector<int> expected;
      for (int f = 0; f < ddf.faceCount(); ++f) {
        bool hit = false;
        for (int k = 0; k <= n && !hit; ++k)
          for (int i = 0; i <= n - k && !hit; ++i)
            hit = (ddf.surfacePoint(f, i, k) - centre).norm() <= r;
        if (hit) expected.push_back(f);
      }
      EXPECT_EQ(grid.facesWithinDistance(centre, r), expected) << "cell " << cell << " r " << r;
    }
  }
  EXPECT_EQ(static_cast<int>(facesWithinDistance(ddf, Vec3(0, 0, 0), 100.0).size()),
            ddf.faceCount());
  EXPECT_TRUE(facesWithinDistance(ddf, Vec3(50, 50, 50), 1.0).empty());
  EXPECT_THROW(facesWithinDistance(ddf, Vec3::Zero(), -1.0), InvalidInput);
}

TEST(RegionEditing, MergeKeepsTheFirstRegionsIdentity) {
  std::vector<Region> before = {region("a", {0, 4}), region("b", {1, 2}), region("c", {3}),
                                region("d", {7})};
  before[1].plan.spacingMm = 2.5;
  const auto after = mergeRegions(before, {3, 1});
  ASSERT_EQ(after.size(), 3u);
  EXPECT_EQ(after[0], before[0]);
  EXPECT_EQ(after[1].name, "b");
  EXPECT_EQ(after[1].plan, before[1].plan);
  EXPECT_EQ(after[1].color, before[1].color);
  EXPECT_EQ(after[1].faces, (std::vector<int>{1, 2, 7}));
  EXPECT_EQ(after[2], before[2]);
  EXPECT_THROW(mergeRegions(before, {1, 1}), InvalidInput);
  EXPECT_THROW(mergeRegions(before, {0, 4}), InvalidInput);
}

TEST(RegionEditing, SplitIntoConnectedPartsMatchesBruteForce) {
  const auto part = plane();
  const ddf::DisplacementField& ddf = part.ddf;
  // Three blocks of faces separated by empty columns: x < 12, 16 < x < 24 and x > 32 mm.
  std::vector<int> faces;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const double x = supportCentroid(ddf, f).x();
    if (x < 12.0 || (x > 16.0 && x < 24.0) || x > 32.0) faces.push_back(f);
  }
  std::vector<Region> before = {region("other", {}), region("blocks", faces)};
  before[1].plan.feedSign = -1;
  const auto parts = bruteParts(ddf, faces);
  ASSERT_EQ(parts.size(), 3u);
  const auto after = splitConnectedParts(ddf, before, 1);
  ASSERT_EQ(after.size(), 4u);
  EXPECT_EQ(after[0], before[0]);
  EXPECT_EQ(after[1].name, "blocks");
  EXPECT_EQ(after[1].color, before[1].color);
  EXPECT_EQ(after[2].name, "blocks (2)");
  EXPECT_EQ(after[3].name, "blocks (3)");
  std::set<std::set<int>> got, want(parts.begin(), parts.end());
  for (int r = 1; r <= 3; ++r) {
    EXPECT_TRUE(std::is_sorted(after[r].faces.begin(), after[r].faces.end()));
    EXPECT_EQ(after[r].plan, before[1].plan);
    got.insert(std::set<int>(after[r].faces.begin(), after[r].faces.end()));
  }
  EXPECT_EQ(got, want);
  EXPECT_EQ(after[1].faces.front(), faces.front());  // the part with the lowest face stays
  EXPECT_LT(after[2].faces.front(), after[3].faces.front());
  // A connected region comes back unchanged.
  EXPECT_EQ(splitConnectedParts(ddf, after, 2), after);
  EXPECT_THROW(splitConnectedParts(ddf, before, 2), InvalidInput);
}

TEST(RegionEditing, SplitByFacesRenameRemoveAndPlan) {
  const std::vector<Region> before = {region("a", {0, 1, 2, 3}), region("b", {5})};
  const auto split = splitRegionFaces(before, 0, std::vector<int>{3, 1});
  ASSERT_EQ(split.size(), 3u);
  EXPECT_EQ(split[0].faces, (std::vector<int>{0, 2}));
  EXPECT_EQ(split[1].faces, (std::vector<int>{1, 3}));
  EXPECT_EQ(split[1].name, "a (split)");
  EXPECT_EQ(split[2], before[1]);
  EXPECT_THROW(splitRegionFaces(before, 0, std::vector<int>{5}), InvalidInput);
  EXPECT_THROW(splitRegionFaces(before, 0, std::vector<int>{0, 1, 2, 3}), InvalidInput);
  EXPECT_THROW(splitRegionFaces(before, 0, std::vector<int>{}), InvalidInput);

  const auto renamed = renameRegion(before, 1, "fillet");
  EXPECT_EQ(renamed[1].name, "fillet");
  EXPECT_EQ(renamed[1].faces, before[1].faces);
  EXPECT_THROW(renameRegion(before, 1, ""), InvalidInput);
  EXPECT_THROW(renameRegion(before, 2, "x"), InvalidInput);

  const auto removed = removeRegion(before, 0);
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_EQ(removed[0], before[1]);
  EXPECT_THROW(removeRegion(before, -1), InvalidInput);

  RegionPlan plan;
  plan.tool = 0;
  plan.linking = LinkingOrder::OneDirection;
  const auto planned = setRegionPlan(before, 1, plan);
  EXPECT_EQ(planned[1].plan, plan);
  EXPECT_EQ(planned[0], before[0]);
}

TEST(RegionEditing, FaceFramesOnAPlane) {
  const auto part = plane();  // z = 0.25 mm, vectors +z
  const auto frames = faceFrames(part.ddf);
  ASSERT_EQ(static_cast<int>(frames.size()), part.ddf.faceCount());
  for (int f = 0; f < part.ddf.faceCount(); ++f) {
    // The raster points of a triangle average to its centroid.
    const Vec3 expected = supportCentroid(part.ddf, f) + Vec3(0, 0, 0.25);
    EXPECT_LT((frames[f].centroid - expected).norm(), 1e-9) << f;
    EXPECT_LT((frames[f].normal - Vec3::UnitZ()).norm(), 1e-12) << f;
  }
}

TEST(RegionEditing, PointInPolygon) {
  // An L shape: the unit square [0,2]^2 without [1,2]x[1,2].
  const std::vector<Eigen::Vector2d> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 2.5);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector2d p(u(rng), u(rng));
    const bool inSquare = p.x() > 0 && p.x() < 2 && p.y() > 0 && p.y() < 2;
    const bool inNotch = p.x() > 1 && p.y() > 1;
    EXPECT_EQ(pointInPolygon(p, l), inSquare && !inNotch) << p.transpose();
  }
  EXPECT_FALSE(pointInPolygon({0.5, 0.5}, std::vector<Eigen::Vector2d>{{0, 0}, {1, 1}}));
}

}  // namespace
}  // namespace ddfcam::planning
