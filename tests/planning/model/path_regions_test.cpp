// SPDX-License-Identifier: MIT
// Tests of pathRegions(): paths on an analytic plane split into regions by face position.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/model/path_regions.h>

#include <gtest/gtest.h>

#include <functional>

namespace ddfcam::planning {
namespace {

/// The plane z = 0.25 over [0, 40] x [0, 30] in 5 mm cells.
ddf::DisplacementField plane() {
  return ddf::planePatch({.cellsX = 8, .cellsY = 6, .m = 5}).ddf;
}

/// Faces whose vertex centroid satisfies @p inside (the oracle: cells never straddle x = 20
/// or y = 15, the grid lines the predicates cut at).
Region regionWhere(const ddf::DisplacementField& part, const std::string& name,
                   const std::function<bool(const ddf::Vec3&)>& inside) {
  Region region;
  region.name = name;
  for (int f = 0; f < part.faceCount(); ++f) {
    ddf::Vec3 centroid = ddf::Vec3::Zero();
    for (const int v : part.faceVertices(f)) centroid += part.position(v) / 3.0;
    if (inside(centroid)) region.faces.push_back(f);
  }
  return region;
}

/// A path with a pose at every contact (the pose itself does not matter here).
ToolPath pathThrough(const std::vector<ddf::Vec3>& contacts) {
  ToolPath path;
  for (const ddf::Vec3& c : contacts) {
    PathPose pose;
    pose.pose.translation() = c + ddf::Vec3(0, 0, 5);
    pose.contact = c;
    path.poses.push_back(pose);
  }
  if (!contacts.empty()) path.passStarts = {0};
  return path;
}

std::vector<ddf::Vec3> lineAlongX(double x0, double x1, double y, int count) {
  std::vector<ddf::Vec3> points;
  for (int i = 0; i < count; ++i) points.emplace_back(x0 + (x1 - x0) * i / (count - 1), y, 0.25);
  return points;
}

TEST(PathRegions, EachPathGoesToTheRegionHoldingMostOfItsContacts) {
  const ddf::DisplacementField part = plane();
  const std::vector<Region> regions = {
      regionWhere(part, "left", [](const ddf::Vec3& c) { return c.x() < 20.0; }),
      regionWhere(part, "right", [](const ddf::Vec3& c) { return c.x() > 20.0; })};
  ASSERT_FALSE(regions[0].faces.empty());
  ASSERT_EQ(regions[0].faces.size() + regions[1].faces.size(),
            static_cast<std::size_t>(part.faceCount()));
  // 7 contacts at x in [22, 38] and 3 at x in [3, 9]: the right region wins.
  std::vector<ddf::Vec3> mixed = lineAlongX(22.0, 38.0, 11.0, 7);
  for (const ddf::Vec3& p : lineAlongX(3.0, 9.0, 11.0, 3)) mixed.push_back(p);
  const std::vector<ToolPath> paths = {
      pathThrough(lineAlongX(2.0, 18.0, 10.0, 20)),   // left
      pathThrough(lineAlongX(21.0, 39.0, 20.0, 20)),  // right
      pathThrough(mixed),                             // mostly right
      pathThrough(lineAlongX(2.0, 38.0, 10.0, 20)),   // 10 left, 10 right: tie -> left
      pathThrough({{10, 10, 60.0}, {12, 10, 60.0}}),  // far above the part: none
      pathThrough({})};                               // no poses: none
  EXPECT_EQ(pathRegions(part, regions, paths), (std::vector<int>{0, 1, 1, 0, -1, -1}));
}

TEST(PathRegions, ContactsOnFacesOfNoRegionDoNotCount) {
  const ddf::DisplacementField part = plane();
  const std::vector<Region> regions = {
      regionWhere(part, "left", [](const ddf::Vec3& c) { return c.x() < 20.0; }),
      regionWhere(part, "lower right",
                  [](const ddf::Vec3& c) { return c.x() > 20.0 && c.y() < 15.0; })};
  // 12 contacts in the unassigned upper right, 4 in the left region: left wins.
  std::vector<ddf::Vec3> contacts = lineAlongX(22.0, 38.0, 25.0, 12);
  for (const ddf::Vec3& p : lineAlongX(5.0, 15.0, 25.0, 4)) contacts.push_back(p);
  const std::vector<ToolPath> paths = {pathThrough(lineAlongX(22.0, 38.0, 22.0, 10)),
                                       pathThrough(contacts),
                                       pathThrough(lineAlongX(22.0, 38.0, 5.0, 10))};
  EXPECT_EQ(pathRegions(part, regions, paths), (std::vector<int>{-1, 0, 1}));
  EXPECT_EQ(pathRegions(part, {}, paths), (std::vector<int>{-1, -1, -1}));
}

TEST(PathRegions, FacesOutsideThePartAreRefused) {
  const ddf::DisplacementField part = plane();
  Region bad;
  bad.name = "bad";
  bad.faces = {part.faceCount()};
  try {
    pathRegions(part, {bad}, {});
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("'bad'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ddfcam::planning
