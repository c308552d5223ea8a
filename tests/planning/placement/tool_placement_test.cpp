// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <random>

namespace ddfcam::planning {
namespace {

TEST(ToolPlacement, RollTouchesTheTangentPlaneAtTheContactPointWithAxisAcrossTheFeed) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const CylinderToolParams roll{5.0, 10.0, 200};
  const ddf::TriangleMesh tool = makeCylinderTool(roll);
  for (int trial = 0; trial < 50; ++trial) {
    const ddf::Vec3 contact(10 * u(rng), 10 * u(rng), 10 * u(rng));
    const ddf::Vec3 normal = ddf::Vec3(u(rng), u(rng), u(rng)).normalized();
    const ddf::Vec3 feed(u(rng), u(rng), u(rng));
    const double depth = 0.3 * std::abs(u(rng));
    const auto pose = rollPoseAtContact(contact, normal, feed, roll.radiusMm, depth);
    // Axis (tool x) perpendicular to the normal and to the feed's tangential part.
    const ddf::Vec3 axis = pose.linear().col(0);
    EXPECT_NEAR(axis.dot(normal), 0.0, 1e-12);
    EXPECT_NEAR(axis.dot(feed - feed.dot(normal) * normal), 0.0, 1e-12);
    EXPECT_NEAR(pose.linear().determinant(), 1.0, 1e-12);
    // The lowest tool vertex along the normal sits depth below the contact point (to the
    // chord error of the 200-segment mantle), and it lies on the line through the contact.
    double lowest = 1e300;
    for (const auto& v : tool.vertices) lowest = std::min(lowest, normal.dot(pose * v - contact));
    EXPECT_NEAR(lowest, -depth, roll.radiusMm * (1 - std::cos(M_PI / 200)) + 1e-9);
  }
}

TEST(ToolPlacement, RejectsDegenerateDirections) {
  EXPECT_THROW(rollPoseAtContact({0, 0, 0}, {0, 0, 0}, {1, 0, 0}, 5, 0), InvalidInput);
  EXPECT_THROW(rollPoseAtContact({0, 0, 0}, {0, 0, 1}, {0, 0, 2}, 5, 0), InvalidInput);
  EXPECT_THROW(rollPoseAtContact({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 0, 0), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
