// SPDX-License-Identifier: MIT
// ddfcam: tests of placing cutter-location programs on a part (round trip with planned paths).
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/model/demo_project.h>
#include <ddfcam/planning/placement/imported_path.h>
#include <ddfcam/planning/placement/tool_orientation.h>
#include <ddfcam/planning/simulation/path_simulation.h>
#include <ddfcam/planning/simulation/workpiece.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

/// The program of @p path written in the test: one Cut point per pose, path index = pass.
ClProgram programFromPoses(const ToolPath& path, const Vec3& spindle, ClPointKind kind,
                           const std::vector<Vec3>& normals = {}) {
  ClProgram program;
  program.pointKind = kind;
  std::vector<int> starts = path.passStarts;
  starts.push_back(static_cast<int>(path.poses.size()));
  for (std::size_t s = 0; s + 1 < starts.size(); ++s)
    for (int i = starts[s]; i < starts[s + 1]; ++i) {
      const PathPose& p = path.poses[static_cast<std::size_t>(i)];
      ClPoint c;
      c.path = static_cast<int>(s);
      c.point = i - starts[s];
      c.positionMm = kind == ClPointKind::Contact ? p.contact : Vec3(p.pose.translation());
      c.axis = p.pose.linear() * spindle;
      if (!normals.empty()) c.normal = normals[static_cast<std::size_t>(i)];
      c.feedMmPerMin = 1500.0;
      program.points.push_back(c);
    }
  return program;
}

struct DemoCase {
  ddf::GeneratedSurface part = ddf::demoPart({.m = 9, .allowanceMm = 0.0});
  Tool roll{.segments = 96};
  ToolPath planned;
  explicit DemoCase(double depthMm = 0.02) {
    planned = demoPasses(*part.design, roll,
                         {.depthMm = depthMm, .stepMm = 1.0, .passXMm = {14.0, 24.0}});
  }
};

void expectSamePoses(const ToolPath& a, const ToolPath& b, const Vec3& spindle, double tol) {
  ASSERT_EQ(a.poses.size(), b.poses.size());
  for (std::size_t i = 0; i < a.poses.size(); ++i) {
    EXPECT_LE((a.poses[i].pose.translation() - b.poses[i].pose.translation()).norm(), tol) << i;
    EXPECT_LE((a.poses[i].pose.linear() * spindle - b.poses[i].pose.linear() * spindle).norm(), tol)
        << i;
    const Eigen::Matrix3d r = b.poses[i].pose.linear();
    EXPECT_TRUE((r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-12)) << i;
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12) << i;
  }
}

TEST(ImportedPath, PlannedRollPathComesBackAndSimulatesAlike) {
  const DemoCase demo;
  const ClProgram program =
      programFromPoses(demo.planned, Vec3::UnitX(), ClPointKind::ToolReference);
  const ImportedPath imported = placeProgram(program, demo.roll, demo.part.ddf);
  expectSamePoses(demo.planned, imported.path, Vec3::UnitX(), 1e-9);
  EXPECT_EQ(imported.path.passStarts, demo.planned.passStarts);
  EXPECT_DOUBLE_EQ(imported.path.feedMmPerMin, 1500.0);
  EXPECT_EQ(imported.pointsOffPart, 0);
  // Contacts on the raster mesh vs the exact ones on the design: within the raster's chord
  // error; the roll sinks 0.02 mm into the design.
  for (std::size_t i = 0; i < imported.path.poses.size(); ++i) {
    EXPECT_LE((imported.path.poses[i].contact - demo.planned.poses[i].contact).norm(), 2e-3) << i;
    EXPECT_NEAR(imported.contactDistancesMm[i], -0.02, 1e-3) << i;
    const Vec3 n = imported.normals[i];
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_GT(n.dot((demo.planned.poses[i].pose.translation() - demo.planned.poses[i].contact)
                        .normalized()),
              0.999)
        << i;
  }
  // Same tool surface at the same places: the ground surfaces agree up to the tool mesh's
  // sagitta R (1 - cos(pi / segments)) (the turn about the roll axis differs, so the facets do).
  const ddf::DisplacementField stock = workpieceWithAllowance(demo.part.ddf, 0.1);
  ddf::DisplacementField a = stock, b = stock;
  simulatePath(a, demo.roll, demo.planned);
  simulatePath(b, demo.roll, imported.path);
  const ScalarField da = deviationMap(a, demo.part.ddf);
  const ScalarField db = deviationMap(b, demo.part.ddf);
  const double sagitta = demo.roll.radiusMm * (1 - std::cos(std::numbers::pi / 96));
  double maxDiff = 0.0, minDeviation = 1.0;
  for (std::size_t i = 0; i < da.values.size(); ++i) {
    maxDiff = std::max(maxDiff, double(std::abs(da.values[i] - db.values[i])));
    minDeviation = std::min(minDeviation, double(da.values[i]));
  }
  EXPECT_LT(minDeviation, -0.015);     // the roll really cut, 0.02 mm into the design
  EXPECT_LE(maxDiff, sagitta + 1e-5);  // + float rounding of the heights
  const ToleranceBand band{-0.01, 0.01};
  const auto sa = errorStatistics(da, demo.part.ddf, band);
  const auto sb = errorStatistics(db, demo.part.ddf, band);
  EXPECT_NEAR(sa.minMm, sb.minMm, sagitta);
  EXPECT_NEAR(sa.maxMm, sb.maxMm, sagitta);
  EXPECT_NEAR(sa.meanMm, sb.meanMm, 0.1 * sagitta);
  EXPECT_NEAR(sa.overcutPercent, sb.overcutPercent, 1.0);
  EXPECT_NEAR(sa.inTolerancePercent, sb.inTolerancePercent, 1.0);
}

TEST(ImportedPath, ContactProgramGivesTheRollCentres) {
  const DemoCase demo(0.0);
  std::vector<Vec3> normals;
  for (const auto& p : demo.planned.poses) {
    Vec3 n = demo.part.design->gradient(p.contact).normalized();
    normals.push_back(n.z() < 0 ? Vec3(-n) : n);
  }
  ClProgram program = programFromPoses(demo.planned, Vec3::UnitX(), ClPointKind::Contact, normals);
  const ImportedPath imported = placeProgram(program, demo.roll, demo.part.ddf);
  expectSamePoses(demo.planned, imported.path, Vec3::UnitX(), 1e-9);
  // Without normals in the file the part's normals place the roll to the raster's accuracy.
  for (ClPoint& p : program.points) p.normal.reset();
  const ImportedPath fromPart = placeProgram(program, demo.roll, demo.part.ddf);
  expectSamePoses(demo.planned, fromPart.path, Vec3::UnitX(), 0.02);
  EXPECT_THROW(placeProgram(program, demo.roll, demo.part.ddf, {.normalsFromPart = false}),
               InvalidInput);
}

TEST(ImportedPath, ContactProgramWithLeadAndTiltGivesTheCutterTips) {
  // Oracle: placeToolDetailed() at the exact design normals with the feed along the
  // chord to the next contact, as the importer derives it.
  const ddf::GeneratedSurface part = ddf::demoPart({.m = 5, .allowanceMm = 0.0});
  const auto& design = dynamic_cast<const ddf::HeightFieldSurface&>(*part.design);
  const Tool torus{
      .kind = ToolKind::TorusCutter, .radiusMm = 4.0, .widthMm = 8.0, .edgeRadiusMm = 1.0};
  std::vector<Vec3> contacts, normals;
  for (int i = 0; i <= 20; ++i) {
    const double x = 10.0 + i, y = 12.0 + 0.3 * i;
    const ddf::HeightDerivatives d = design.evaluate(x, y);
    contacts.emplace_back(x, y, d.f);
    normals.push_back(Vec3(-d.fx, -d.fy, 1.0).normalized());
  }
  ToolPath planned;
  planned.passStarts = {0};
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Vec3 feed = i + 1 < contacts.size() ? Vec3(contacts[i + 1] - contacts[i])
                                              : Vec3(contacts[i] - contacts[i - 1]);
    PathPose pose;
    pose.pose = placeTool(torus, contacts[i], normals[i], feed, {.leadDeg = 10.0, .tiltDeg = -5.0});
    pose.contact = contacts[i];
    planned.poses.push_back(pose);
  }
  const ClProgram program = programFromPoses(planned, Vec3::UnitZ(), ClPointKind::Contact, normals);
  const ImportedPath imported = placeProgram(program, torus, part.ddf);
  expectSamePoses(planned, imported.path, Vec3::UnitZ(), 1e-9);
  // The torus touches the design at the contact: its distance to the raster surface is the
  // raster's error.
  for (double d : imported.contactDistancesMm) EXPECT_NEAR(d, 0.0, 2e-3);
}

TEST(ImportedPath, ContactAnglesReplaceTheAnglesOfTheFileAxes) {
  // A contact program whose axes lean by lead 10, tilt -5, placed with lead 3, tilt 2 given:
  // oracle placeToolDetailed() at the same contacts and normals with those angles, the feed
  // along the chord to the next contact.
  const ddf::GeneratedSurface part = ddf::demoPart({.m = 5, .allowanceMm = 0.0});
  const auto& design = dynamic_cast<const ddf::HeightFieldSurface&>(*part.design);
  const Tool torus{
      .kind = ToolKind::TorusCutter, .radiusMm = 4.0, .widthMm = 8.0, .edgeRadiusMm = 1.0};
  const PlacementParams given{.leadDeg = 3.0, .tiltDeg = 2.0};
  ToolPath inFile, expected;
  inFile.passStarts = expected.passStarts = {0};
  std::vector<Vec3> normals;
  for (int i = 0; i <= 20; ++i) {
    const auto contactAt = [&](int k) {
      const double x = 10.0 + k, y = 12.0 + 0.3 * k;
      return Vec3(x, y, design.evaluate(x, y).f);
    };
    const ddf::HeightDerivatives d = design.evaluate(10.0 + i, 12.0 + 0.3 * i);
    const Vec3 n = normals.emplace_back(Vec3(-d.fx, -d.fy, 1.0).normalized());
    const Vec3 c = contactAt(i);
    const Vec3 feed = i < 20 ? Vec3(contactAt(i + 1) - c) : Vec3(c - contactAt(i - 1));
    inFile.poses.push_back({placeTool(torus, c, n, feed, {.leadDeg = 10.0, .tiltDeg = -5.0}), c});
    expected.poses.push_back({placeTool(torus, c, n, feed, given), c});
  }
  const ClProgram program = programFromPoses(inFile, Vec3::UnitZ(), ClPointKind::Contact, normals);
  expectSamePoses(inFile, placeProgram(program, torus, part.ddf).path, Vec3::UnitZ(), 1e-9);
  PlaceProgramParams params;
  params.contactAngles = given;
  expectSamePoses(expected, placeProgram(program, torus, part.ddf, params).path, Vec3::UnitZ(),
                  1e-9);
}

TEST(ImportedPath, UnitsAndTransformPlaceIdentically) {
  const DemoCase demo;
  const ClProgram program =
      programFromPoses(demo.planned, Vec3::UnitX(), ClPointKind::ToolReference);
  const ImportedPath base = placeProgram(program, demo.roll, demo.part.ddf);
  for (const LengthUnit unit : {LengthUnit::Inch, LengthUnit::Metre}) {
    ClProgram scaled = program;
    for (ClPoint& p : scaled.points) {
      p.positionMm /= millimetresPer(unit);
      p.feedMmPerMin /= millimetresPer(unit);
    }
    const ImportedPath placed =
        placeProgram(scaled, demo.roll, demo.part.ddf, {.actualUnit = unit});
    expectSamePoses(base.path, placed.path, Vec3::UnitX(), 1e-9);
    EXPECT_NEAR(placed.path.feedMmPerMin, 1500.0, 1e-9);
  }
  const Eigen::Isometry3d t = Eigen::Translation3d(120.0, -35.0, 7.5) *
                              Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized());
  ClProgram moved = program;
  for (ClPoint& p : moved.points) {
    p.positionMm = t * p.positionMm;
    p.axis = t.linear() * *p.axis;
  }
  const ImportedPath placed =
      placeProgram(moved, demo.roll, demo.part.ddf, {.transform = t.inverse()});
  expectSamePoses(base.path, placed.path, Vec3::UnitX(), 1e-9);
  for (std::size_t i = 0; i < base.path.poses.size(); ++i) {
    EXPECT_LE((base.path.poses[i].contact - placed.path.poses[i].contact).norm(), 1e-7);
    EXPECT_NEAR(base.contactDistancesMm[i], placed.contactDistancesMm[i], 1e-7);
  }
}

/// A plane z = 0.25 (planePatch defaults) and a program of single cutter positions on it.
ClProgram oneCut(const std::vector<Vec3>& positions, std::optional<Vec3> axis = {}) {
  ClProgram program;
  for (const Vec3& p : positions) {
    ClPoint c;
    c.positionMm = p;
    c.axis = axis;
    program.points.push_back(c);
  }
  return program;
}

TEST(ImportedPath, CutterContactsOnAPlaneAreAnalytic) {
  const ddf::GeneratedSurface plane = ddf::planePatch({.m = 5});
  const Tool ball{.kind = ToolKind::BallEnd, .radiusMm = 3.0};
  // 3-axis: default axis +z; the ball's lowest point 0.1 above the plane.
  const ImportedPath a = placeProgram(oneCut({{10, 12, 0.35}, {11, 12, 0.2}}), ball, plane.ddf);
  EXPECT_LE((a.path.poses[0].pose.linear() * Vec3::UnitZ() - Vec3::UnitZ()).norm(), 1e-12);
  EXPECT_NEAR(a.contactDistancesMm[0], 0.1, 1e-6);
  EXPECT_NEAR(a.contactDistancesMm[1], -0.05, 1e-6);
  EXPECT_LE((a.path.poses[0].contact - Vec3(10, 12, 0.25)).norm(), 1e-6);
  EXPECT_LE((a.normals[0] - Vec3::UnitZ()).norm(), 1e-6);
  EXPECT_EQ(a.warnings.size(), 1u);  // no feed
  EXPECT_DOUBLE_EQ(a.path.feedMmPerMin, ToolPath{}.feedMmPerMin);
  // Flat end tilted by 20 deg: its rim reaches down by R sin(20 deg) below the tip (up to the
  // 16 rim samples' spacing).
  const Tool flat{.kind = ToolKind::FlatEnd, .radiusMm = 4.0};
  const double theta = 20.0 * std::numbers::pi / 180.0;
  const ImportedPath b = placeProgram(
      oneCut({{20, 15, 2.0}}, Vec3(std::sin(theta), 0.0, std::cos(theta))), flat, plane.ddf);
  const double drop = 4.0 * std::sin(theta);
  EXPECT_LE(b.contactDistancesMm[0], 1.75 - drop + drop * (1 - std::cos(std::numbers::pi / 16)));
  EXPECT_GE(b.contactDistancesMm[0], 1.75 - drop - 1e-6);
  EXPECT_NEAR(b.path.poses[0].contact.z(), 0.25, 1e-6);
  // Contact program without axes on the plane: the ball's tip sits on the contact.
  ClProgram contact = oneCut({{10, 10, 0.25}, {12, 10, 0.25}});
  contact.pointKind = ClPointKind::Contact;
  const ImportedPath c = placeProgram(contact, ball, plane.ddf);
  EXPECT_LE((c.path.poses[1].pose.translation() - Vec3(12, 10, 0.25)).norm(), 1e-6);
  EXPECT_NEAR(c.contactDistancesMm[1], 0.0, 1e-6);
  // Far above the plane: off the part.
  const ImportedPath d = placeProgram(oneCut({{10, 10, 30.0}}), ball, plane.ddf);
  EXPECT_EQ(d.pointsOffPart, 1);
  // The figures agree: the pose off the part is the farthest one, none is on the part.
  EXPECT_NEAR(d.maxAbsContactDistanceMm, 30.0 - 0.25, 1e-6);
  EXPECT_FALSE(d.maxOnPartContactDistanceMm.has_value());
  EXPECT_EQ(d.gougingPoses, 0);
}

TEST(ImportedPath, PointsWithoutAnAxisKeepTheAxisInForce) {
  const ddf::GeneratedSurface plane = ddf::planePatch({.m = 5});
  const Tool flat{.kind = ToolKind::FlatEnd, .radiusMm = 2.0};
  const double theta = 25.0 * std::numbers::pi / 180.0;
  const Vec3 tilted(0.0, std::sin(theta), std::cos(theta));
  // A tilted rapid (left out of the path), then cuts that give no axis of their own.
  ClProgram program = oneCut({{8, 8, 5.0}, {10, 10, 1.0}, {11, 10, 1.0}, {12, 10, 1.0}});
  program.points[0].axis = tilted;
  program.points[0].move = MoveKind::Rapid;
  const ImportedPath placed = placeProgram(program, flat, plane.ddf);
  ASSERT_EQ(placed.path.poses.size(), 3u);
  for (const PathPose& pose : placed.path.poses)
    EXPECT_LE((pose.pose.linear() * Vec3::UnitZ() - tilted).norm(), 1e-12);
  // Without any axis given, the default axis (+z).
  program.points[0].axis.reset();
  for (const PathPose& pose : placeProgram(program, flat, plane.ddf).path.poses)
    EXPECT_LE((pose.pose.linear() * Vec3::UnitZ() - Vec3::UnitZ()).norm(), 1e-12);
}

TEST(ImportedPath, AProgramWithToolChangesSaysItIsPlacedWithOneTool) {
  const ddf::GeneratedSurface plane = ddf::planePatch({.m = 5});
  const Tool ball{.name = "ball 6", .kind = ToolKind::BallEnd, .radiusMm = 3.0};
  ClProgram program = oneCut({{10, 10, 0.25}, {11, 10, 0.25}, {12, 10, 0.25}});
  program.toolNumber = 1;
  program.toolChanges = {{.firstPoint = 2, .toolNumber = 5, .toolName = "flat", .sourceLine = 9}};
  const ImportedPath placed = placeProgram(program, ball, plane.ddf);
  const auto it =
      std::find_if(placed.warnings.begin(), placed.warnings.end(),
                   [](const ClMessage& m) { return m.text.find("T1, T5") != std::string::npos; });
  ASSERT_NE(it, placed.warnings.end());
  EXPECT_EQ(it->line, 9);
  EXPECT_NE(it->text.find("'ball 6'"), std::string::npos) << it->text;
}

TEST(ImportedPath, PassesBreakWhereCuttingBreaks) {
  const ddf::GeneratedSurface plane = ddf::planePatch({.m = 3});
  const Tool ball{.kind = ToolKind::BallEnd, .radiusMm = 2.0};
  ClProgram program = oneCut({{5, 5, 0.25},
                              {9, 5, 0.25},
                              {9, 5, 5.25},
                              {5, 9, 5.25},
                              {5, 9, 0.25},
                              {9, 9, 0.25},
                              {9, 12, 0.25},
                              {5, 12, 0.25}});
  const MoveKind kinds[] = {MoveKind::Cut,  MoveKind::Cut, MoveKind::Link, MoveKind::Rapid,
                            MoveKind::Link, MoveKind::Cut, MoveKind::Cut,  MoveKind::Cut};
  for (std::size_t i = 0; i < program.points.size(); ++i) {
    program.points[i].move = kinds[i];
    program.points[i].path = i < 6 ? 0 : 1;  // 6 and 7: a new program path without a lift
    program.points[i].feedMmPerMin = kinds[i] == MoveKind::Rapid ? 0.0 : 800.0;
  }
  const ImportedPath links = placeProgram(program, ball, plane.ddf);
  EXPECT_EQ(links.sourcePoints, (std::vector<int>{0, 1, 2, 4, 5, 6, 7}));
  EXPECT_EQ(links.path.passStarts, (std::vector<int>{0, 3, 5}));
  const ImportedPath cuts = placeProgram(program, ball, plane.ddf, {.includeLinks = false});
  EXPECT_EQ(cuts.sourcePoints, (std::vector<int>{0, 1, 5, 6, 7}));
  EXPECT_EQ(cuts.path.passStarts, (std::vector<int>{0, 2, 3}));
  const ImportedPath all = placeProgram(program, ball, plane.ddf, {.includeRapids = true});
  EXPECT_EQ(all.path.poses.size(), 8u);
  EXPECT_EQ(all.path.passStarts, (std::vector<int>{0, 6}));
  EXPECT_DOUBLE_EQ(all.path.feedMmPerMin, 800.0);
}

TEST(ImportedPath, RefusesBadInput) {
  const ddf::GeneratedSurface plane = ddf::planePatch({.m = 3});
  const Tool ball{.kind = ToolKind::BallEnd, .radiusMm = 2.0};
  EXPECT_THROW(placeProgram(ClProgram{}, ball, plane.ddf), InvalidInput);
  EXPECT_THROW(placeProgram(oneCut({{1, 1, 1}}, Vec3::Zero()), ball, plane.ddf), InvalidInput);
  EXPECT_THROW(placeProgram(oneCut({{1, 1, 1}}, Vec3(0, NAN, 1)), ball, plane.ddf), InvalidInput);
  EXPECT_THROW(placeProgram(oneCut({{1, NAN, 1}}), ball, plane.ddf), InvalidInput);
  Eigen::Isometry3d bad = Eigen::Isometry3d::Identity();
  bad.translation().x() = INFINITY;
  EXPECT_THROW(placeProgram(oneCut({{1, 1, 1}}), ball, plane.ddf, {.transform = bad}),
               InvalidInput);
  bad = Eigen::Isometry3d::Identity();
  bad.linear() *= 2.0;
  EXPECT_THROW(placeProgram(oneCut({{1, 1, 1}}), ball, plane.ddf, {.transform = bad}),
               InvalidInput);
  EXPECT_THROW(placeProgram(oneCut({{1, 1, 1}}), ball, plane.ddf, {.defaultAxis = Vec3::Zero()}),
               InvalidInput);
  EXPECT_THROW(placeProgram(oneCut({{1, 1, 1}}), ball, plane.ddf, {.contactSearchMm = 0.0}),
               InvalidInput);
  ClProgram rapids = oneCut({{1, 1, 1}});
  rapids.points[0].move = MoveKind::Rapid;
  EXPECT_THROW(placeProgram(rapids, ball, plane.ddf), InvalidInput);
  try {
    ClProgram contact = oneCut({{1, 1, 0.25}});
    contact.pointKind = ClPointKind::Contact;
    contact.points[0].sourceLine = 42;
    placeProgram(contact, ball, plane.ddf, {.normalsFromPart = false});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("needs normals"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("line 42"), std::string::npos) << e.what();
  }
}

TEST(ImportedPath, ProgressCanCancel) {
  const ddf::GeneratedSurface plane = ddf::planePatch({.m = 3});
  const Tool ball{.kind = ToolKind::BallEnd, .radiusMm = 2.0};
  std::vector<Vec3> points;
  for (int i = 0; i < 600; ++i) points.emplace_back(5.0 + 0.05 * i, 10.0, 0.25);
  PlaceProgramParams params;
  double last = -1.0;
  params.progress = [&](double f) {
    last = f;
    return true;
  };
  placeProgram(oneCut(points), ball, plane.ddf, params);
  EXPECT_DOUBLE_EQ(last, 1.0);
  params.progress = [](double) { return false; };
  EXPECT_THROW(placeProgram(oneCut(points), ball, plane.ddf, params), Cancelled);
}

}  // namespace
}  // namespace ddfcam::planning
