// SPDX-License-Identifier: MIT
// Tests of path ordering and linking against analytic link lengths on parallel lines.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/evenly_spaced_streamlines.h>
#include <ddfcam/planning/placement/path_linking.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kLength = 40.0;
const std::vector<double> kRows = {0.0, 1.0, 2.5, 4.0, 6.0, 6.5};

// Lines along x at the rows, shuffled and with random orientations (fixed seed).
std::vector<std::vector<Vec3>> parallelLines() {
  std::vector<std::vector<Vec3>> out;
  std::mt19937 rng(5);
  for (const double y : kRows) {
    std::vector<Vec3> line;
    for (int i = 0; i <= 20; ++i) line.emplace_back(kLength * i / 20.0, y, 0.0);
    if (rng() % 2) std::reverse(line.begin(), line.end());
    out.push_back(std::move(line));
  }
  std::shuffle(out.begin(), out.end(), rng);
  return out;
}

double rowOf(const PathMove& move) {
  return move.points.front().y();
}

std::vector<const PathMove*> cuts(const LinkedPaths& linked) {
  std::vector<const PathMove*> out;
  for (const auto& m : linked.moves)
    if (m.kind == MoveKind::Cut) out.push_back(&m);
  return out;
}

TEST(PathLinking, ZigZagAlternatesAndIdleIsTheSumOfGaps) {
  LinkingParams params;
  params.directLinkMaxMm = 5.0;
  const auto paths = parallelLines();
  const LinkedPaths linked = linkPaths(paths, params);
  const auto c = cuts(linked);
  ASSERT_EQ(c.size(), kRows.size());
  EXPECT_EQ(linked.pathCount, 6);
  EXPECT_EQ(linked.linkCount, 5);
  EXPECT_EQ(linked.liftedLinkCount, 0);
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_DOUBLE_EQ(rowOf(*c[i]), kRows[i]);  // ordered across the family
    const double dx = c[i]->points.back().x() - c[i]->points.front().x();
    EXPECT_DOUBLE_EQ(dx, i % 2 == 0 ? kLength : -kLength) << i;  // first along +x, alternating
    EXPECT_EQ(c[i]->path, linked.order[i]);
  }
  EXPECT_NEAR(linked.cuttingLengthMm, kRows.size() * kLength, 1e-9);
  EXPECT_NEAR(linked.idleLengthMm, kRows.back() - kRows.front(), 1e-12);
  for (std::size_t i = 1; i < linked.moves.size(); ++i)  // a continuous tool path
    EXPECT_EQ(linked.moves[i].points.front(), linked.moves[i - 1].points.back());
}

TEST(PathLinking, LiftedLinksRetractTraverseAndApproach) {
  LinkingParams params;
  params.clearanceMm = 2.0;
  const LinkedPaths linked = linkPaths(parallelLines(), params);
  EXPECT_EQ(linked.liftedLinkCount, 5);
  EXPECT_NEAR(linked.idleLengthMm, 5 * 2 * 2.0 + (kRows.back() - kRows.front()), 1e-12);
  int rapids = 0;
  for (const auto& m : linked.moves) {
    if (m.kind != MoveKind::Rapid) continue;
    ++rapids;
    EXPECT_DOUBLE_EQ(m.points.front().z(), 2.0);
    EXPECT_DOUBLE_EQ(m.points.back().z(), 2.0);
  }
  EXPECT_EQ(rapids, 5);
}

TEST(PathLinking, OneDirectionKeepsTheFeedDirection) {
  for (const int sign : {1, -1}) {
    LinkingParams params;
    params.order = LinkingOrder::OneDirection;
    params.feedSign = sign;
    params.directLinkMaxMm = 100.0;
    const LinkedPaths linked = linkPaths(parallelLines(), params);
    const auto c = cuts(linked);
    ASSERT_EQ(c.size(), kRows.size());
    double idle = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) {
      EXPECT_DOUBLE_EQ(rowOf(*c[i]), kRows[i]);
      EXPECT_DOUBLE_EQ(c[i]->points.back().x() - c[i]->points.front().x(), sign * kLength);
      if (i > 0) idle += std::hypot(kLength, kRows[i] - kRows[i - 1]);
    }
    EXPECT_NEAR(linked.idleLengthMm, idle, 1e-9);
    EXPECT_NEAR(linked.cuttingLengthMm, kRows.size() * kLength, 1e-9);
  }
}

TEST(PathLinking, ExplicitFeedDirectionAndNormalsAreUsed) {
  LinkingParams params;
  params.order = LinkingOrder::OneDirection;
  params.feedDirection = Vec3(-1.0, 0.2, 0.0);
  params.clearanceMm = 1.0;
  const auto paths = parallelLines();
  std::vector<std::vector<Vec3>> normals;
  for (const auto& p : paths) normals.emplace_back(p.size(), Vec3(0.0, 0.0, -1.0));
  const LinkedPaths linked = linkPaths(paths, normals, params);
  for (const auto* c : cuts(linked)) EXPECT_LT(c->points.back().x(), c->points.front().x());
  for (const auto& m : linked.moves) {
    if (m.kind == MoveKind::Rapid) {
      EXPECT_DOUBLE_EQ(m.points.front().z(), -1.0);
    }
  }
  normals.back().pop_back();
  EXPECT_THROW(linkPaths(paths, normals, params), InvalidInput);
}

TEST(PathLinking, SkipsDegeneratePathsAndRejectsBadParams) {
  std::vector<std::vector<Vec3>> paths = parallelLines();
  paths.push_back({Vec3(1.0, 2.0, 3.0)});
  paths.emplace_back();
  const LinkedPaths linked = linkPaths(paths);
  EXPECT_EQ(linked.pathCount, 6);
  EXPECT_TRUE(linkPaths({}).moves.empty());
  LinkingParams bad;
  bad.feedSign = 0;
  EXPECT_THROW(linkPaths(paths, bad), InvalidInput);
  bad.feedSign = 1;
  bad.clearanceMm = -1.0;
  EXPECT_THROW(linkPaths(paths, bad), InvalidInput);
}

TEST(PathLinking, EvenlySpacedLinesOnAPlaneLinkIntoOneZigZag) {
  const ddf::GeneratedSurface part = ddf::planePatch({.m = 5});
  const auto& ddf = part.ddf;
  LineField field(ddf.allHeights().size(), Vec3::UnitX());
  EvenSpacingParams p;
  p.separationMm = 3.0;
  const auto lines = evenlySpacedStreamlines(ddf, field, p);
  LinkingParams params;
  params.directLinkMaxMm = 3.5;
  const LinkedPaths linked = linkStreamlines(ddf, lines, params);
  double total = 0.0, minY = 1e9, maxY = -1e9;
  for (const auto& line : lines) {
    total += line.lengthMm;
    minY = std::min(minY, line.points[0].point.y()),
    maxY = std::max(maxY, line.points[0].point.y());
  }
  EXPECT_EQ(linked.pathCount, static_cast<int>(lines.size()));
  EXPECT_NEAR(linked.cuttingLengthMm, total, 1e-9);
  EXPECT_EQ(linked.liftedLinkCount, 0);
  // Straight lines spanning the patch: the zig-zag's links add up to the extent across them.
  EXPECT_NEAR(linked.idleLengthMm, maxY - minY, 1e-6);
}

}  // namespace
}  // namespace ddfcam::planning
