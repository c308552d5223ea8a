// SPDX-License-Identifier: MIT
// Tests of the segmentation by CAD face: regions are the connected pieces of each CAD face.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/cad_face_segmentation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace ddfcam::planning {
namespace {

ddf::Vec3 centroid(const ddf::DisplacementField& ddf, int f) {
  const auto& t = ddf.faceVertices(f);
  return (ddf.position(t[0]) + ddf.position(t[1]) + ddf.position(t[2])) / 3.0;
}

struct LabelledPlane {
  ddf::DisplacementField ddf;
  std::vector<int> cadFace;  // per support face
  std::vector<std::string> names = {"face 1 (plane)", "face 2 (plane)", "face 3 (cylinder)"};
  int lonelyFace = 0;  // the one support face of CAD face 2
};

// A plane split at its middle in x into CAD faces 0 and 1, plus one support face inside face 0
// that forms CAD face 2 on its own (a narrow fillet, say).
LabelledPlane labelledPlane() {
  LabelledPlane out{ddf::planePatch({.cellsX = 20, .cellsY = 15, .m = 5}).ddf, {}};
  double xMin = 1e300, xMax = -1e300;
  for (int v = 0; v < out.ddf.vertexCount(); ++v) {
    xMin = std::min(xMin, out.ddf.position(v).x());
    xMax = std::max(xMax, out.ddf.position(v).x());
  }
  const double middle = 0.5 * (xMin + xMax);
  for (int f = 0; f < out.ddf.faceCount(); ++f)
    out.cadFace.push_back(centroid(out.ddf, f).x() < middle ? 0 : 1);
  // An interior face of CAD face 0: away from the plane's border and from the split.
  const ddf::Vec3 target(xMin + 0.25 * (xMax - xMin), 15.0, 0.0);  // the patch is 30 mm in y
  double best = 1e300;
  for (int f = 0; f < out.ddf.faceCount(); ++f) {
    ddf::Vec3 c = centroid(out.ddf, f);
    c.z() = 0.0;
    if ((c - target).norm() < best && out.cadFace[f] == 0) {
      best = (c - target).norm();
      out.lonelyFace = f;
    }
  }
  out.cadFace[out.lonelyFace] = 2;
  return out;
}

TEST(CadFaceSegmentation, EveryCadFaceIsARegionEvenASingleSupportFace) {
  const LabelledPlane part = labelledPlane();
  const std::vector<Region> regions = segmentByCadFace(part.ddf, part.cadFace, part.names);
  ASSERT_EQ(regions.size(), 3u);
  std::vector<int> covered(part.ddf.faceCount(), 0);
  for (const Region& region : regions) {
    ASSERT_FALSE(region.faces.empty());
    const int label = part.cadFace[region.faces.front()];
    for (const int f : region.faces) {
      EXPECT_EQ(part.cadFace[f], label) << region.name;
      ++covered[f];
    }
    EXPECT_EQ(region.name.rfind(part.names[label], 0), 0u) << region.name;
    if (label == 2) {
      EXPECT_EQ(region.faces, std::vector<int>{part.lonelyFace});
    }
  }
  for (int f = 0; f < part.ddf.faceCount(); ++f) EXPECT_EQ(covered[f], 1) << f;
}

TEST(CadFaceSegmentation, RaisedMinFacesMergesTheSmallFaceIntoItsNeighbour) {
  const LabelledPlane part = labelledPlane();
  SegmentationParams params = cadFaceSegmentationParams();
  params.minFaces = 4;
  const std::vector<Region> regions = segmentByCadFace(part.ddf, part.cadFace, part.names, params);
  ASSERT_EQ(regions.size(), 2u);
  for (const Region& region : regions)
    if (std::count(region.faces.begin(), region.faces.end(), part.lonelyFace) == 1) {
      EXPECT_EQ(region.name.rfind(part.names[0], 0), 0u) << region.name;
    }
}

TEST(CadFaceSegmentation, FacesWithoutCadFaceFormTheirOwnRegion) {
  LabelledPlane part = labelledPlane();
  part.cadFace[part.lonelyFace] = -1;
  const std::vector<Region> regions = segmentByCadFace(part.ddf, part.cadFace, part.names);
  ASSERT_EQ(regions.size(), 3u);
  const auto none = std::find_if(regions.begin(), regions.end(), [](const Region& r) {
    return r.name.rfind("no CAD face", 0) == 0;
  });
  ASSERT_NE(none, regions.end());
  EXPECT_EQ(none->faces, std::vector<int>{part.lonelyFace});
}

TEST(CadFaceSegmentation, RejectsSizeMismatchAndIndicesOutOfRange) {
  LabelledPlane part = labelledPlane();
  std::vector<int> shorter(part.cadFace.begin(), part.cadFace.end() - 1);
  EXPECT_THROW(segmentByCadFace(part.ddf, shorter, part.names), InvalidInput);
  part.cadFace[3] = 3;
  EXPECT_THROW(segmentByCadFace(part.ddf, part.cadFace, part.names), InvalidInput);
  part.cadFace[3] = -2;
  EXPECT_THROW(segmentByCadFace(part.ddf, part.cadFace, part.names), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
