// SPDX-License-Identifier: MIT
// Tests of the built-in demo session.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/bspline_patch.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/model/demo_project.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

namespace ddfcam::planning {
namespace {

/// The demo part's design surface, built from its documented parameters rather than taken
/// from the code under test.
const ddf::BSplinePatch& demoDesign() {
  static const ddf::BSplinePatch design = ddf::makeBumpPatch(ddf::DemoPartParams{}.shape);
  return design;
}

/// demoProject() is built once: generating the demo part is the expensive step.
const Project& demo() {
  static const Project project = demoProject();
  return project;
}

ddf::Vec3 triangleNormal(const ddf::TriangleMesh& mesh, std::size_t t) {
  const auto& [a, b, c] = mesh.triangles[t];
  const ddf::Vec3& p = mesh.vertices[a];
  return (mesh.vertices[b] - p).cross(mesh.vertices[c] - p);
}

ddf::Vec3 triangleCentroid(const ddf::TriangleMesh& mesh, std::size_t t) {
  const auto& [a, b, c] = mesh.triangles[t];
  return (mesh.vertices[a] + mesh.vertices[b] + mesh.vertices[c]) / 3.0;
}

TEST(DemoProject, PassesFollowTheDesignSurfaceWithTheRollAcrossTheFeed) {
  const DemoPassesParams params;
  const Tool roll;
  const ToolPath path = demoPasses(demoDesign(), roll, params);
  const int perPass =
      1 + static_cast<int>(std::lround((params.endYMm - params.startYMm) / params.stepMm));
  ASSERT_EQ(perPass, 89);
  ASSERT_EQ(path.poses.size(), 3u * 89u);
  EXPECT_EQ(path.passStarts, (std::vector<int>{0, 89, 178}));
  EXPECT_EQ(path.name, "demo passes");
  EXPECT_EQ(path.tool, 0);
  for (std::size_t p = 0; p < path.passStarts.size(); ++p)
    for (int s = 0; s < perPass; ++s) {
      const PathPose& pose = path.poses[path.passStarts[p] + s];
      EXPECT_DOUBLE_EQ(pose.contact.x(), params.passXMm[p]);
      EXPECT_NEAR(pose.contact.y(), params.startYMm + s * params.stepMm, 1e-12);
      EXPECT_LT(std::abs(demoDesign().value(pose.contact)), 1e-12);
      const ddf::Vec3 n = demoDesign().normal(pose.contact);
      const ddf::Vec3 feed = (ddf::Vec3::UnitY() - n.y() * n).normalized();
      const ddf::Vec3 axis = pose.pose.linear().col(0);
      EXPECT_NEAR(axis.norm(), 1.0, 1e-12);
      EXPECT_NEAR(axis.dot(n), 0.0, 1e-12);
      EXPECT_NEAR(axis.dot(feed), 0.0, 1e-12);
      // Roll centre on the normal through the contact, R - depth above it.
      const ddf::Vec3 centre = pose.contact + (roll.radiusMm - params.depthMm) * n;
      EXPECT_LT((pose.pose.translation() - centre).norm(), 1e-12);
    }
}

TEST(DemoProject, PassParametersShapeThePathAndBadOnesAreRejected) {
  DemoPassesParams params;
  params.passXMm = {5.0, 7.0};
  params.startYMm = 2.0;
  params.endYMm = 3.0;
  params.stepMm = 0.5;
  const ToolPath path = demoPasses(demoDesign(), Tool{}, params);
  EXPECT_EQ(path.poses.size(), 6u);
  EXPECT_EQ(path.passStarts, (std::vector<int>{0, 3}));
  EXPECT_THROW(demoPasses(ddf::PlaneSurface(0.0), Tool{}, {}), InvalidInput);
  EXPECT_THROW(demoPasses(demoDesign(), Tool{}, {.stepMm = 0.0}), InvalidInput);
  EXPECT_THROW(demoPasses(demoDesign(), Tool{}, {.depthMm = -0.1}), InvalidInput);
  EXPECT_THROW(demoPasses(demoDesign(), Tool{}, {.startYMm = 5.0, .endYMm = 4.0}), InvalidInput);
  EXPECT_THROW(demoPasses(demoDesign(), Tool{}, {.passXMm = {}}), InvalidInput);
  EXPECT_THROW(demoPasses(demoDesign(), Tool{.radiusMm = 0.0}, {}), InvalidInput);
}

TEST(DemoProject, HoldsTheDemoPartItsStockRollAndPasses) {
  const Project& p = demo();
  ASSERT_TRUE(p.part.has_value());
  EXPECT_EQ(p.partName, "demo part");
  EXPECT_TRUE(p.sourcePath.empty());
  EXPECT_EQ(p.part->faceCount(), 2 * 32 * 24);
  EXPECT_EQ(p.part->resolution(), 17);
  ASSERT_EQ(p.states.size(), 1u);
  EXPECT_EQ(p.states[0].name, "stock");
  EXPECT_TRUE(p.states[0].heights == p.part->allHeights());
  EXPECT_EQ(p.tools, std::vector<Tool>{Tool{}});
  ASSERT_EQ(p.paths.size(), 1u);
  EXPECT_EQ(p.paths[0].poses.size(), 3u * 89u);
  EXPECT_TRUE(p.fields.empty() && p.regions.empty() && p.surfaces.empty());
  EXPECT_NO_THROW(validateProject(p));
}

TEST(DemoProject, DesignMeshLiesOnTheDesignAndFacesLikeThePart) {
  const Project& p = demo();
  ASSERT_TRUE(p.designMesh.has_value());
  const ddf::TriangleMesh& mesh = *p.designMesh;
  // 40 x 30 mm at 0.25 mm: 160 x 120 cells.
  EXPECT_EQ(mesh.vertices.size(), 161u * 121u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 160u * 120u);
  const auto [lo, hi] = mesh.bounds();
  EXPECT_NEAR(lo.x(), 0.0, 1e-12);
  EXPECT_NEAR(lo.y(), 0.0, 1e-12);
  EXPECT_NEAR(hi.x(), 40.0, 1e-12);
  EXPECT_NEAR(hi.y(), 30.0, 1e-12);
  for (const ddf::Vec3& v : mesh.vertices) ASSERT_LT(std::abs(demoDesign().value(v)), 1e-12);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    ASSERT_GT(triangleNormal(mesh, t).dot(demoDesign().normal(triangleCentroid(mesh, t))), 0.0)
        << "design triangle " << t;
  // The part's own surface faces the same (front, material-outward) side.
  const ddf::TriangleMesh surface = ddf::extractRasterMesh(*p.part).mesh;
  for (std::size_t t = 0; t < surface.triangles.size(); t += 97)
    ASSERT_GT(triangleNormal(surface, t).dot(demoDesign().normal(triangleCentroid(surface, t))),
              0.0)
        << "raster triangle " << t;
}

/// Points farther across the feed from every pass than half the roll width keep their heights.
void expectNothingCutFarFromThePasses(const Project& p, const ddf::DisplacementField& part) {
  const Tool& roll = p.tools[0];
  const DemoPassesParams params;
  // Across the feed the straight roll reaches its half width from the contact line; on the
  // concave parts its edges dig deeper than the contact (no crowning), so along the feed no
  // tight bound holds and only the x extent is checked.
  const double margin = 1.0;
  const double xLo = params.passXMm.front() - 0.5 * roll.widthMm - margin;
  const double xHi = params.passXMm.back() + 0.5 * roll.widthMm + margin;
  std::size_t lowered = 0, far = 0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k < part.resolution(); ++k)
      for (int i = 0; i + k < part.resolution(); ++i) {
        const float before = p.part->height(f, i, k), after = part.height(f, i, k);
        ASSERT_LE(after, before);
        const ddf::Vec3 q = p.part->surfacePoint(f, i, k);
        const bool isFar = q.x() < xLo || q.x() > xHi;
        far += isFar;
        if (isFar) {
          ASSERT_EQ(after, before) << "far point " << q.transpose() << " was cut";
        }
        lowered += after < before;
      }
  EXPECT_GT(far, 10000u);
  EXPECT_GT(lowered, 10000u);
}

/// Points on the contact lines end up depthMm below the design surface.
void expectContactLinesAtTheInfeed(const Project& p, const ddf::DisplacementField& part) {
  const DemoPassesParams params;
  // Passes 6 mm apart with a 10 mm roll: only a line's own pass reaches it. The faceted roll
  // sits up to its chord sag R (1 - cos(pi / s)) above the analytic one, and between two poses
  // 0.25 mm apart it rises by ~0.125^2 / (2 R) = 1.6e-3 mm; value() is measured along z, i.e.
  // the normal depth times W = sqrt(1 + |grad f|^2) >= 1 (<= ~1.2 on the demo part).
  const Tool& roll = p.tools[0];
  const double sag = roll.radiusMm * (1.0 - std::cos(std::numbers::pi / roll.segments));
  std::size_t checked = 0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k < part.resolution(); ++k)
      for (int i = 0; i + k < part.resolution(); ++i) {
        const ddf::Vec3 q = part.surfacePoint(f, i, k);
        if (q.y() < params.startYMm + 2.0 || q.y() > params.endYMm - 2.0) continue;
        for (double x : params.passXMm)
          if (std::abs(q.x() - x) < 0.1) {
            const double below = -demoDesign().value(q);
            EXPECT_GT(below, params.depthMm - sag - 0.002) << q.transpose();
            EXPECT_LT(below, 1.25 * params.depthMm) << q.transpose();
            ++checked;
          }
      }
  EXPECT_GT(checked, 500u);
}

TEST(DemoProject, SimulatedPassesGrindTheContactLinesAndNothingFarFromThem) {
  const Project& p = demo();
  ddf::DisplacementField part = *p.part;
  const PathSimulationReport report = simulatePath(part, p.tools[0], p.paths[0]);
  EXPECT_EQ(report.poses, 3 * 89);
  expectNothingCutFarFromThePasses(p, part);
  expectContactLinesAtTheInfeed(p, part);
}

}  // namespace
}  // namespace ddfcam::planning
