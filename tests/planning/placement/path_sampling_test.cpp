// SPDX-License-Identifier: MIT
// Tests of the sampling step rules and of placeAlongPath against chord, cusp and count formulas.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/path_sampling.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kDeg = std::numbers::pi / 180.0;

const Tool kBall{
    .name = "ball end R5", .kind = ToolKind::BallEnd, .radiusMm = 5.0, .widthMm = 10.0};
const Tool kFlat{
    .name = "flat end R5", .kind = ToolKind::FlatEnd, .radiusMm = 5.0, .widthMm = 10.0};

PathSamplingParams sampling(double toleranceMm, std::optional<double> stepMm = std::nullopt,
                            double rasterFactor = 1.0) {
  PathSamplingParams p;
  p.toleranceMm = toleranceMm;
  p.stepOverrideMm = stepMm;
  p.rasterSpacingFactor = rasterFactor;
  return p;
}

/// The surface location at @p p, searched on faces whose support centroid is within @p reach.
ddf::SurfaceLocation locate(const ddf::DisplacementField& ddf, const Vec3& p, double reach) {
  std::optional<ddf::SurfaceLocation> best;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& v = ddf.faceVertices(f);
    const Vec3 c = (ddf.position(v[0]) + ddf.position(v[1]) + ddf.position(v[2])) / 3.0;
    if ((c - p).norm() > reach) continue;
    const auto loc = ddf::locateOnFace(ddf, f, p);
    if (loc && (!best || (loc->point - p).norm() < (best->point - p).norm())) best = loc;
  }
  EXPECT_TRUE(best.has_value());
  return *best;
}

double polylineLength(const std::vector<ddf::SurfaceLocation>& pass) {
  double length = 0;
  for (std::size_t i = 1; i < pass.size(); ++i)
    length += (pass[i].point - pass[i - 1].point).norm();
  return length;
}

TEST(ToolFeedStep, CircularFeedSectionsGiveTheSagittaFormula) {
  const double expected = 2.0 * std::sqrt(2.0 * 5.0 * 0.01 - 0.01 * 0.01);  // 0.632139 (oracles)
  EXPECT_NEAR(toolFeedStepMm(kBall, {}, 0.0, 0.01), expected, 2e-5);
  EXPECT_NEAR(toolFeedStepMm(kBall, {20.0, -15.0, 0.0}, 0.0, 0.01), expected, 2e-5);
  const Tool roll{.name = "roll", .radiusMm = 5.0, .widthMm = 10.0};
  EXPECT_NEAR(toolFeedStepMm(roll, {}, 0.0, 0.01), expected, 2e-5);
  // Curved surfaces: h ~ (L^2 / 8)(1/R + kappa) for small h.
  for (const double kappa : {0.05, -0.05}) {
    const double approx = std::sqrt(8.0 * 0.01 / (1.0 / 5.0 + kappa));
    EXPECT_NEAR(toolFeedStepMm(kBall, {}, kappa, 0.01), approx, 2e-3 * approx) << kappa;
  }
}

TEST(ToolFeedStep, FlatEndWithLeadLeavesAVeeAndWithoutLeadItsDiameter) {
  for (const double lead : {2.0, 10.0, 30.0}) {
    const double l = lead * kDeg;
    EXPECT_NEAR(toolFeedStepMm(kFlat, {lead, 0.0, 0.0}, 0.0, 0.01),
                0.01 * (std::tan(l) + 1.0 / std::tan(l)), 1e-9)
        << lead;
  }
  EXPECT_NEAR(toolFeedStepMm(kFlat, {}, 0.0, 0.01), 10.0, 1e-9);
}

TEST(ChooseStep, TheSmallestRuleBindsAndTheOverrideWins) {
  const double rho = 10.0, tol = 0.05;
  SamplingStep s = chooseStep(kFlat, {}, {1.0 / rho, 0.0, 0.0}, sampling(tol));
  EXPECT_NEAR(s.stepMm, std::sqrt(8.0 * tol * rho), 1e-12);  // L = sqrt(8 delta rho)
  EXPECT_EQ(s.rule, StepRule::FeedChord);
  s = chooseStep(kFlat, {}, {1.0 / rho, 0.0, 0.5}, sampling(tol));
  EXPECT_NEAR(s.stepMm, 0.5, 1e-12);
  EXPECT_EQ(s.rule, StepRule::RasterSpacing);
  s = chooseStep(kBall, {}, {0.0, 0.0, 0.0}, sampling(0.01));
  EXPECT_EQ(s.rule, StepRule::ToolProfile);
  s = chooseStep(kBall, {}, {0.1, 0.0, 0.1}, sampling(0.01, 3.0));
  EXPECT_EQ(s.rule, StepRule::Override);
  EXPECT_EQ(s.stepMm, 3.0);
  EXPECT_STREQ(stepRuleName(StepRule::FeedChord), "feed chord");
}

TEST(PlaceAlongPath, CirclePathIsSampledAtTheChordStep) {
  // Coarse raster (spacing ~5.7 mm) so that the chord rule binds: rho = 10, T = 0.05 -> 2 mm.
  const auto plane = ddf::planePatch({.cellsX = 4, .cellsY = 3, .m = 3});
  const double rho = 10.0, tol = 0.05;
  std::vector<ddf::SurfaceLocation> pass;
  for (int i = 0; i <= 720; ++i) {
    const double a = i * 0.5 * kDeg;
    pass.push_back(
        locate(plane.ddf, Vec3(20 + rho * std::cos(a), 15 + rho * std::sin(a), 0.25), 15.0));
  }
  const PlacedPath placed = placeAlongPathDetailed(plane.ddf, {pass}, kFlat, 2, {}, sampling(tol));
  ASSERT_EQ(placed.passes.size(), 1u);
  const PassSampling& ps = placed.passes[0];
  EXPECT_EQ(ps.step.rule, StepRule::FeedChord);
  EXPECT_NEAR(ps.step.stepMm, std::sqrt(8.0 * tol * rho), 1e-3);
  const double length = polylineLength(pass);
  EXPECT_EQ(placed.path.poses.size(), std::ceil(length / ps.step.stepMm) + 1);
  EXPECT_EQ(ps.sweepInsertedPoses, 0);
  EXPECT_EQ(placed.path.tool, 2);
  EXPECT_EQ(placed.path.passStarts, std::vector<int>{0});
  const auto& poses = placed.path.poses;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_NEAR((poses[i].contact - Vec3(20, 15, 0.25)).norm(), rho, 1e-3);
    EXPECT_LT((poses[i].pose.translation() - poses[i].contact).norm(), 1e-9);  // tip on contact
    EXPECT_LT((poses[i].pose.linear().col(2) - Vec3::UnitZ()).norm(), 1e-9);
    if (i == 0) continue;
    const double chord = (poses[i].contact - poses[i - 1].contact).norm();
    EXPECT_LE(rho - std::sqrt(rho * rho - chord * chord / 4), tol * 1.002);  // chord error
  }
}

std::vector<ddf::SurfaceLocation> straightPass(const ddf::DisplacementField& ddf) {
  std::vector<ddf::SurfaceLocation> pass;
  for (int i = 0; i <= 60; ++i) pass.push_back(locate(ddf, Vec3(5 + 0.5 * i, 15.3, 0.25), 4.0));
  return pass;
}

TEST(PlaceAlongPath, StraightLineCountsFollowTheBindingRule) {
  const auto plane = ddf::planePatch();  // 2 mm cells, m = 17
  const auto pass = straightPass(plane.ddf);
  const double spacing = (2.0 + 2.0 + 2.0 * std::sqrt(2.0)) / 3.0 / 16.0;
  PlacedPath placed = placeAlongPathDetailed(plane.ddf, {pass}, kBall, 0, {});
  EXPECT_EQ(placed.passes[0].step.rule, StepRule::RasterSpacing);
  EXPECT_NEAR(placed.passes[0].step.stepMm, spacing, 1e-12);
  EXPECT_EQ(placed.path.poses.size(), std::ceil(30.0 / spacing) + 1);
  for (const PathPose& p : placed.path.poses) {
    EXPECT_NEAR(p.contact.z(), 0.25, 1e-9);
    EXPECT_NEAR(p.contact.y(), 15.3, 1e-9);
    EXPECT_LT((p.pose.translation() - p.contact).norm(), 1e-9);  // ball-end tip
  }
  // Without the raster rule the ball's own cusp rule binds: 0.632139 mm -> 49 poses.
  placed =
      placeAlongPathDetailed(plane.ddf, {pass}, kBall, 0, {}, sampling(0.01, std::nullopt, 0.0));
  EXPECT_EQ(placed.passes[0].step.rule, StepRule::ToolProfile);
  EXPECT_EQ(placed.path.poses.size(), 49u);
  // Override respected.
  const ToolPath overridden =
      placeAlongPath(plane.ddf, {pass, pass}, kBall, 0, {}, sampling(0.01, 0.7));
  EXPECT_EQ(overridden.poses.size(), 2u * 44u);
  EXPECT_EQ(overridden.passStarts, (std::vector<int>{0, 44}));
  EXPECT_NEAR((overridden.poses[1].contact - overridden.poses[0].contact).norm(), 30.0 / 43, 1e-9);
}

TEST(PlaceAlongPath, AxisTurningOnACylinderInsertsPosesByEq58) {
  const auto cylinder = ddf::cylinderPart({.radiusMm = 10.0});
  const Tool longBall{
      .name = "long ball end", .kind = ToolKind::BallEnd, .radiusMm = 2.0, .widthMm = 20.0};
  std::vector<ddf::SurfaceLocation> pass;
  for (int i = 0; i <= 45; ++i) {
    const double a = i * 2.0 * kDeg;
    pass.push_back(locate(cylinder.ddf, Vec3(10 * std::cos(a), 10 * std::sin(a), 15.2), 4.0));
  }
  const PlacedPath placed = placeAlongPathDetailed(cylinder.ddf, {pass}, longBall, 0, {});
  const PassSampling& ps = placed.passes[0];
  EXPECT_EQ(ps.step.rule, StepRule::RasterSpacing);
  EXPECT_EQ(ps.bindingRule, StepRule::OrientationSweep);
  // The top centre sits 20 mm above the tip: it sweeps (10 + 20) / 10 = 3 times the contact,
  // so about two poses are inserted per interval.
  const int intervals = ps.uniformPoses - 1;
  EXPECT_NEAR(ps.sweepInsertedPoses, 2.0 * intervals, 0.05 * intervals);
  const double w = ps.inputs.rasterSpacingMm;
  double sumTop = 0, maxTop = 0;
  const auto& poses = placed.path.poses;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const Vec3 top0 = poses[i - 1].pose * Vec3(0, 0, 20), top1 = poses[i].pose * Vec3(0, 0, 20);
    sumTop += (top1 - top0).norm();
    maxTop = std::max(maxTop, (top1 - top0).norm());
    EXPECT_LE((poses[i].contact - poses[i - 1].contact).norm(), w * (1 + 1e-6));
  }
  EXPECT_LE(sumTop / (poses.size() - 1), w);
  EXPECT_LE(maxTop, 1.02 * w);
}

TEST(PlaceAlongPath, RejectsBadInputNamingIt) {
  const auto plane = ddf::planePatch({.cellsX = 4, .cellsY = 3, .m = 5});
  const auto pass = straightPass(plane.ddf);
  const auto expectMessage = [&](const PathSamplingParams& p, const std::string& word) {
    try {
      placeAlongPath(plane.ddf, {pass}, kBall, 0, {}, p);
      ADD_FAILURE() << "no exception for " << word;
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  expectMessage(sampling(-0.01), "tolerance");
  expectMessage(sampling(0.01, 0.0), "step override");
  expectMessage(sampling(0.01, std::nullopt, -1.0), "raster spacing factor");
  EXPECT_THROW(placeAlongPath(plane.ddf, {{pass[0]}}, kBall, 0, {}), InvalidInput);
  auto broken = pass;
  broken[3].face = 999;
  EXPECT_THROW(placeAlongPath(plane.ddf, {broken}, kBall, 0, {}), InvalidInput);
  EXPECT_THROW(toolFeedStepMm(kBall, {}, 0.0, -1.0), InvalidInput);
  EXPECT_THROW(placeAlongPath(plane.ddf, {pass}, kBall, 0, {}, sampling(0.01, 1e-9)), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
