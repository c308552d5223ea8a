// SPDX-License-Identifier: MIT
// Tests of the hashed uniform grid against brute-force neighbour searches.
#include <ddfcam/planning/surface/uniform_grid.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

Vec3 randomPoint(std::mt19937& rng, double extentMm) {
  std::uniform_real_distribution<double> u(-extentMm, extentMm);
  return {u(rng), u(rng), u(rng)};
}

double segmentDistance(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - q).norm();
}

// The ids within radius that the grid offers, each once.
std::set<int> gridNeighbours(const UniformGrid& grid, const std::vector<Vec3>& points,
                             const Vec3& q, double r) {
  std::set<int> found;
  grid.forEachNear(q, r, [&](int id) {
    if ((points[id] - q).norm() <= r) found.insert(id);
  });
  return found;
}

std::set<int> bruteNeighbours(const std::vector<Vec3>& points, const Vec3& q, double r) {
  std::set<int> found;
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    if ((points[i] - q).norm() <= r) found.insert(i);
  return found;
}

TEST(UniformGrid, PointQueriesMatchBruteForce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double cellMm : {0.05, 0.7, 3.0, 50.0}) {
    std::vector<Vec3> points;
    for (int i = 0; i < 600; ++i) points.push_back(randomPoint(rng, 10.0));
    points.push_back(points[5]);  // a repeated point is found twice
    UniformGrid grid(cellMm);
    for (int i = 0; i < static_cast<int>(points.size()); ++i) grid.add(i, points[i]);
    for (int trial = 0; trial < 200; ++trial) {
      // Radii from 0 to well past the part, centres inside and outside it.
      const double r = trial == 0 ? 1e9 : trial == 1 ? 0.0 : 6.0 * std::pow(unit(rng), 2.0);
      const Vec3 q = trial == 1 ? points[5] : randomPoint(rng, 14.0);
      EXPECT_EQ(gridNeighbours(grid, points, q, r), bruteNeighbours(points, q, r))
          << "cell " << cellMm << " r " << r;
    }
  }
}

TEST(UniformGrid, SegmentsGrownOneByOneMatchBruteForce) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cellMm = 0.8;
  UniformGrid grid(cellMm);
  std::vector<Vec3> a, b;
  Vec3 tip = Vec3::Zero();
  for (int step = 0; step < 400; ++step) {
    // A random walk with long and zero-length steps, entered as it grows.
    const Vec3 next = step % 50 == 0   ? randomPoint(rng, 8.0)
                      : step % 17 == 0 ? tip
                                       : tip + randomPoint(rng, 3.0 * unit(rng));
    a.push_back(tip), b.push_back(next);
    grid.add(step, tip.cwiseMin(next), tip.cwiseMax(next));
    tip = next;
    for (int trial = 0; trial < 5; ++trial) {
      const Vec3 q = randomPoint(rng, 10.0);
      const double r = 2.5 * unit(rng);
      std::set<int> expected, found;
      for (int s = 0; s <= step; ++s)
        if (segmentDistance(q, a[s], b[s]) < r) expected.insert(s);
      grid.forEachNear(q, r, [&](int s) {
        if (segmentDistance(q, a[s], b[s]) < r) found.insert(s);
      });
      ASSERT_EQ(found, expected) << "step " << step << " r " << r;
      const bool any =
          grid.findNear(q, r, [&](int s) { return segmentDistance(q, a[s], b[s]) < r; });
      EXPECT_EQ(any, !expected.empty());
    }
  }
}

TEST(UniformGrid, BoxQueriesVisitEveryPointInTheBox) {
  std::mt19937 rng(3);
  std::vector<Vec3> points;
  for (int i = 0; i < 500; ++i) points.push_back(randomPoint(rng, 5.0));
  UniformGrid grid(0.4);
  for (int i = 0; i < static_cast<int>(points.size()); ++i) grid.add(i, points[i]);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 u = randomPoint(rng, 6.0), v = randomPoint(rng, 6.0);
    const Vec3 lo = u.cwiseMin(v), hi = u.cwiseMax(v);
    std::set<int> expected, found;
    for (int i = 0; i < static_cast<int>(points.size()); ++i)
      if ((points[i].array() >= lo.array()).all() && (points[i].array() <= hi.array()).all())
        expected.insert(i);
    grid.forEachInBox(lo, hi, [&](int i) {
      if ((points[i].array() >= lo.array()).all() && (points[i].array() <= hi.array()).all())
        found.insert(i);
    });
    EXPECT_EQ(found, expected);
  }
}

TEST(UniformGrid, EmptyGridsFindNothingAndHugeRadiiFindAll) {
  UniformGrid grid(1.0);
  EXPECT_FALSE(grid.findNear(Vec3::Zero(), 1e12, [](int) { return true; }));
  grid.add(0, Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(grid.cellCount(), 1u);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(grid.findNear(Vec3::Zero(), inf, [](int id) { return id == 0; }));
  EXPECT_TRUE(grid.findNear(Vec3(1e15, -1e15, 0.0), 1e16, [](int id) { return id == 0; }));
  EXPECT_FALSE(grid.findNear(Vec3(-40.0, 0.0, 0.0), 1.0, [](int) { return false; }));
}

}  // namespace
}  // namespace ddfcam::planning
