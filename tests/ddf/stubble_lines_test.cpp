// SPDX-License-Identifier: MIT
// Tests of the displacement stubbles on a planar field and by brute-force selection.
#include <ddfcam/ddf/stubble_lines.h>

#include <gtest/gtest.h>

#include <limits>
#include <set>

#include "surface_fixtures.h"

namespace ddfcam::ddf {
namespace {

// Planar support z = 0 with vectors (0, 0, 0.5): a stubble is vertical, from z = 0 to 0.5 h.
DisplacementField planarField() {
  const auto mesh = test::gridMesh(2, 2, 1.0, 1.0);
  DisplacementField field(mesh, test::constantVectors(mesh, {0, 0, 0.5}), 7);
  test::fillHeights(field, [](int, const Vec3& g) { return 0.4 * g.x() - 0.3 * g.y(); });
  return field;
}

TEST(StubbleLines, BaseToSurfaceRunsFromSupportToSurfacePoint) {
  const auto field = planarField();
  const StubbleLines lines = stubbleLines(field, {.stride = 1});
  ASSERT_EQ(lines.from.size(), field.topology().pointCount());
  ASSERT_EQ(lines.to.size(), lines.from.size());
  std::set<PointId> seen(lines.point.begin(), lines.point.end());
  EXPECT_EQ(seen.size(), lines.point.size());  // each distinct point once
  for (std::size_t s = 0; s < lines.from.size(); ++s) {
    EXPECT_EQ(lines.from[s].z(), 0.0);
    EXPECT_EQ(lines.from[s].head<2>(), lines.to[s].head<2>());
    const double h = 0.4 * lines.from[s].x() - 0.3 * lines.from[s].y();
    EXPECT_NEAR(lines.to[s].z(), 0.5 * h, 1e-6) << "segment " << s;
  }
}

TEST(StubbleLines, FullCrustSpansMinusOneToPlusOne) {
  const auto field = planarField();
  const StubbleLines lines = stubbleLines(field, {.stride = 1, .range = StubbleRange::FullCrust});
  for (std::size_t s = 0; s < lines.from.size(); ++s) {
    EXPECT_DOUBLE_EQ(lines.from[s].z(), -0.5);
    EXPECT_DOUBLE_EQ(lines.to[s].z(), 0.5);
  }
}

// Brute-force selection: a point is drawn iff its lowest-face copy has i and k divisible by
// the stride.
TEST(StubbleLines, StrideSelectsOwnerLatticeMultiples) {
  const auto field = test::bumpyOctahedronDdf(11);
  const auto& topo = field.topology();
  for (int stride : {2, 3, 5}) {
    std::set<PointId> expected;
    for (std::size_t p = 0; p < topo.pointCount(); ++p) {
      PointCopy lowest{std::numeric_limits<int>::max(), 0};
      topo.forEachCopy(static_cast<PointId>(p), [&](PointCopy c) {
        if (c.face < lowest.face) lowest = c;
      });
      const RasterCoord rc = topo.coord(lowest);
      if (rc.i % stride == 0 && rc.k % stride == 0) expected.insert(static_cast<PointId>(p));
    }
    const StubbleLines lines = stubbleLines(field, {.stride = stride});
    EXPECT_EQ(std::set<PointId>(lines.point.begin(), lines.point.end()), expected);
    EXPECT_EQ(lines.point.size(), expected.size());
  }
}

TEST(StubbleLines, EmptyFieldGivesNoLines) {
  EXPECT_TRUE(stubbleLines(DisplacementField{}).from.empty());
}

}  // namespace
}  // namespace ddfcam::ddf
