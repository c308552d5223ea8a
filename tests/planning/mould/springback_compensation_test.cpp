// SPDX-License-Identifier: MIT
// ddfcam: tests of the springback compensation loop against the linear model's closed forms.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/mould/springback_compensation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <utility>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

// Calls fn(flat index, support point g, vector v) for every raster point copy (allHeights()
// layout).
void forEachCopy(const ddf::DisplacementField& ddf,
                 const std::function<void(std::size_t, const Vec3&, const Vec3&)>& fn) {
  const int n = ddf.raster().steps();
  std::size_t l = 0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l) {
        const Vec3 bary = ddf.rasterBary(i, k);
        fn(l, ddf.basePoint(f, bary), ddf.vectorAt(f, bary));
      }
}

// P = target + bump(g) along v (bump in mm), with shared copies made equal.
std::vector<float> relaxedShape(const ddf::DisplacementField& target,
                                const std::function<double(const Vec3&)>& bumpMm) {
  ddf::DisplacementField relaxed = target;
  forEachCopy(target, [&](std::size_t l, const Vec3& g, const Vec3& v) {
    relaxed.allHeights()[l] = static_cast<float>(target.allHeights()[l] + bumpMm(g) / v.norm());
  });
  relaxed.synchronizeShared(ddf::SharedPolicy::Canonical);
  return relaxed.allHeights();
}

constexpr double kPlaneVector = 4.0;  // mm: the plane patch's vector length

ddf::DisplacementField planeTarget() {
  return ddf::planePatch({.origin = {0.0, 0.0},
                          .size = {40.0, 30.0},
                          .cellsX = 8,
                          .cellsY = 6,
                          .m = 9,
                          .planeZMm = 0.5,
                          .vectorLengthMm = kPlaneVector})
      .ddf;
}

double planeBump(const Vec3& g) {
  return 1.2 *
         std::exp(-((g.x() - 18.0) * (g.x() - 18.0) + (g.y() - 14.0) * (g.y() - 14.0)) / 60.0);
}

// Brute-force |T - P| on the plane: max |bump| and RMS weighted by a third of every planar raster
// triangle's area per corner (the plane's normal is v's direction, so the deviation is the bump).
std::pair<double, double> planeBumpMaxRms(const ddf::DisplacementField& target) {
  const int n = target.raster().steps();
  double maxMm = 0.0, sumW = 0.0, sumW2 = 0.0;
  for (int f = 0; f < target.faceCount(); ++f) {
    auto at = [&](int i, int k) { return target.basePoint(f, target.rasterBary(i, k)); };
    auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
      const double third = (b - a).cross(c - a).norm() / 6.0;
      for (const Vec3* p : {&a, &b, &c}) {
        sumW += third;
        sumW2 += third * planeBump(*p) * planeBump(*p);
        maxMm = std::max(maxMm, std::abs(planeBump(*p)));
      }
    };
    for (int k = 0; k < n; ++k)
      for (int i = 0; i + k < n; ++i) {
        add(at(i, k), at(i + 1, k), at(i, k + 1));
        if (i + k + 1 < n) add(at(i + 1, k), at(i, k + 1), at(i + 1, k + 1));
      }
  }
  return {maxMm, std::sqrt(sumW2 / sumW)};
}

LinearSpringbackModel isotropicModel(const ddf::DisplacementField& target, double alpha) {
  LinearSpringbackModel model;
  model.alpha = alpha;
  model.relaxedHeights = relaxedShape(target, planeBump);
  return model;
}

void formWithModel(CompensationHistory& history, const LinearSpringbackModel& model) {
  recordFormedResponse(
      history, linearSpringback(model, history.target, history.iterations.back().mouldHeights),
      "linear model");
}

TEST(SpringbackCompensation, LambdaOneFollowsTheAlphaPowerLaw) {
  const ddf::DisplacementField target = planeTarget();
  const auto [maxBump, rmsBump] = planeBumpMaxRms(target);
  for (const double alpha : {0.2, 0.3, 0.6}) {
    const LinearSpringbackModel model = isotropicModel(target, alpha);
    CompensationHistory history = startCompensation(target);
    for (int j = 0; j < 5; ++j) {
      if (j > 0) compensationStep(history, 1.0);
      formWithModel(history, model);
      const double expected = std::pow(alpha, j + 1);
      const CompensationIteration& it = history.iterations.back();
      EXPECT_NEAR(it.maxDeviationMm, expected * maxBump, 2e-6 + 1e-5 * maxBump)
          << alpha << " " << j;
      EXPECT_NEAR(it.rmsDeviationMm, expected * rmsBump, 2e-6 + 1e-5 * rmsBump)
          << alpha << " " << j;
    }
    EXPECT_EQ(history.iterations.size(), 5u);
    EXPECT_EQ(history.iterations[1].lambda, 1.0);
  }
}

TEST(SpringbackCompensation, LambdaOneOverOneMinusAlphaConvergesInOneStep) {
  const ddf::DisplacementField target = planeTarget();
  const double alpha = 0.35;
  const LinearSpringbackModel model = isotropicModel(target, alpha);
  CompensationHistory history = startCompensation(target);
  formWithModel(history, model);
  EXPECT_GT(history.iterations[0].maxDeviationMm, 0.3);
  compensationStep(history, 1.0 / (1.0 - alpha));
  formWithModel(history, model);
  EXPECT_LT(history.iterations[1].maxDeviationMm, 1e-5);
  EXPECT_LT(history.iterations[1].rmsDeviationMm, 1e-5);
}

TEST(SpringbackCompensation, LambdaBeyondTwoOverOneMinusAlphaDiverges) {
  const ddf::DisplacementField target = planeTarget();
  const double alpha = 0.3;
  const double lambda = 2.5 / (1.0 - alpha);  // error factor |1 - lambda (1 - alpha)| = 1.5
  const LinearSpringbackModel model = isotropicModel(target, alpha);
  CompensationHistory history = startCompensation(target);
  formWithModel(history, model);
  for (int j = 1; j < 5; ++j) {
    compensationStep(history, lambda);
    formWithModel(history, model);
    const CompensationIteration& it = history.iterations[j];
    EXPECT_NEAR(it.maxDeviationMm / history.iterations[j - 1].maxDeviationMm, 1.5, 1e-4);
    EXPECT_GT(it.rmsDeviationMm, history.iterations[j - 1].rmsDeviationMm * 1.49);
  }
}

TEST(SpringbackCompensation, MouldMeshIsTheRasterSurfaceOfTheMouldHeights) {
  const ddf::DisplacementField target = planeTarget();
  const LinearSpringbackModel model = isotropicModel(target, 0.3);
  CompensationHistory history = startCompensation(target);
  formWithModel(history, model);
  compensationStep(history, 1.0);
  const ddf::TriangleMesh mesh = mouldMesh(history, 1);
  const int n = target.raster().steps();
  EXPECT_EQ(mesh.triangles.size(), static_cast<std::size_t>(target.faceCount() * n * n));
  // c_1 = t - (s_0 - t) = t - 0.3 bump / L on the plane: z = 0.5 - 0.3 bump(x, y).
  for (const Vec3& q : mesh.vertices) EXPECT_NEAR(q.z(), 0.5 - 0.3 * planeBump(q), 2e-6);
}

LinearSpringbackModel anisotropicModel(const ddf::DisplacementField& target,
                                       const std::function<double(const Vec3&)>& bumpMm) {
  LinearSpringbackModel model;
  model.axisAlpha = Eigen::Vector3d(0.1, 0.3, 0.5);
  model.relaxedHeights = relaxedShape(target, bumpMm);
  return model;
}

TEST(SpringbackCompensation, AnisotropicModelConvergesMonotonically) {
  ddf::SaddleParams params;
  params.grid.cellsX = 10;
  params.grid.cellsY = 10;
  params.grid.m = 9;
  const ddf::DisplacementField target = ddf::saddlePatch(params).ddf;
  const LinearSpringbackModel model = anisotropicModel(target, [](const Vec3& g) {
    return 0.5 * std::exp(-((g.x() - 2.0) * (g.x() - 2.0) + g.y() * g.y()) / 30.0);
  });
  CompensationHistory history = startCompensation(target);
  formWithModel(history, model);
  EXPECT_GT(history.iterations[0].maxDeviationMm, 0.03);
  for (int j = 1; j <= 6; ++j) {
    compensationStep(history, 1.0);
    formWithModel(history, model);
    const CompensationIteration& now = history.iterations[j];
    const CompensationIteration& before = history.iterations[j - 1];
    EXPECT_LT(now.maxDeviationMm, before.maxDeviationMm) << j;
    EXPECT_LT(now.rmsDeviationMm, before.rmsDeviationMm) << j;
    // The normal springback share lies between the smallest and largest axis share.
    EXPECT_LT(now.rmsDeviationMm, 0.55 * before.rmsDeviationMm) << j;
  }
}

// Largest angle between the normals of neighbouring mesh triangles, rad: {across support
// edges, within support faces}; triangle t lies on support face t / trianglesPerFace.
std::pair<double, double> largestDihedral(const ddf::TriangleMesh& mesh, int trianglesPerFace) {
  std::map<std::pair<int, int>, std::vector<int>> edges;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int e = 0; e < 3; ++e) {
      const int a = mesh.triangles[t][e], b = mesh.triangles[t][(e + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  auto normal = [&](int t) {
    const auto& tri = mesh.triangles[t];
    const Vec3& a = mesh.vertices[tri[0]];
    return Vec3((mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a).normalized());
  };
  double seam = 0.0, inside = 0.0;
  for (const auto& [edge, tris] : edges) {
    if (tris.size() != 2) continue;
    const double angle = std::acos(std::clamp(normal(tris[0]).dot(normal(tris[1])), -1.0, 1.0));
    double& slot = tris[0] / trianglesPerFace == tris[1] / trianglesPerFace ? inside : seam;
    slot = std::max(slot, angle);
  }
  return {seam, inside};
}

TEST(SpringbackCompensation, CompensatedMouldStaysSmoothAcrossSupportSeams) {
  const ddf::DisplacementField target =
      ddf::cylinderPart({.radiusMm = 10.0, .lengthMm = 20.0, .segments = 16, .rings = 4, .m = 7})
          .ddf;
  const LinearSpringbackModel model = anisotropicModel(target, [](const Vec3& g) {
    return 1.0 * std::exp(-(g.z() - 10.0) * (g.z() - 10.0) / 30.0) * (1.0 + 0.5 * g.x() / 10.0);
  });
  CompensationHistory history = startCompensation(target);
  for (int j = 0; j < 5; ++j) {
    if (j > 0) compensationStep(history, 1.0);
    formWithModel(history, model);
  }
  const std::vector<float>& mould = history.iterations.back().mouldHeights;
  // Every copy of a shared raster point carries the same mould height (no cracks).
  std::map<ddf::PointId, float> first;
  const int n = target.raster().steps();
  std::size_t l = 0, shared = 0;
  for (int f = 0; f < target.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l) {
        const auto [it, inserted] = first.emplace(target.topology().id(f, i, k), mould[l]);
        if (inserted) continue;
        EXPECT_EQ(it->second, mould[l]) << "face " << f << " (" << i << "," << k << ")";
        ++shared;
      }
  EXPECT_GT(shared, 0u);
  const auto [targetSeam, targetInside] = largestDihedral(mouldMesh(history, 0), n * n);
  const auto [mouldSeam, mouldInside] = largestDihedral(mouldMesh(history, 4), n * n);
  RecordProperty("targetSeamDeg", std::to_string(targetSeam * 180.0 / 3.14159265));
  RecordProperty("mouldSeamDeg", std::to_string(mouldSeam * 180.0 / 3.14159265));
  RecordProperty("mouldInsideDeg", std::to_string(mouldInside * 180.0 / 3.14159265));
  EXPECT_LT(mouldSeam, 1.5 * mouldInside);
  EXPECT_LT(mouldSeam, 1.5 * targetSeam);
  EXPECT_LT(history.iterations[4].maxDeviationMm, 0.05 * history.iterations[0].maxDeviationMm);
}

TEST(SpringbackCompensation, CalibrationReproducesTheFirstForming) {
  const ddf::DisplacementField target =
      ddf::cylinderPart({.radiusMm = 10.0, .lengthMm = 20.0, .segments = 16, .rings = 4, .m = 7})
          .ddf;
  std::vector<float> measured = target.allHeights();
  forEachCopy(target, [&](std::size_t l, const Vec3& g, const Vec3&) {
    measured[l] += static_cast<float>(0.1 * std::sin(g.z() / 3.0) + 0.05 * g.x() / 10.0);
  });
  const LinearSpringbackModel model = calibrateSpringback(target, measured, 0.3);
  EXPECT_EQ(model.alpha, 0.3);
  EXPECT_FALSE(model.axisAlpha.has_value());
  const std::vector<float> formed = linearSpringback(model, target, target.allHeights());
  ASSERT_EQ(formed.size(), measured.size());
  for (std::size_t l = 0; l < formed.size(); ++l) EXPECT_NEAR(formed[l], measured[l], 1e-6f);
}

TEST(SpringbackCompensation, FormedHeightsOfAParallelPlaneAreItsOffset) {
  const ddf::DisplacementField target = planeTarget();
  // The plane z = 1.3 mm over the whole patch: the stubbles are its normals, so every height is
  // 1.3 / L.
  ddf::TriangleMesh formed;
  formed.vertices = {{-5.0, -5.0, 1.3}, {45.0, -5.0, 1.3}, {45.0, 35.0, 1.3}, {-5.0, 35.0, 1.3}};
  formed.triangles = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<float> heights = formedHeightsFromMesh(target, formed);
  ASSERT_EQ(heights.size(), target.allHeights().size());
  for (const float h : heights) EXPECT_NEAR(h, 1.3 / kPlaneVector, 1e-6);
  ddf::TriangleMesh far = formed;
  for (Vec3& p : far.vertices) p.x() += 500.0;
  EXPECT_THROW(formedHeightsFromMesh(target, far), InvalidInput);
}

TEST(SpringbackCompensation, RejectsBadInput) {
  EXPECT_THROW(startCompensation(ddf::DisplacementField{}), InvalidInput);
  const ddf::DisplacementField target = planeTarget();
  CompensationHistory history = startCompensation(target);
  EXPECT_THROW(compensationStep(history, 1.0), InvalidInput);  // no response yet
  EXPECT_THROW(recordFormedResponse(history, std::vector<float>(3, 0.0f), "x"), InvalidInput);
  EXPECT_THROW(recordFormedResponse(history,
                                    std::vector<float>(target.allHeights().size(),
                                                       std::numeric_limits<float>::quiet_NaN()),
                                    "x"),
               InvalidInput);
  EXPECT_TRUE(history.iterations[0].formedHeights.empty());
  const LinearSpringbackModel model = isotropicModel(target, 0.3);
  formWithModel(history, model);
  for (const double lambda : {0.0, -1.0, 10.5, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_THROW(compensationStep(history, lambda), InvalidInput) << lambda;
  EXPECT_EQ(history.iterations.size(), 1u);
  EXPECT_THROW(mouldMesh(history, 1), InvalidInput);
  EXPECT_THROW(mouldMesh(history, -1), InvalidInput);
  EXPECT_THROW(linearSpringback(model, target, std::vector<float>(5, 0.0f)), InvalidInput);
  LinearSpringbackModel bad = model;
  bad.relaxedHeights.clear();
  EXPECT_THROW(linearSpringback(bad, target, target.allHeights()), InvalidInput);
  bad = model;
  bad.alpha = 1.0;
  EXPECT_THROW(linearSpringback(bad, target, target.allHeights()), InvalidInput);
  bad.alpha = 0.3;
  bad.axisAlpha = Eigen::Vector3d(0.1, -0.2, 0.3);
  EXPECT_THROW(linearSpringback(bad, target, target.allHeights()), InvalidInput);
  EXPECT_THROW(calibrateSpringback(target, target.allHeights(), 0.0), InvalidInput);
  EXPECT_THROW(calibrateSpringback(target, target.allHeights(), 1.0), InvalidInput);
  EXPECT_THROW(calibrateSpringback(target, std::vector<float>(2), 0.3), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
