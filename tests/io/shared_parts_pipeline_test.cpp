// SPDX-License-Identifier: MIT
// The issue-4 pipeline on the shared turbine blade and bunny, against independent oracles:
// Gauss-Bonnet, Euler characteristic, Poincare-Hopf, segmentation coverage and signs,
// streamline spacing and coverage by brute force, linking lengths.
#include "shared_parts_support.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/analysis/segmentation.h>
#include <ddfcam/planning/flow/flow_field.h>
#include <ddfcam/planning/lines/evenly_spaced_streamlines.h>
#include <ddfcam/planning/placement/path_linking.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace ddfcam::io {
namespace {

using namespace ddfcam::io::test;
using planning::Region;
using planning::Streamline;

struct SharedPart {
  const char* file;
};

void PrintTo(const SharedPart& p, std::ostream* os) {
  *os << p.file;
}

class SharedPartsPipeline : public ::testing::TestWithParam<SharedPart> {
 protected:
  void SetUp() override {
    part_ = sharedPart(GetParam().file);
    if (part_ == nullptr) GTEST_SKIP() << "shared data not found at " << meshPath(GetParam().file);
  }
  const char* name() const { return GetParam().file; }
  const Part* part_ = nullptr;
};

TEST_P(SharedPartsPipeline, SupportIsAClosedSurfaceOfEulerCharacteristicTwo) {
  const auto& ddf = part_->ddf;
  // Independent count: undirected edges from the face corner triples, each used twice.
  std::map<std::pair<int, int>, int> edgeUses;
  std::set<int> usedVertices;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto v = ddf.faceVertices(f);
    for (int e = 0; e < 3; ++e) {
      const int a = v[e], b = v[(e + 1) % 3];
      ++edgeUses[{std::min(a, b), std::max(a, b)}];
      usedVertices.insert(a);
    }
  }
  for (const auto& [edge, uses] : edgeUses)
    ASSERT_EQ(uses, 2) << "edge " << edge.first << "-" << edge.second << " of " << name();
  const long chi =
      static_cast<long>(usedVertices.size()) - static_cast<long>(edgeUses.size()) + ddf.faceCount();
  std::printf("[%s] V - E + F = %zu - %zu + %d = %ld\n", name(), usedVertices.size(),
              edgeUses.size(), ddf.faceCount(), chi);
  EXPECT_EQ(chi, 2);
  EXPECT_EQ(static_cast<int>(usedVertices.size()), ddf.vertexCount());
}

/// Integral of the Gaussian curvature over the represented surface: area of every raster
/// triangle times the mean of K at its corners, mm^0.
double integratedGaussianCurvature(const ddf::DisplacementField& ddf,
                                   const planning::CurvatureField& curvature) {
  const auto& K = curvature.gaussian;
  const std::vector<Vec3> points = rasterPoints(ddf);
  const std::size_t perFace = ddf.pointsPerFace();
  double integral = 0.0;
  forEachRasterTriangle(ddf, [&](int f, std::size_t a, std::size_t b, std::size_t c) {
    const std::size_t o = static_cast<std::size_t>(f) * perFace;
    const Vec3 e1 = points[o + b] - points[o + a], e2 = points[o + c] - points[o + a];
    integral += 0.5 * e1.cross(e2).norm() * (K[o + a] + K[o + b] + K[o + c]) / 3.0;
  });
  return integral;
}

/// Sum of the angle defects 2 pi - (sum of corner angles) over the support vertices.
double angleDefectSum(const ddf::DisplacementField& ddf) {
  std::vector<double> angleSum(ddf.vertexCount(), 0.0);
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto v = ddf.faceVertices(f);
    for (int e = 0; e < 3; ++e) {
      const Vec3 p = ddf.position(v[e]);
      const Vec3 u = (ddf.position(v[(e + 1) % 3]) - p).normalized();
      const Vec3 w = (ddf.position(v[(e + 2) % 3]) - p).normalized();
      angleSum[v[e]] += std::acos(std::clamp(u.dot(w), -1.0, 1.0));
    }
  }
  double defects = 0.0;
  for (double s : angleSum) defects += 2.0 * std::numbers::pi - s;
  return defects;
}

constexpr double kFourPi = 4.0 * std::numbers::pi;

// The vertex quadric fit does not conserve total curvature on these coarse, irregular scans:
// measured 0.52 x 4 pi on the bunny and 1.63 x 4 pi on the blade (m = 5; the integral of |K|
// is ~13 x 4 pi, i.e. the estimate is dominated by vertex-scale noise, and it stays 0.5..4 x
// 4 pi for 1..4 rings, weighted or not). The 2 % Gauss-Bonnet oracle of the estimator is
// checked on a smooth closed mesh below (ConvertedEllipsoidMesh); here the exact discrete
// Gauss-Bonnet of the support is the oracle and the estimator's figure is printed, with only a
// sanity range asserted.
TEST_P(SharedPartsPipeline, GaussBonnetOfTheSupportAndTheCurvatureEstimate) {
  const auto& ddf = part_->ddf;
  EXPECT_EQ(part_->curvature.method, planning::CurvatureMethod::VertexQuadricFit);
  const double integral = integratedGaussianCurvature(ddf, part_->curvature);
  const double defects = angleDefectSum(ddf);
  std::printf("[%s] integral of K dA = %.6f = %.4f x 4 pi; angle defects %.12f x 4 pi\n", name(),
              integral, integral / kFourPi, defects / kFourPi);
  EXPECT_NEAR(defects, kFourPi, 1e-9 * ddf.vertexCount());
  EXPECT_GT(integral, 0.25 * kFourPi);
  EXPECT_LT(integral, 4.0 * kFourPi);
}

// Poincare-Hopf, also across the bunny's sharp creases (support edge 3217-3231 turns the
// normals by 147.5 degrees, where a triangle encloses more than pi of curvature).
TEST_P(SharedPartsPipeline, FlowFieldSingularityIndicesSumToEulerCharacteristic) {
  const auto& ddf = part_->ddf;
  auto start = std::chrono::steady_clock::now();
  const planning::LineField field = planning::flowField(ddf, part_->curvature);
  const double fieldSeconds = secondsSince(start);
  start = std::chrono::steady_clock::now();
  const auto singularities = planning::findSingularities(ddf, field);
  const double findSeconds = secondsSince(start);
  // Poincare-Hopf needs the field defined at every raster point.
  std::size_t undefined = 0;
  for (const Vec3& d : field) undefined += d.squaredNorm() == 0.0 ? 1 : 0;
  double sum = 0.0, absSum = 0.0;
  for (const auto& s : singularities) {
    EXPECT_NEAR(2.0 * s.index, std::round(2.0 * s.index), 1e-9);
    sum += s.index;
    absSum += std::abs(s.index);
  }
  std::printf(
      "[%s] flow field %.3f s, singularities %.3f s: %zu singular triangles, index sum "
      "%.3f, sum |index| %.1f, undefined points %zu\n",
      name(), fieldSeconds, findSeconds, singularities.size(), sum, absSum, undefined);
  EXPECT_EQ(undefined, 0u);
  EXPECT_NEAR(sum, 2.0, 1e-9);
}

/// "convex 3" -> Convex, by the region name segmentByCurvatureType gives.
planning::CurvatureType typeOfRegion(const Region& region) {
  for (auto t : {planning::CurvatureType::Flat, planning::CurvatureType::Convex,
                 planning::CurvatureType::Concave, planning::CurvatureType::Saddle})
    if (region.name.starts_with(std::string(planning::curvatureTypeName(t)) + " ")) return t;
  ADD_FAILURE() << "region name " << region.name;
  return planning::CurvatureType::Flat;
}

TEST_P(SharedPartsPipeline, SegmentationCoversEveryFaceOnceWithMatchingCurvatureSigns) {
  const auto& ddf = part_->ddf;
  const auto& c = part_->curvature;
  auto start = std::chrono::steady_clock::now();
  const std::vector<Region> regions = planning::segmentByCurvatureType(ddf, c);
  std::printf("[%s] segmentation by curvature type: %.3f s, %zu regions\n", name(),
              secondsSince(start), regions.size());
  std::vector<int> cover(ddf.faceCount(), 0);
  std::map<planning::CurvatureType, int> facesOfType;
  const std::size_t perFace = ddf.pointsPerFace();
  int disagreeing = 0, disagreeingFaces = 0;
  for (const Region& r : regions) {
    ASSERT_FALSE(r.faces.empty()) << r.name;
    for (int f : r.faces) ++cover.at(f);
    const auto type = typeOfRegion(r);
    facesOfType[type] += static_cast<int>(r.faces.size());
    // Oracle: the signs of the mean and Gaussian curvature averaged over the region's points.
    double mean = 0.0, gauss = 0.0;
    for (int f : r.faces)
      for (std::size_t p = 0; p < perFace; ++p) {
        mean += c.mean[f * perFace + p];
        gauss += c.gaussian[f * perFace + p];
      }
    const double count = static_cast<double>(r.faces.size() * perFace);
    mean /= count, gauss /= count;
    bool agrees = true;
    switch (type) {
      case planning::CurvatureType::Convex:
        agrees = mean > 0 && gauss >= 0;
        break;
      case planning::CurvatureType::Concave:
        agrees = mean < 0 && gauss >= 0;
        break;
      case planning::CurvatureType::Saddle:
        agrees = gauss < 0;
        break;
      case planning::CurvatureType::Flat:
        agrees = true;
        break;
    }
    if (!agrees && r.faces.size() * 100 >= static_cast<std::size_t>(ddf.faceCount()))
      ADD_FAILURE() << r.name << " holds >= 1 % of the faces and disagrees with its curvature";
    if (!agrees) {
      ++disagreeing;
      disagreeingFaces += static_cast<int>(r.faces.size());
      std::printf("[%s]   %s (%zu faces): mean %.4g 1/mm, Gaussian %.4g 1/mm^2 disagree\n", name(),
                  r.name.c_str(), r.faces.size(), mean, gauss);
    }
  }
  for (int f = 0; f < ddf.faceCount(); ++f) ASSERT_EQ(cover[f], 1) << "face " << f;
  std::printf(
      "[%s] faces: convex %d, concave %d, saddle %d, flat %d; %d regions (%d faces) "
      "disagree with their averaged curvature signs\n",
      name(), facesOfType[planning::CurvatureType::Convex],
      facesOfType[planning::CurvatureType::Concave], facesOfType[planning::CurvatureType::Saddle],
      facesOfType[planning::CurvatureType::Flat], disagreeing, disagreeingFaces);
  EXPECT_GT(facesOfType[planning::CurvatureType::Convex], 0);
  EXPECT_GT(facesOfType[planning::CurvatureType::Concave], 0);
  EXPECT_GT(facesOfType[planning::CurvatureType::Saddle], 0);
  // Merged small regions may tip a region's average; they must stay a small minority.
  EXPECT_LE(disagreeingFaces, ddf.faceCount() / 50);

  // Tool-size classes relative to the part: also a partition of the faces.
  const double d = part_->diagonal;
  start = std::chrono::steady_clock::now();
  const auto bySize = planning::segmentByToolRadius(ddf, c, {d / 200, d / 50, d / 10});
  std::printf("[%s] segmentation by tool radius: %.3f s, %zu regions\n", name(),
              secondsSince(start), bySize.size());
  std::fill(cover.begin(), cover.end(), 0);
  for (const Region& r : bySize)
    for (int f : r.faces) ++cover.at(f);
  for (int f = 0; f < ddf.faceCount(); ++f) ASSERT_EQ(cover[f], 1) << "face " << f;
}

/// Brute force: smallest distance between points of two different lines (box pruned).
double minSeparation(const std::vector<std::vector<Vec3>>& lines) {
  std::vector<std::pair<Vec3, Vec3>> box;
  for (const auto& l : lines) {
    Vec3 lo = Vec3::Constant(1e300), hi = -lo;
    for (const Vec3& p : l) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    box.emplace_back(lo, hi);
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < lines.size(); ++a)
    for (const Vec3& p : lines[a])
      for (std::size_t b = a + 1; b < lines.size(); ++b) {
        if ((box[b].first - p).cwiseMax(p - box[b].second).cwiseMax(0.0).norm() >= best) continue;
        for (std::size_t j = 0; j + 1 < lines[b].size(); ++j)
          best = std::min(best, segmentDistance(p, lines[b][j], lines[b][j + 1]));
      }
  return best;
}

/// The largest convex region covered by evenly spaced streamlines, d_sep = diagonal / 40.
struct Cover {
  Region region;
  std::vector<std::uint8_t> mask;  ///< per face: 1 in the region
  std::vector<Streamline> lines;
  std::vector<std::vector<Vec3>> polylines;
  double dSep = 0.0, dTest = 0.0, step = 0.0;  ///< mm
};

/// Computes the Cover of @p part once (cached), printing the stage timings.
const Cover& coverLargestConvexRegion(const Part& part, const char* name) {
  static std::map<const Part*, Cover> cache;
  if (const auto it = cache.find(&part); it != cache.end()) return it->second;
  Cover c;
  for (Region& r : planning::segmentByCurvatureType(part.ddf, part.curvature))
    if (typeOfRegion(r) == planning::CurvatureType::Convex &&
        r.faces.size() > c.region.faces.size())
      c.region = std::move(r);
  c.mask.assign(part.ddf.faceCount(), 0);
  for (int f : c.region.faces) c.mask[f] = 1;
  auto start = std::chrono::steady_clock::now();
  planning::FlowFieldParams fp;
  fp.faceMask = c.mask;
  const planning::LineField field = planning::flowField(part.ddf, part.curvature, fp);
  const double fieldSeconds = secondsSince(start);
  planning::EvenSpacingParams ep;
  c.dSep = ep.separationMm = part.diagonal / 40.0;
  c.dTest = ep.testRatio * c.dSep;
  c.step = 0.1 * c.dSep;  // the default trace step
  ep.faceMask = c.mask;
  start = std::chrono::steady_clock::now();
  c.lines = planning::evenlySpacedStreamlines(part.ddf, field, ep);
  for (const Streamline& l : c.lines) c.polylines.push_back(l.polyline());
  std::printf("[%s] %s (%zu faces): field %.3f s, %zu lines %.3f s\n", name, c.region.name.c_str(),
              c.region.faces.size(), fieldSeconds, c.lines.size(), secondsSince(start));
  return cache[&part] = std::move(c);
}

/// Brute force on every 3rd raster point of the region: the largest distance to the lines
/// (an upper bound: the search stops at the first segment within d_sep / 2).
double worstGap(const ddf::DisplacementField& ddf, const Cover& c, std::size_t* sampled) {
  const std::vector<Vec3> points = rasterPoints(ddf);
  double worst = 0.0;
  for (int f : c.region.faces)
    for (std::size_t p = 0; p < ddf.pointsPerFace(); p += 3, ++*sampled) {
      const Vec3& q = points[f * ddf.pointsPerFace() + p];
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& l : c.polylines)
        for (std::size_t j = 0; j + 1 < l.size() && nearest > 0.5 * c.dSep; ++j)
          nearest = std::min(nearest, segmentDistance(q, l[j], l[j + 1]));
      worst = std::max(worst, nearest);
    }
  return worst;
}

TEST_P(SharedPartsPipeline, EvenlySpacedStreamlinesCoverTheLargestConvexRegion) {
  const Cover& c = coverLargestConvexRegion(*part_, name());
  ASSERT_FALSE(c.lines.empty());
  const auto start = std::chrono::steady_clock::now();
  std::size_t pointCount = 0;
  double offPart = 0.0;
  for (const Streamline& l : c.lines)
    for (const auto& p : l.points) {
      ASSERT_EQ(c.mask.at(p.face), 1) << "a line left the region";
      // Every 5th point against every mesh triangle (all of them would take seconds).
      if (pointCount++ % 5 == 0) offPart = std::max(offPart, meshDistance(part_->mesh, p.point));
    }
  const double separation = minSeparation(c.polylines);
  std::size_t sampled = 0;
  const double gap = worstGap(part_->ddf, c, &sampled);
  std::printf(
      "[%s]   d_sep %.5g mm, %zu points: off-part %.3g x diag, min separation %.4f d_sep "
      "(bound %.2f), worst gap of %zu samples %.4f d_sep (bound %.2f); checks %.3f s\n",
      name(), c.dSep, pointCount, offPart / part_->diagonal, separation / c.dSep,
      (c.dTest - c.step) / c.dSep, sampled, gap / c.dSep, (c.dSep + c.step) / c.dSep,
      secondsSince(start));
  EXPECT_LE(offPart, 1e-6 * part_->diagonal);
  EXPECT_GE(separation, c.dTest - c.step);
  EXPECT_LE(gap, c.dSep + c.step);
}

TEST_P(SharedPartsPipeline, LinkingReportsTheLengthsOfTheLines) {
  const Cover& c = coverLargestConvexRegion(*part_, name());
  double expectedCut = 0.0;
  int expectedPaths = 0;
  for (const auto& l : c.polylines) {
    if (l.size() < 2) continue;
    ++expectedPaths;
    for (std::size_t j = 0; j + 1 < l.size(); ++j) expectedCut += (l[j + 1] - l[j]).norm();
  }
  planning::LinkingParams lp;
  lp.clearanceMm = c.dSep;
  const auto start = std::chrono::steady_clock::now();
  const planning::LinkedPaths linked = planning::linkStreamlines(part_->ddf, c.lines, lp);
  std::printf("[%s] linking %.3f s: %d paths, cutting %.5g mm (independent %.5g), idle %.5g mm\n",
              name(), secondsSince(start), linked.pathCount, linked.cuttingLengthMm, expectedCut,
              linked.idleLengthMm);
  EXPECT_EQ(linked.pathCount, expectedPaths);
  EXPECT_NEAR(linked.cuttingLengthMm, expectedCut, 1e-9 * expectedCut);
  EXPECT_GE(linked.idleLengthMm, 0.0);
  double moved = 0.0;
  for (const auto& m : linked.moves)
    if (m.kind != planning::MoveKind::Cut)
      for (std::size_t j = 0; j + 1 < m.points.size(); ++j)
        moved += (m.points[j + 1] - m.points[j]).norm();
  EXPECT_NEAR(linked.idleLengthMm, moved, 1e-9 * std::max(moved, 1.0));
}

INSTANTIATE_TEST_SUITE_P(Io, SharedPartsPipeline,
                         ::testing::Values(SharedPart{"turbine-blade-jigsaw.stl"},
                                           SharedPart{"libigl-bunny.off"}),
                         [](const auto& info) {
                           return std::string(info.param.file).starts_with("turbine")
                                      ? std::string("TurbineBlade")
                                      : std::string("Bunny");
                         });

// Control for the shared parts: a smooth closed mesh (the ellipsoid support with its 5,120
// triangles, vertices on the ellipsoid) converted like a mesh file. Gauss-Bonnet holds to
// 1.0 % here (measured 1.0102 x 4 pi; 1.04 at 1,280 and 1.11 at 320 triangles: it converges),
// and the flow field's singularity indices sum to 2.
TEST(ConvertedEllipsoidMesh, GaussBonnetWithinTwoPercentAndIndicesSumToTwo) {
  const auto part = ddf::ellipsoidPart({.axesMm = Vec3(30, 20, 10), .subdivisions = 4});
  ddf::TriangleMesh mesh;
  for (int v = 0; v < part.ddf.vertexCount(); ++v) mesh.vertices.push_back(part.ddf.position(v));
  for (int f = 0; f < part.ddf.faceCount(); ++f) mesh.triangles.push_back(part.ddf.faceVertices(f));
  ddf::ConversionParams conversion;
  conversion.resolution = kResolution;
  const auto ddf = ddf::convertMeshToDdf(mesh, conversion).ddf;
  const auto curvature = planning::computeCurvature(ddf);
  ASSERT_EQ(curvature.method, planning::CurvatureMethod::VertexQuadricFit);
  const double integral = integratedGaussianCurvature(ddf, curvature);
  std::printf("[ellipsoid mesh] integral of K dA = %.4f x 4 pi\n", integral / kFourPi);
  EXPECT_NEAR(integral, kFourPi, 0.02 * kFourPi);
  double sum = 0.0;
  for (const auto& s : planning::findSingularities(ddf, planning::flowField(ddf, curvature)))
    sum += s.index;
  EXPECT_NEAR(sum, 2.0, 1e-9);
}

}  // namespace
}  // namespace ddfcam::io
