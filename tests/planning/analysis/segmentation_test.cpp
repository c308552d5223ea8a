// SPDX-License-Identifier: MIT
// Tests of the automatic segmentation by curvature type and tool size against analytic parts.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/segmentation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::GeneratedSurface;
using ddf::Vec3;

constexpr int kM = 9;

GeneratedSurface cylinder() {
  return ddf::cylinderPart({.radiusMm = 2.0, .lengthMm = 4.0, .segments = 16, .rings = 4, .m = kM});
}

// The same cylinder machined from inside: vectors point to the axis, faces flipped.
GeneratedSurface cylinderInside() {
  GeneratedSurface out = cylinder();
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  for (int v = 0; v < out.ddf.vertexCount(); ++v) points.push_back(out.ddf.position(v));
  for (int f = 0; f < out.ddf.faceCount(); ++f) {
    const auto& t = out.ddf.faceVertices(f);
    triangles.push_back({t[0], t[2], t[1]});
  }
  std::vector<Vec3> vectors = out.ddf.vectors();
  for (Vec3& v : vectors) v = -v;
  return ddf::fromAnalytic(ddf::makeSupportMesh(points, triangles), std::move(vectors), kM,
                           out.surface);
}

GeneratedSurface plane() {
  return ddf::planePatch({.cellsX = 20, .cellsY = 15, .m = kM});
}

SegmentationParams minFaces(int faces) {
  SegmentationParams params;
  params.minFaces = faces;
  return params;
}

SegmentationParams minArea(double areaMm2) {
  SegmentationParams params;
  params.minAreaMm2 = areaMm2;
  return params;
}

Vec3 supportCentroid(const ddf::DisplacementField& ddf, int f) {
  const auto& v = ddf.faceVertices(f);
  return (ddf.position(v[0]) + ddf.position(v[1]) + ddf.position(v[2])) / 3.0;
}

std::vector<int> faceTypes(const ddf::DisplacementField& ddf, const CurvatureField& curvature) {
  const std::vector<Region> regions = segmentByCurvatureType(ddf, curvature, minFaces(1));
  std::vector<int> type(ddf.faceCount(), -1);
  for (const Region& r : regions) {
    const std::string name = r.name.substr(0, r.name.find(' '));
    for (int t = 0; t < 4; ++t)
      if (name == curvatureTypeName(static_cast<CurvatureType>(t)))
        for (int f : r.faces) type[f] = t;
  }
  return type;
}

// Every face in exactly one region, faces ascending, names and colours unique, regions
// connected over shared support edges.
void expectPartition(const ddf::DisplacementField& ddf, const std::vector<Region>& regions) {
  std::vector<int> owner(ddf.faceCount(), -1);
  std::set<std::string> names;
  std::set<std::array<float, 3>> colors;
  for (int r = 0; r < static_cast<int>(regions.size()); ++r) {
    const Region& region = regions[r];
    ASSERT_FALSE(region.faces.empty());
    EXPECT_TRUE(std::is_sorted(region.faces.begin(), region.faces.end()));
    for (int f : region.faces) {
      ASSERT_EQ(owner[f], -1) << "face " << f << " in two regions";
      owner[f] = r;
    }
    EXPECT_TRUE(names.insert(region.name).second) << region.name;
    EXPECT_TRUE(colors.insert(region.color).second) << region.name;
  }
  EXPECT_EQ(std::count(owner.begin(), owner.end(), -1), 0);
  const auto& mesh = ddf.support();
  for (const Region& region : regions) {
    std::set<int> reached{region.faces.front()};
    std::vector<int> stack{region.faces.front()};
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (auto nb : mesh.ff_range(mesh.face_handle(f)))
        if (owner[nb.idx()] == owner[f] && reached.insert(nb.idx()).second)
          stack.push_back(nb.idx());
    }
    EXPECT_EQ(reached.size(), region.faces.size()) << region.name << " is not connected";
  }
}

void expectSingleRegion(const GeneratedSurface& part, CurvatureType type) {
  const std::string name = curvatureTypeName(type);
  const CurvatureField curvature = computeCurvature(part.ddf);
  const std::vector<std::uint8_t> types = classifyCurvature(curvature);
  EXPECT_EQ(std::count(types.begin(), types.end(), static_cast<std::uint8_t>(type)),
            std::ssize(types))
      << name;
  const std::vector<Region> regions = segmentByCurvatureType(part.ddf, curvature);
  ASSERT_EQ(regions.size(), 1u) << name;
  EXPECT_EQ(regions[0].name, name + " 1");
  EXPECT_EQ(std::ssize(regions[0].faces), part.ddf.faceCount());
}

CurvatureField syntheticField(const std::vector<std::pair<float, float>>& kMaxMin) {
  CurvatureField field;
  for (const auto& [kMax, kMin] : kMaxMin) {
    field.kMax.push_back(kMax);
    field.kMin.push_back(kMin);
  }
  return field;
}

// Truth table of the tool-side signs with the zero band |k| <= 1e-3 1/mm.
TEST(Segmentation, ClassifiesTheSignTable) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const CurvatureField field = syntheticField({{0.5f, 0.2f},
                                               {0.5f, 0.0f},
                                               {0.5f, -5e-4f},
                                               {-0.1f, -0.3f},
                                               {0.0f, -0.3f},
                                               {0.2f, -0.3f},
                                               {5e-4f, -5e-4f},
                                               {0.0f, 0.0f},
                                               {nan, nan}});
  using T = CurvatureType;
  const std::vector<T> expected{T::Convex, T::Convex, T::Convex, T::Concave, T::Concave,
                                T::Saddle, T::Flat,   T::Flat,   T::Flat};
  const std::vector<std::uint8_t> types = classifyCurvature(field);
  ASSERT_EQ(types.size(), expected.size());
  for (std::size_t p = 0; p < types.size(); ++p)
    EXPECT_EQ(types[p], static_cast<std::uint8_t>(expected[p])) << "point " << p;
  const ScalarField asField = curvatureTypeField(field);
  EXPECT_EQ(asField.values[5], 3.0f);
}

// Bound 1/|k_min| against radii {1, 2, 3} mm: k_min = -0.5 admits exactly 2 mm.
TEST(Segmentation, ToolRadiusClassIsTheLargestRadiusBelowTheBound) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const CurvatureField field =
      syntheticField({{0.5f, 0.1f}, {0.0f, -0.5f}, {0.0f, -0.9f}, {0.0f, -2.0f}, {nan, nan}});
  const std::vector<int> classes = classifyToolRadius(field, {1.0, 2.0, 3.0});
  EXPECT_EQ(classes, (std::vector<int>{2, 1, 0, kNoToolFits, kNoToolFits}));
  // A 10 % tolerance keeps these classes (3 > 2.2, 2 > 1.22, 1 > 0.55) but admits 2.1 mm at
  // the 2 mm bound and 1.2 mm at the 1.11 mm bound (k = -0.9).
  EXPECT_EQ(classifyToolRadius(field, {1.0, 2.0, 3.0}, 0.1),
            (std::vector<int>{2, 1, 0, kNoToolFits, kNoToolFits}));
  EXPECT_EQ(classifyToolRadius(field, {1.2, 2.1}, 0.1),
            (std::vector<int>{1, 1, 0, kNoToolFits, kNoToolFits}));
  const ScalarField radius = maxToolRadiusField(field);
  EXPECT_EQ(radius.values[0], static_cast<float>(kUnlimitedToolRadiusMm));
  EXPECT_FLOAT_EQ(radius.values[1], 2.0f);
  EXPECT_FLOAT_EQ(radius.values[3], 0.5f);
  EXPECT_TRUE(std::isnan(radius.values[4]));
}

TEST(Segmentation, CylinderFromOutsideIsConvex) {
  expectSingleRegion(cylinder(), CurvatureType::Convex);
}

TEST(Segmentation, CylinderFromInsideIsConcave) {
  expectSingleRegion(cylinderInside(), CurvatureType::Concave);
}

TEST(Segmentation, PlaneIsFlat) {
  expectSingleRegion(plane(), CurvatureType::Flat);
}

TEST(Segmentation, SaddlePatchIsSaddle) {
  expectSingleRegion(ddf::saddlePatch({.grid = {.cellsX = 10, .cellsY = 10, .m = kM}}),
                     CurvatureType::Saddle);
}

// Torus from outside: Gaussian curvature > 0 on the outer half (convex), < 0 on the inner half
// (saddle); faces near the parabolic circles v = +-pi/2 are left out.
TEST(Segmentation, TorusTypesFollowGaussianSign) {
  const double bigR = 3.0, r = 1.0;
  const GeneratedSurface part = ddf::torusPart(
      {.majorRadiusMm = bigR, .minorRadiusMm = r, .segmentsU = 24, .segmentsV = 12, .m = kM});
  const CurvatureField curvature = computeCurvature(part.ddf);
  const std::vector<int> type = faceTypes(part.ddf, curvature);
  int compared = 0;
  for (int f = 0; f < part.ddf.faceCount(); ++f) {
    const int n = part.ddf.raster().steps();
    const Vec3 q = part.ddf.surfacePoint(f, n / 3, n / 3);
    const double cosV = (std::hypot(q.x(), q.y()) - bigR) / r;
    if (std::abs(cosV) < 0.2) continue;
    ++compared;
    const auto expected = cosV > 0 ? CurvatureType::Convex : CurvatureType::Saddle;
    EXPECT_EQ(type[f], static_cast<int>(expected)) << "face " << f << " cos v " << cosV;
  }
  EXPECT_GT(compared, part.ddf.faceCount() / 2);
  const std::vector<Region> regions = segmentByCurvatureType(part.ddf, curvature);
  expectPartition(part.ddf, regions);
  ASSERT_EQ(regions.size(), 2u);  // one convex and one saddle band
  std::set<std::string> kinds;
  for (const Region& region : regions) kinds.insert(region.name.substr(0, region.name.find(' ')));
  EXPECT_EQ(kinds, (std::set<std::string>{"convex", "saddle"}));
}

TEST(Segmentation, MaxToolRadiusOfConcaveCylinderIsItsRadius) {
  const ScalarField inside = maxToolRadiusField(computeCurvature(cylinderInside().ddf));
  EXPECT_EQ(inside.name, "max tool radius");
  EXPECT_EQ(inside.unit, "mm");
  for (float radius : inside.values) ASSERT_NEAR(radius, 2.0, 0.02);
  const ScalarField outside = maxToolRadiusField(computeCurvature(cylinder().ddf), 500.0);
  for (float radius : outside.values) ASSERT_EQ(radius, 500.0f);
}

TEST(Segmentation, ToolRadiusClassesOnCylinders) {
  const std::vector<double> radii{0.5, 1.5, 2.5};
  const GeneratedSurface inside = cylinderInside();
  const CurvatureField kIn = computeCurvature(inside.ddf);
  const std::vector<int> classes = classifyToolRadius(kIn, radii);
  EXPECT_EQ(std::count(classes.begin(), classes.end(), 1), std::ssize(classes));
  std::vector<Region> regions = segmentByToolRadius(inside.ddf, kIn, radii);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].name, "radius 1.5 mm 1");
  const std::vector<int> tiny = classifyToolRadius(kIn, {3.0, 4.0});
  EXPECT_EQ(std::count(tiny.begin(), tiny.end(), kNoToolFits), std::ssize(tiny));
  const GeneratedSurface outside = cylinder();
  regions = segmentByToolRadius(outside.ddf, computeCurvature(outside.ddf), radii);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].name, "radius 2.5 mm 1");
}

// Labels by support centroid on the 40 x 30 mm plane (2 x 2 mm cells, 2 mm^2 triangles).
std::vector<int> labelsByCentroid(const ddf::DisplacementField& ddf, auto&& labelOf) {
  std::vector<int> labels(ddf.faceCount());
  for (int f = 0; f < ddf.faceCount(); ++f) labels[f] = labelOf(supportCentroid(ddf, f));
  return labels;
}

TEST(Segmentation, SmallRegionsAreMergedIntoTheirSurroundings) {
  const GeneratedSurface part = plane();
  const auto& ddf = part.ddf;
  // A 2 x 2 cell block (8 faces) of label 2 and one lone triangle of label 1 (the first face
  // in the cell at x, y in (6, 8)).
  std::vector<int> labels = labelsByCentroid(ddf, [](const Vec3& c) {
    return c.x() > 20 && c.x() < 24 && c.y() > 10 && c.y() < 14 ? 2 : 0;
  });
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const Vec3 c = supportCentroid(ddf, f);
    if (c.x() > 6 && c.x() < 8 && c.y() > 6 && c.y() < 8) {
      labels[f] = 1;
      break;
    }
  }
  const std::vector<std::string> names{"a", "b", "c"};
  std::vector<Region> all = segmentFaces(ddf, labels, names, minFaces(1));
  expectPartition(ddf, all);
  ASSERT_EQ(all.size(), 3u);
  const std::vector<Region> merged = segmentFaces(ddf, labels, names, minFaces(4));
  expectPartition(ddf, merged);
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_EQ(merged[0].name, "a 1");
  EXPECT_EQ(merged[0].faces.size(), 592u);
  EXPECT_EQ(merged[1].name, "c 2");
  EXPECT_EQ(merged[1].faces.size(), 8u);
  // 16 mm^2 block below a 20 mm^2 area threshold: everything becomes one region.
  const std::vector<Region> one = segmentFaces(ddf, labels, names, minArea(20.0));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].name, "a 1");
  EXPECT_EQ(one[0].faces.size(), 600u);
}

TEST(Segmentation, SmallRegionJoinsTheNeighbourWithTheLongestBoundary) {
  const GeneratedSurface part = plane();
  // Left half a, right half b, and one cell (2 faces) of c just right of the border: it
  // touches a along 2 mm and b along 6 mm, so it must join b.
  const std::vector<int> labels = labelsByCentroid(part.ddf, [](const Vec3& c) {
    if (c.x() > 20 && c.x() < 22 && c.y() > 14 && c.y() < 16) return 2;
    return c.x() < 20 ? 0 : 1;
  });
  const std::vector<Region> regions = segmentFaces(part.ddf, labels, {"a", "b", "c"});
  expectPartition(part.ddf, regions);
  ASSERT_EQ(regions.size(), 2u);
  for (const Region& r : regions) {
    EXPECT_EQ(r.faces.size(), 300u) << r.name;
    const bool left = supportCentroid(part.ddf, r.faces.front()).x() < 20;
    EXPECT_EQ(r.name.substr(0, 1), left ? "a" : "b");
  }
}

TEST(Segmentation, SinSinPartitionIsCompleteMergedAndDeterministic) {
  ddf::SinSinParams p;
  p.grid.cellsX = p.grid.cellsY = 12;
  p.grid.m = kM;
  const GeneratedSurface part = ddf::sinSinPatch(p);
  const CurvatureField curvature = computeCurvature(part.ddf);
  const SegmentationParams params = minFaces(6);
  const std::vector<Region> regions = segmentByCurvatureType(part.ddf, curvature, params);
  expectPartition(part.ddf, regions);
  EXPECT_GT(regions.size(), 2u);
  for (const Region& r : regions) EXPECT_GE(r.faces.size(), 6u) << r.name;
  EXPECT_EQ(segmentByCurvatureType(part.ddf, curvature, params), regions);
  const std::vector<Region> bySize = segmentByToolRadius(part.ddf, curvature, {0.5, 1.0, 2.0});
  expectPartition(part.ddf, bySize);
  EXPECT_EQ(segmentByToolRadius(part.ddf, curvature, {0.5, 1.0, 2.0}), bySize);
}

TEST(Segmentation, ProgressEndsAtOneAndCancelThrows) {
  const GeneratedSurface part = plane();
  const CurvatureField curvature = computeCurvature(part.ddf);
  std::vector<double> seen;
  SegmentationParams params;
  params.progress = [&](double x) {
    seen.push_back(x);
    return true;
  };
  segmentByCurvatureType(part.ddf, curvature, params);
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  params.progress = [](double) { return false; };
  EXPECT_THROW(segmentByCurvatureType(part.ddf, curvature, params), Cancelled);
}

TEST(Segmentation, RejectsInvalidInput) {
  const GeneratedSurface part = plane();
  const CurvatureField curvature = computeCurvature(part.ddf);
  EXPECT_THROW(classifyToolRadius(curvature, {}), InvalidInput);
  EXPECT_THROW(classifyToolRadius(curvature, {2.0, 1.0}), InvalidInput);
  EXPECT_THROW(classifyCurvature(curvature, {.flatCurvaturePerMm = -1.0}), InvalidInput);
  EXPECT_THROW(maxToolRadiusField(curvature, 0.0), InvalidInput);
  std::vector<int> labels(part.ddf.faceCount(), 0);
  EXPECT_THROW(segmentFaces(part.ddf, labels, {}), InvalidInput);
  EXPECT_THROW(segmentFaces(part.ddf, labels, {"a"}, minFaces(0)), InvalidInput);
  labels.pop_back();
  EXPECT_THROW(segmentFaces(part.ddf, labels, {"a"}), InvalidInput);
  CurvatureField truncated = curvature;
  truncated.kMin.pop_back();
  EXPECT_THROW(segmentByCurvatureType(part.ddf, truncated), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
