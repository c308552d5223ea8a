// SPDX-License-Identifier: MIT
// Tests of the cutter-location program builder: spindle axes per tool kind, normals derived
// from the tool's geometry, lifts between passes, linked moves, and project exports.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/cl_program_builder.h>
#include <ddfcam/planning/placement/path_linking.h>
#include <ddfcam/planning/placement/tool_placement.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace ddfcam::planning {
namespace {

Tool toolOf(ToolKind kind, double radius = 3.0, double edge = 0.0) {
  return Tool{.name = std::string(toolKindName(kind)),
              .kind = kind,
              .radiusMm = radius,
              .widthMm = 10.0,
              .edgeRadiusMm = edge};
}

/// A rotation taking +z to @p axis (and some x, y about it).
Eigen::Matrix3d rotationWithZ(const ddf::Vec3& axis) {
  return Eigen::Quaterniond::FromTwoVectors(ddf::Vec3::UnitZ(), axis).toRotationMatrix();
}

TEST(ClProgramBuilder, SpindleAxisFollowsTheToolFrames) {
  EXPECT_EQ(spindleAxisInToolFrame(ToolKind::CylinderRoll), ddf::Vec3::UnitX());
  EXPECT_EQ(spindleAxisInToolFrame(ToolKind::BeltContactWheel), ddf::Vec3::UnitX());
  EXPECT_EQ(spindleAxisInToolFrame(ToolKind::Sphere), ddf::Vec3::UnitX());
  EXPECT_EQ(spindleAxisInToolFrame(ToolKind::BallEnd), ddf::Vec3::UnitZ());
  EXPECT_EQ(spindleAxisInToolFrame(ToolKind::FlatEnd), ddf::Vec3::UnitZ());
  EXPECT_EQ(spindleAxisInToolFrame(ToolKind::TorusCutter), ddf::Vec3::UnitZ());
  EXPECT_THROW(spindleAxisInToolFrame(static_cast<ToolKind>(17)), InvalidInput);
}

TEST(ClProgramBuilder, CutterAxisIsThePoseZAndItsNormalFromTheBallCentre) {
  // Ball-end cutter R 3 touching the plane z = 0 (normal +z) with its axis tilted 30 deg
  // towards +x: ball centre 3 above the contact, tip = centre - 3 axis.
  const double tilt = M_PI / 6;
  const ddf::Vec3 axis(std::sin(tilt), 0, std::cos(tilt));
  const ddf::Vec3 contact(4, 5, 0);
  PathPose pose;
  pose.pose.linear() = rotationWithZ(axis);
  pose.pose.translation() = contact + ddf::Vec3(0, 0, 3) - 3.0 * axis;
  pose.contact = contact;
  ToolPath path{.name = "ball", .feedMmPerMin = 700, .poses = {pose}, .passStarts = {0}};
  const ClProgram program =
      clProgramFromPath(path, toolOf(ToolKind::BallEnd), ClPointKind::Contact);
  ASSERT_EQ(program.points.size(), 1u);
  const ClPoint& p = program.points[0];
  EXPECT_LT((*p.axis - axis).norm(), 1e-12);  // pose z, not pose x
  EXPECT_LT((*p.normal - ddf::Vec3::UnitZ()).norm(), 1e-12);
  EXPECT_EQ(p.positionMm, contact);
  EXPECT_EQ(p.feedMmPerMin, 700.0);
  EXPECT_EQ(p.move, MoveKind::Cut);
  EXPECT_EQ(program.toolName, "ball_end");
  ASSERT_TRUE(program.cutter.has_value());
  EXPECT_EQ(*program.cutter, (ClCutter{6.0, 3.0, 0.0, 3.0, 0.0, 0.0, 10.0}));
  const ClProgram reference =
      clProgramFromPath(path, toolOf(ToolKind::BallEnd), ClPointKind::ToolReference);
  EXPECT_EQ(reference.points[0].positionMm, ddf::Vec3(pose.pose.translation()));
}

TEST(ClProgramBuilder, DerivedNormalsMatchTheAnalyticContactOfEachToolKind) {
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss;
  for (int trial = 0; trial < 50; ++trial) {
    const ddf::Vec3 n = ddf::Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    // A spindle axis tilted from the normal in a random direction.
    const ddf::Vec3 lean = n.cross(ddf::Vec3(gauss(rng), gauss(rng), gauss(rng))).normalized();
    const double angle = std::abs(gauss(rng)) * 0.4 + 0.05;
    const ddf::Vec3 a = (std::cos(angle) * n + std::sin(angle) * lean).normalized();
    const ddf::Vec3 contact(gauss(rng), gauss(rng), gauss(rng));
    PathPose pose;
    pose.pose.linear() = rotationWithZ(a);
    pose.contact = contact;
    // Torus R 4, corner 1: the corner circle's lowest point along n lies in the direction d
    // (in the plane normal to the axis) opposite to n; contact = that corner centre - e n.
    const double R = 4.0, e = 1.0;
    const ddf::Vec3 d = -(n - n.dot(a) * a).normalized();
    const ddf::Vec3 cornerCentre = contact + e * n;
    pose.pose.translation() = cornerCentre - e * a - (R - e) * d;
    EXPECT_LT((derivedContactNormal(pose, toolOf(ToolKind::TorusCutter, R, e), 0) - n).norm(),
              1e-9);
    // Ball end R 4: tip = contact + R n - R a.
    pose.pose.translation() = contact + R * n - R * a;
    EXPECT_LT((derivedContactNormal(pose, toolOf(ToolKind::BallEnd, R), 0) - n).norm(), 1e-9);
    // Sphere and wheels: reference R above the contact.
    pose.pose.translation() = contact + R * n;
    EXPECT_LT((derivedContactNormal(pose, toolOf(ToolKind::Sphere, R), 0) - n).norm(), 1e-9);
    EXPECT_LT((derivedContactNormal(pose, toolOf(ToolKind::CylinderRoll, R), 0) - n).norm(), 1e-9);
    // Flat end standing on its bottom (axis = normal): the tip face touches.
    pose.pose.linear() = rotationWithZ(n);
    pose.pose.translation() = contact + 1.5 * lean;  // the contact under the bottom face
    EXPECT_LT((derivedContactNormal(pose, toolOf(ToolKind::FlatEnd, R), 0) - n).norm(), 1e-9);
  }
  PathPose degenerate;  // wheel centre on the contact
  EXPECT_THROW(derivedContactNormal(degenerate, toolOf(ToolKind::CylinderRoll), 4), InvalidInput);
}

/// Two passes along x on the plane z = 0 (3 and 2 poses), a roll R 5 above each contact.
ToolPath twoRollPasses() {
  ToolPath path;
  path.name = "two";
  path.feedMmPerMin = 1200;
  const std::vector<ddf::Vec3> contacts = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}};
  for (const ddf::Vec3& c : contacts) {
    PathPose pose;
    pose.pose = rollPoseAtContact(c, ddf::Vec3::UnitZ(), ddf::Vec3::UnitX(), 5.0, 0.0);
    pose.contact = c;
    path.poses.push_back(pose);
  }
  path.passStarts = {0, 3};
  return path;
}

TEST(ClProgramBuilder, PassesAreJoinedByRetractRapidAndApproach) {
  const ToolPath path = twoRollPasses();
  const ClProgram program = clProgramFromPath(path, toolOf(ToolKind::CylinderRoll, 5.0),
                                              ClPointKind::ToolReference, {}, {.clearanceMm = 4});
  struct Expected {
    int path, point;
    ddf::Vec3 position;
    MoveKind move;
    double feed;
  };
  // Reference points: 5 above the contacts; the lift 4 above the pass ends.
  const std::vector<Expected> expected = {
      {0, 0, {0, 0, 5}, MoveKind::Cut, 1200}, {0, 1, {1, 0, 5}, MoveKind::Cut, 1200},
      {0, 2, {2, 0, 5}, MoveKind::Cut, 1200}, {1, 0, {2, 0, 9}, MoveKind::Link, 1200},
      {1, 1, {2, 3, 9}, MoveKind::Rapid, 0},  {1, 2, {2, 3, 5}, MoveKind::Link, 1200},
      {1, 3, {2, 3, 5}, MoveKind::Cut, 1200}, {1, 4, {0, 3, 5}, MoveKind::Cut, 1200}};
  ASSERT_EQ(program.points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const ClPoint& p = program.points[i];
    EXPECT_EQ(p.path, expected[i].path) << i;
    EXPECT_EQ(p.point, expected[i].point) << i;
    EXPECT_LT((p.positionMm - expected[i].position).norm(), 1e-12) << i;
    EXPECT_EQ(p.move, expected[i].move) << i;
    EXPECT_EQ(p.feedMmPerMin, expected[i].feed) << i;
    EXPECT_LT((*p.normal - ddf::Vec3::UnitZ()).norm(), 1e-12) << i;
    EXPECT_NEAR(std::abs(p.axis->y()), 1.0, 1e-12) << i;  // roll axis across the feed
  }
  EXPECT_EQ(program.pathCount(), 2);
  const ClProgram direct = clProgramFromPath(path, toolOf(ToolKind::CylinderRoll, 5.0),
                                             ClPointKind::Contact, {}, {.linkPasses = false});
  ASSERT_EQ(direct.points.size(), 5u);
  EXPECT_EQ(direct.points[3].path, 1);
  EXPECT_EQ(direct.points[3].point, 0);
  EXPECT_EQ(direct.points[3].positionMm, ddf::Vec3(2, 3, 0));
  EXPECT_THROW(clProgramFromPath(path, toolOf(ToolKind::CylinderRoll), ClPointKind::Contact,
                                 {ddf::Vec3::UnitZ()}),
               InvalidInput);
  EXPECT_THROW(clProgramFromPath(path, toolOf(ToolKind::CylinderRoll), ClPointKind::Contact, {},
                                 {.clearanceMm = -1}),
               InvalidInput);
}

TEST(ClProgramBuilder, AppendedProgramsContinueThePathNumbering) {
  const ToolPath path = twoRollPasses();
  const Tool roll = toolOf(ToolKind::CylinderRoll, 5.0);
  ClProgram program = clProgramFromPath(path, roll, ClPointKind::Contact);
  const std::size_t first = program.points.size();
  appendClProgram(program, clProgramFromPath(path, roll, ClPointKind::Contact), {.clearanceMm = 2});
  ASSERT_EQ(program.points.size(), 2 * first + 3);
  EXPECT_EQ(program.pathCount(), 4);
  EXPECT_EQ(program.points[first].move, MoveKind::Link);
  EXPECT_EQ(program.points[first].path, 2);
  EXPECT_EQ(program.points[first].positionMm, ddf::Vec3(0, 3, 2));  // above the last contact
  EXPECT_EQ(program.points[first + 1].positionMm, ddf::Vec3(0, 0, 2));
  EXPECT_EQ(program.points[first + 3].point, 3);
  EXPECT_EQ(program.points.back().path, 3);
}

TEST(ClProgramBuilder, LinkedMovesCarryTypesFeedsAndTheLastCutsOrientation) {
  // Three parallel lines along x on the plane z = 0, 2 mm apart; every link lifts.
  std::vector<std::vector<ddf::Vec3>> lines;
  ToolPath path;
  path.name = "lines";
  path.feedMmPerMin = 800;
  for (int l = 0; l < 3; ++l) {
    lines.emplace_back();
    path.passStarts.push_back(static_cast<int>(path.poses.size()));
    for (int i = 0; i <= 4; ++i) {
      const ddf::Vec3 contact(2.5 * i, 2.0 * l, 0.0);
      lines.back().push_back(contact);
      PathPose pose;
      pose.pose = rollPoseAtContact(contact, ddf::Vec3::UnitZ(), ddf::Vec3::UnitX(), 5.0, 0.0);
      pose.contact = contact;
      path.poses.push_back(pose);
    }
  }
  const LinkedPaths linked = linkPaths(lines, LinkingParams{.clearanceMm = 2.0});
  EXPECT_GT(linked.liftedLinkCount, 0);
  const Tool roll = toolOf(ToolKind::CylinderRoll, 5.0);
  for (const ClPointKind kind : {ClPointKind::Contact, ClPointKind::ToolReference}) {
    const ClProgram program = clProgramFromLinked(linked, path, roll, kind);
    std::size_t row = 0;
    for (std::size_t m = 0; m < linked.moves.size(); ++m) {
      const PathMove& move = linked.moves[m];
      for (std::size_t i = 0; i < move.points.size(); ++i, ++row) {
        ASSERT_LT(row, program.points.size());
        const ClPoint& r = program.points[row];
        EXPECT_EQ(r.path, static_cast<int>(m));
        EXPECT_EQ(r.point, static_cast<int>(i));
        EXPECT_EQ(r.move, move.kind);
        EXPECT_EQ(r.feedMmPerMin, move.kind == MoveKind::Rapid ? 0.0 : 800.0);
        // A roll touching z = 0 from above: centre 5 mm up, axis across the feed (along y).
        const ddf::Vec3 expected =
            move.points[i] + ddf::Vec3(0, 0, kind == ClPointKind::Contact ? 0 : 5);
        EXPECT_LT((r.positionMm - expected).norm(), 1e-9) << "move " << m << " point " << i;
        EXPECT_LT((*r.normal - ddf::Vec3::UnitZ()).norm(), 1e-9);
        EXPECT_NEAR(std::abs(r.axis->y()), 1.0, 1e-9);
      }
    }
    EXPECT_EQ(row, program.points.size());
  }
  LinkedPaths broken = linked;
  broken.moves[0].points[1].x() += 0.1;
  EXPECT_THROW(clProgramFromLinked(broken, path, roll, ClPointKind::Contact), InvalidInput);
  broken = linked;
  broken.moves[0].path = 3;
  EXPECT_THROW(clProgramFromLinked(broken, path, roll, ClPointKind::Contact), InvalidInput);
}

/// A pass of ball-end poses (axis +z) on the plane z = 0.25 along x at height y.
ToolPath ballPass(const std::string& name, int tool, double x0, double x1, double y) {
  ToolPath path{.name = name, .tool = tool, .feedMmPerMin = 900};
  for (int i = 0; i <= 6; ++i) {
    PathPose pose;
    pose.contact = ddf::Vec3(x0 + (x1 - x0) * i / 6.0, y, 0.25);
    pose.pose.translation() = pose.contact;  // tip on the contact, axis +z
    path.poses.push_back(pose);
  }
  path.passStarts = {0};
  return path;
}

Project twoRegionProject() {
  Project project;
  project.partName = "plate";
  project.part = ddf::planePatch({.cellsX = 8, .cellsY = 6, .m = 5}).ddf;
  for (const auto& [name, left] : {std::pair{"left", true}, std::pair{"right", false}}) {
    Region region;
    region.name = name;
    for (int f = 0; f < project.part->faceCount(); ++f) {
      double x = 0;
      for (const int v : project.part->faceVertices(f)) x += project.part->position(v).x() / 3;
      if ((x < 20.0) == left) region.faces.push_back(f);
    }
    project.regions.push_back(region);
  }
  project.tools = {toolOf(ToolKind::BallEnd, 2.0), toolOf(ToolKind::FlatEnd, 4.0)};
  project.tools[1].name = "flat 8";
  project.paths = {ballPass("a", 0, 2, 18, 10), ballPass("b", 0, 22, 38, 10),
                   ballPass("c", 1, 22, 38, 20), ballPass("off", 0, 2, 18, 0)};
  project.paths[3].poses.clear();  // no poses: left out
  project.paths[3].passStarts.clear();
  return project;
}

TEST(ClProgramBuilder, ExportPerRegionSplitsByRegionAndTool) {
  const Project project = twoRegionProject();
  const std::vector<NamedProgram> programs =
      programsForExport(project, {.pointKind = ClPointKind::Contact, .perRegion = true});
  ASSERT_EQ(programs.size(), 3u);
  EXPECT_EQ(programs[0].name, "left");
  EXPECT_EQ(programs[1].name, "right T1");
  EXPECT_EQ(programs[2].name, "right T2");
  EXPECT_EQ(programs[0].program.toolNumber, 1);
  EXPECT_EQ(programs[2].program.toolNumber, 2);
  EXPECT_EQ(programs[2].program.toolName, "flat 8");
  EXPECT_EQ(programs[2].program.partName, "right T2");
  for (const NamedProgram& named : programs) {
    ASSERT_EQ(named.program.points.size(), 7u) << named.name;
    EXPECT_EQ(named.program.pointKind, ClPointKind::Contact);
    for (const ClPoint& p : named.program.points) {
      EXPECT_LT((*p.normal - ddf::Vec3::UnitZ()).norm(), 1e-9);  // the plane's normal
      EXPECT_LT((*p.axis - ddf::Vec3::UnitZ()).norm(), 1e-12);
      EXPECT_EQ(p.feedMmPerMin, 900.0);
      EXPECT_NEAR(p.positionMm.z(), 0.25, 1e-12);
    }
  }
  EXPECT_NEAR(programs[0].program.points[0].positionMm.x(), 2.0, 1e-12);
  EXPECT_NEAR(programs[2].program.points[0].positionMm.y(), 20.0, 1e-12);
}

TEST(ClProgramBuilder, ExportAllInOneAndSelections) {
  Project project = twoRegionProject();
  project.paths[2].tool = 0;  // one tool: a single program
  const std::vector<NamedProgram> all = programsForExport(project, {.link = {.clearanceMm = 3}});
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].name, "plate");
  const ClProgram& program = all[0].program;
  EXPECT_EQ(program.pathCount(), 3);
  ASSERT_EQ(program.points.size(), 3u * 7u + 2u * 3u);  // two lifts of three points
  EXPECT_EQ(program.pointKind, ClPointKind::ToolReference);
  EXPECT_EQ(program.points[7].move, MoveKind::Link);
  EXPECT_NEAR(program.points[7].positionMm.z(), 3.25, 1e-9);  // 3 above the last contact
  EXPECT_EQ(program.points[8].move, MoveKind::Rapid);
  const std::vector<NamedProgram> left = programsForExport(project, {.regions = {0}});
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].program.points.size(), 7u);
  const std::vector<NamedProgram> onlyC = programsForExport(project, {.paths = {2}});
  ASSERT_EQ(onlyC.size(), 1u);
  EXPECT_NEAR(onlyC[0].program.points[0].positionMm.y(), 20.0, 1e-12);
  // Without a part every path is unassigned.
  project.part.reset();
  project.regions.clear();
  const std::vector<NamedProgram> noPart = programsForExport(project, {.perRegion = true});
  ASSERT_EQ(noPart.size(), 1u);
  EXPECT_EQ(noPart[0].name, "unassigned");
  EXPECT_THROW(programsForExport(project, {.paths = {9}}), InvalidInput);
  EXPECT_THROW(programsForExport(project, {.regions = {0}}), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
