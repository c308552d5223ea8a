// SPDX-License-Identifier: MIT
// Tests of the stored tool description and its cutting mesh.
#include <ddfcam/error.h>
#include <ddfcam/planning/tools/tool.h>

#include <gtest/gtest.h>

#include <string>

namespace ddfcam::planning {
namespace {

void expectBounds(const ddf::TriangleMesh& mesh, const Eigen::Vector3d& half) {
  const auto [lo, hi] = mesh.bounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(lo[a], -half[a], 1e-12) << "axis " << a;
    EXPECT_NEAR(hi[a], half[a], 1e-12) << "axis " << a;
  }
}

TEST(Tool, RollMeshHasFourTrianglesPerSegmentAndTheRollsExtent) {
  Tool roll;
  roll.radiusMm = 3.5;
  roll.widthMm = 8.0;
  roll.segments = 40;  // a multiple of 4: vertices at 0, 90, 180, 270 degrees reach +-R
  const ddf::TriangleMesh mesh = toolMesh(roll);
  EXPECT_EQ(mesh.triangles.size(), 4u * 40u);
  expectBounds(mesh, {4.0, 3.5, 3.5});
  EXPECT_GT(mesh.signedVolume(), 0.0);
}

TEST(Tool, BallMeshHasTheBallsExtent) {
  Tool ball{.name = "ball R2", .kind = ToolKind::Sphere, .radiusMm = 2.0, .segments = 40};
  const ddf::TriangleMesh mesh = toolMesh(ball);
  // rings = 20: a south and a north fan of 40 and 18 bands of 80 triangles.
  EXPECT_EQ(mesh.triangles.size(), 2u * 40u + 18u * 80u);
  expectBounds(mesh, {2.0, 2.0, 2.0});
  EXPECT_GT(mesh.signedVolume(), 0.0);
}

void expectRejectedNamingTool(const Tool& tool) {
  try {
    toolMesh(tool);
    FAIL() << "tool accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("'" + tool.name + "'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(validateTool(tool), InvalidInput);
}

TEST(Tool, InvalidToolsAreRejectedWithTheirName) {
  expectRejectedNamingTool(Tool{.name = "zero radius", .radiusMm = 0.0});
  expectRejectedNamingTool(Tool{.name = "flat", .widthMm = -1.0});
  expectRejectedNamingTool(Tool{.name = "coarse roll", .segments = 2});
  expectRejectedNamingTool(Tool{.name = "coarse ball", .kind = ToolKind::Sphere, .segments = 3});
  expectRejectedNamingTool(Tool{.name = "huge", .segments = 100000});
  expectRejectedNamingTool(Tool{.name = "alien", .kind = static_cast<ToolKind>(7)});
  // A ball ignores the width.
  EXPECT_NO_THROW(toolMesh(Tool{.name = "ball", .kind = ToolKind::Sphere, .widthMm = 0.0}));
}

}  // namespace
}  // namespace ddfcam::planning
