// SPDX-License-Identifier: MIT
// Tests: traced lines made ready for placement (repeated points, reversal, cutting order).
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_locator.h>
#include <ddfcam/planning/lines/line_ordering.h>

#include <gtest/gtest.h>

namespace ddfcam::planning {
namespace {

/// A straight line on the 40 x 30 plane patch (z = 0.25) from (x0, y) to (x1, y), 1 mm steps.
Streamline lineOnPlane(const ddf::SurfaceLocator& locator, double x0, double x1, double y) {
  Streamline line;
  const int steps = static_cast<int>(std::abs(x1 - x0));
  for (int i = 0; i <= steps; ++i) {
    const double x = x0 + (x1 - x0) * i / steps;
    const std::optional<ddf::SurfaceLocation> at = locator.locate({x, y, 0.25});
    EXPECT_TRUE(at.has_value());
    line.points.push_back(*at);
  }
  line.lengthMm = std::abs(x1 - x0);
  return line;
}

ddf::SurfaceLocation at(double x) {
  ddf::SurfaceLocation q;
  q.point = {x, 0.0, 0.0};
  return q;
}

TEST(LineOrdering, DropsRepeatedPointsAndFoldBacks) {
  Streamline line;
  // A A B A C C D: the repeat of A and of C go, the fold-back B A removes B (A B A -> A).
  line.points = {at(0), at(0), at(1), at(0), at(2), at(2), at(3)};
  line.seedIndex = 6;
  dropRepeatedPoints(line);
  ASSERT_EQ(line.points.size(), 3u);
  EXPECT_EQ(line.points[0].point.x(), 0.0);
  EXPECT_EQ(line.points[1].point.x(), 2.0);
  EXPECT_EQ(line.points[2].point.x(), 3.0);
  EXPECT_EQ(line.seedIndex, 2u);
}

TEST(LineOrdering, TheSeedIndexFollowsItsPoint) {
  Streamline line;
  // A A B C C D with the seed on the second C: it stays on C, now at index 2.
  line.points = {at(0), at(0), at(1), at(2), at(2), at(3)};
  line.seedIndex = 4;
  dropRepeatedPoints(line);
  ASSERT_EQ(line.points.size(), 4u);
  EXPECT_EQ(line.points[line.seedIndex].point.x(), 2.0);
  // A B A C with the seed on B: B folds back onto A, which takes the seed's place.
  line.points = {at(0), at(1), at(0), at(2)};
  line.seedIndex = 1;
  dropRepeatedPoints(line);
  ASSERT_EQ(line.points.size(), 2u);
  EXPECT_EQ(line.seedIndex, 0u);
  EXPECT_EQ(line.points[1].point.x(), 2.0);
}

TEST(LineOrdering, ReversingTwiceGivesTheLineBack) {
  Streamline line;
  line.points = {at(0), at(1), at(2), at(5)};
  line.seedIndex = 1;
  line.stop = Streamline::Boundary;
  line.backwardStop = Streamline::Singularity;
  const Streamline back = reversedStreamline(line);
  EXPECT_EQ(back.points.front().point.x(), 5.0);
  EXPECT_EQ(back.seedIndex, 2u);
  EXPECT_EQ(back.stop, Streamline::Singularity);
  EXPECT_EQ(back.backwardStop, Streamline::Boundary);
  const Streamline again = reversedStreamline(back);
  EXPECT_EQ(again.seedIndex, line.seedIndex);
  EXPECT_EQ(again.stop, line.stop);
  for (std::size_t i = 0; i < line.points.size(); ++i)
    EXPECT_EQ(again.points[i].point, line.points[i].point);
}

// Four parallel lines traced in the same direction, given out of order: zig-zag cuts them
// across the family, each starting where the previous one ended (alternating directions).
TEST(LineOrdering, ZigZagOrdersAcrossTheFamilyAndAlternatesDirections) {
  const ddf::GeneratedSurface plane = ddf::planePatch({});
  const ddf::SurfaceLocator locator(plane.ddf);
  std::vector<Streamline> lines;
  for (double y : {20.0, 5.0, 15.0, 10.0}) lines.push_back(lineOnPlane(locator, 5.0, 35.0, y));
  const LinkedPaths linked =
      orderLinesForCutting(plane.ddf, lines, {.order = LinkingOrder::ZigZag});
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(linked.pathCount, 4);
  double lastY = lines[0].points.front().point.y();
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const double y = lines[l].points.front().point.y();
    EXPECT_NEAR(std::abs(y - lastY), 5.0, 1e-9);  // neighbours, one spacing apart
    // Each line starts at the x where the previous one ended.
    EXPECT_NEAR(lines[l].points.front().point.x(), lines[l - 1].points.back().point.x(), 1e-9);
    lastY = y;
  }
}

}  // namespace
}  // namespace ddfcam::planning
