// SPDX-License-Identifier: MIT
// Tests of scallop heights: analytic formulas against the oracles note, and simulated passes.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/inspection/scallop_prediction.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

TEST(ScallopPrediction, BallMatchesOracleSpacings) {
  // oracles note: R = 5, h = 0.01 -> w = 0.632139 (plane); rho = 20: 0.565266 convex, 0.730124
  // concave; rho = 200: 0.624367 / 0.640208.
  EXPECT_NEAR(ballScallopOnPlaneMm(5.0, 0.632139), 0.01, 2e-6);
  EXPECT_NEAR(*ballScallopMm(5.0, 0.632139, 0.0), 0.01, 2e-6);
  EXPECT_NEAR(*ballScallopMm(5.0, 0.565266, 1.0 / 20.0), 0.01, 2e-6);
  EXPECT_NEAR(*ballScallopMm(5.0, 0.730124, -1.0 / 20.0), 0.01, 2e-6);
  EXPECT_NEAR(*ballScallopMm(5.0, 0.624367, 1.0 / 200.0), 0.01, 2e-6);
  EXPECT_NEAR(*ballScallopMm(5.0, 0.640208, -1.0 / 200.0), 0.01, 2e-6);
  EXPECT_FALSE(ballScallopMm(5.0, 1.0, -1.0 / 4.0));  // concave radius below R: gouge
  EXPECT_THROW(ballScallopOnPlaneMm(5.0, 11.0), InvalidInput);
  EXPECT_THROW(ballScallopMm(-1.0, 1.0, 0.0), InvalidInput);
  // The approximation (w^2/8)(1/R + kappa) agrees to second order for small spacings.
  EXPECT_NEAR(approximateScallopMm(5.0, 0.565266, 0.05) / 0.01, 1.0, 2e-3);
}

TEST(ScallopPrediction, FlatWheelAndTiltedFlat) {
  // Edge error of one pass ~ kappa B^2/8; exact sqrt(rho^2 + B^2/4) - rho.
  EXPECT_NEAR(flatWheelEdgeErrorMm(10.0, 1.0 / 50.0), std::sqrt(2500.0 + 25.0) - 50.0, 1e-12);
  EXPECT_NEAR(flatWheelEdgeErrorMm(10.0, 1.0 / 50.0), 100.0 / 8.0 / 50.0, 0.01 * 0.25);
  EXPECT_NEAR(flatWheelEdgeErrorMm(10.0, -1.0 / 50.0), -(50.0 - std::sqrt(2500.0 - 25.0)), 1e-12);
  EXPECT_EQ(flatWheelEdgeErrorMm(10.0, 0.0), 0.0);
  EXPECT_EQ(*flatWheelScallopMm(10.0, 8.0, 0.0), 0.0);
  EXPECT_FALSE(flatWheelScallopMm(10.0, 12.0, 0.0));
  EXPECT_FALSE(flatWheelScallopMm(10.0, 4.0, -0.02));
  // Polygon corner of tangent lines theta = w kappa apart: rho (1/cos(theta/2) - 1).
  EXPECT_NEAR(*flatWheelScallopMm(10.0, 4.0, 0.02), 50.0 * (1.0 / std::cos(0.04) - 1.0), 1e-12);
  EXPECT_FALSE(flatWheelScallopMm(10.0, 10.5, 0.02));  // the segments no longer meet
  EXPECT_NEAR(tiltedFlatEffectiveRadiusMm(5.0, std::numbers::pi / 6.0), 10.0, 1e-12);
  // Ellipse of semi-axes R_t and R_t sin l vs the osculating circle R_t / sin l.
  const double l = 0.2;
  EXPECT_NEAR(tiltedFlatScallopOnPlaneMm(5.0, l, 0.5) /
                  approximateScallopMm(tiltedFlatEffectiveRadiusMm(5.0, l), 0.5, 0.0),
              1.0, 1e-3);
  EXPECT_NEAR(tiltedFlatScallopOnPlaneMm(5.0, l, 8.0), 5.0 * std::sin(l) * (1.0 - 0.6), 1e-12);
}

TEST(ScallopPrediction, MeasuredScallopIsAreaQuantile) {
  ddf::PlanePatchParams params;
  params.m = 9;
  const ddf::DisplacementField plane = ddf::planePatch(params).ddf;
  ScalarField map{"deviation", "mm", true,
                  std::vector<float>(plane.allHeights().size(), 0.0f), {}};
  map.values[5] = 0.3f;  // a single spike
  EXPECT_NEAR(measuredScallopMm(map, plane), 0.3, 1e-7);
  EXPECT_EQ(measuredScallopMm(map, plane, {}, {0.99}), 0.0);
  for (float& v : map.values) v = -0.1f;
  EXPECT_EQ(measuredScallopMm(map, plane), 0.0);  // overcut: no scallop
  EXPECT_THROW(measuredScallopMm(map, plane, {}, {0.0}), InvalidInput);
}

// Small patches and a coarser tool mesh keep each simulation well below a second; the inscribed
// mesh cuts at most chordToleranceMm too little.
ScallopSimulationParams fastParams() {
  ScallopSimulationParams params;
  params.passes = 3;
  params.passLengthMm = 1.0;
  params.chordToleranceMm = 0.002;
  return params;
}

TEST(ScallopPrediction, SimulatedBallOnPlaneMatchesExactScallop) {
  ScallopCase c;
  c.label = "ball R2";
  c.radiusMm = 2.0;
  c.spacingMm = 1.0;  // h = 0.0635
  const ScallopSimulationParams params = fastParams();
  const ScallopRow row = simulateScallopCase(c, params);
  EXPECT_NEAR(row.predictedMm, 2.0 - std::sqrt(4.0 - 0.25), 1e-12);
  EXPECT_LE(row.rasterSpacingMm, c.spacingMm / 10.0 + 1e-12);
  // Cusps lie on raster points; the inscribed tool mesh leaves at most its chord tolerance.
  EXPECT_NEAR(row.simulatedMm, row.predictedMm, params.chordToleranceMm + 1e-4);
}

// The scallop table's default precision (the Error map panel's first row): a ball R5, passes
// 1 mm apart on a plane, four passes of 6 mm and a tool mesh within 0.5 micrometres.
TEST(ScallopPrediction, DefaultPrecisionBallOnPlaneMatchesExactScallop) {
  ScallopCase c;
  c.label = "ball R5, plane";
  c.radiusMm = 5.0;
  c.spacingMm = 1.0;
  const ScallopSimulationParams params;
  const ScallopRow row = simulateScallopCase(c, params);
  EXPECT_NEAR(row.predictedMm, 5.0 - std::sqrt(25.0 - 0.25), 1e-12);
  EXPECT_NEAR(row.simulatedMm, row.predictedMm, params.chordToleranceMm + 1e-4);
}

TEST(ScallopPrediction, SimulatedBallOnConvexCylinder) {
  ScallopCase c;
  c.radiusMm = 2.0;
  c.spacingMm = 1.0;
  c.crossFeedCurvaturePerMm = 1.0 / 20.0;
  const ScallopSimulationParams params = fastParams();
  const ScallopRow row = simulateScallopCase(c, params);
  EXPECT_NEAR(row.spacingMm, 1.0, 0.01);
  const double exact = *ballScallopMm(2.0, row.spacingMm, c.crossFeedCurvaturePerMm);
  EXPECT_NEAR(row.predictedMm, exact, 1e-12);
  EXPECT_NEAR(row.simulatedMm, exact, params.chordToleranceMm + 2e-4);
}

TEST(ScallopPrediction, SimulatedFlatWheelOnConvexCylinder) {
  ScallopCase c;
  c.label = "roll R10 B6";
  c.model = ScallopToolModel::FlatWheel;
  c.radiusMm = 10.0;
  c.widthMm = 6.0;
  c.spacingMm = 4.0;
  c.crossFeedCurvaturePerMm = 1.0 / 20.0;
  const ScallopRow row = simulateScallopCase(c, fastParams());
  const double exact = 20.0 * (1.0 / std::cos(0.5 * row.spacingMm / 20.0) - 1.0);  // ~0.1 mm
  EXPECT_NEAR(row.predictedMm, exact, 1e-12);
  EXPECT_NEAR(row.simulatedMm, exact, 0.02 * exact);
  EXPECT_NEAR(row.approximateMm, row.spacingMm * row.spacingMm / 8.0 / 20.0, 1e-12);
}

TEST(ScallopPrediction, FlatRollSinglePassFormErrorOnConvexCylinder) {
  // One pass of a roll of width B along the axis of a cylinder of radius rho: inside the
  // footprint the deviation is rho / cos(phi) - rho (tangent line), at the edges ~ kappa B^2/8.
  constexpr double kRho = 20.0, kB = 6.0, kStock = 0.3;
  ddf::CylinderParams params;
  params.radiusMm = kRho;
  params.segments = 180;
  params.rings = 2;
  params.lengthMm = 2.0;
  params.m = 9;
  params.crustFraction = 0.06;
  ddf::DisplacementField part = ddf::cylinderPart(params).ddf;
  const std::vector<float> desired = part.allHeights();
  for (float& h : part.allHeights()) h += static_cast<float>(kStock / (0.06 * kRho));
  Tool roll;
  roll.radiusMm = 10.0;
  roll.widthMm = kB;
  roll.segments = 512;
  ToolPath path;
  path.passStarts = {0};
  for (int i = 0; i <= 16; ++i) {
    const Vec3 contact(kRho, 0.0, 0.125 * i);
    path.poses.push_back(
        {rollPoseAtContact(contact, Vec3::UnitX(), Vec3::UnitZ(), 10.0, 0.0), contact});
  }
  simulatePath(part, roll, path);
  const ScalarField map = deviationMap(part, desired);
  double worst = 0.0, edge = 0.0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0, l = 0; k <= 8; ++k)
      for (int i = 0; i + k <= 8; ++i, ++l) {
        const Vec3 g = part.basePoint(f, part.rasterBary(i, k));
        const double phi = std::atan2(g.y(), g.x());
        if (std::abs(phi) > 1.0 || kRho * std::tan(std::abs(phi)) > 0.5 * kB - 0.05)
          continue;  // outside the footprint
        const double expected = kRho / std::cos(phi) - kRho;
        const double d = map.values[f * part.pointsPerFace() + l];
        worst = std::max(worst, std::abs(d - expected));
        edge = std::max(edge, d);
      }
  EXPECT_LT(worst, 2e-3);
  // The largest deviation inside the footprint approaches the edge error kappa B^2/8 = 0.225.
  EXPECT_NEAR(edge, flatWheelEdgeErrorMm(kB, 1.0 / kRho), 0.015);
  EXPECT_NEAR(flatWheelEdgeErrorMm(kB, 1.0 / kRho), kB * kB / 8.0 / kRho, 0.002);
}

TEST(ScallopPrediction, SimulatedTiltedFlatEndOnPlane) {
  ScallopCase c;
  c.label = "flat end R5 lead 0.2";
  c.model = ScallopToolModel::TiltedFlatEnd;
  c.spacingMm = 4.0;
  c.leadAngleRad = 0.2;
  Tool probe;
  probe.kind = ToolKind::FlatEnd;
  try {
    toolMesh(probe);
  } catch (const InvalidInput&) {
    GTEST_SKIP() << "ToolKind::FlatEnd has no mesh yet (section TL)";
  }
  ScallopSimulationParams params = fastParams();
  params.passLengthMm = 0.5;
  const ScallopRow row = simulateScallopCase(c, params);
  EXPECT_NEAR(row.predictedMm, 5.0 * std::sin(0.2) * (1.0 - std::sqrt(1.0 - 0.16)), 1e-12);
  // Feed steps leave at most 2 % of h; the mesh at most its chord tolerance.
  EXPECT_NEAR(row.simulatedMm, row.predictedMm,
              0.02 * row.predictedMm + params.chordToleranceMm + 1e-4);
}

TEST(ScallopPrediction, TableHasOneRowPerCase) {
  ScallopCase plane;
  plane.radiusMm = 2.0;
  plane.spacingMm = 1.0;
  ScallopCase wheel;
  wheel.label = "roll plane";
  wheel.model = ScallopToolModel::FlatWheel;
  wheel.spacingMm = 4.0;
  const std::vector<ScallopCase> cases{plane, wheel};
  const auto rows = scallopTable(cases, fastParams());
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].tool, "roll plane");
  EXPECT_EQ(rows[1].predictedMm, 0.0);
  EXPECT_LT(rows[1].simulatedMm, 1e-4);  // a flat wheel leaves a plane flat when w <= B
  ScallopCase bad = plane;
  bad.crossFeedCurvaturePerMm = -0.05;
  EXPECT_THROW(simulateScallopCase(bad), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
