// SPDX-License-Identifier: MIT
// Tests of the workbench document's invariants and exact equality.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/model/demo_project.h>
#include <ddfcam/planning/model/project.h>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>

namespace ddfcam::planning {
namespace {

ddf::DisplacementField smallPlane() {
  return ddf::planePatch({.size = {4.0, 4.0}, .cellsX = 2, .cellsY = 2, .m = 5}).ddf;
}

/// A small project with every kind of item: 8 faces of 15 raster points (120 heights).
Project smallProject() {
  Project p;
  p.partName = "plane";
  p.sourcePath = "parts/plane.stl";
  p.part = smallPlane();
  const std::size_t n = p.part->allHeights().size();
  p.designMesh =
      ddf::TriangleMesh{{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}}, {{0, 1, 2}}};
  p.fields = {ScalarField{"height", "mm", true, std::vector<float>(n, 0.5f), {}}};
  p.regions = {Region{"left", {0, 2, 5}, {0.9f, 0.6f, 0.2f}, {}}};
  RegionPlan& plan = p.regions[0].plan;
  plan.tool = 1;
  plan.flowSource = FlowFieldSource::UserStrokes;
  plan.fixedDirection = ddf::Vec3(0.0, 1.0, 0.25);
  plan.strokes = {{ddf::Vec3(0, 0, 0), ddf::Vec3(1, 0.5, 0)}, {ddf::Vec3(2, 2, 0)}};
  plan.smoothnessWeight = 0.5;
  plan.spacingMode = SpacingMode::ScallopTolerance;
  plan.spacingMm = 0.75;
  plan.feedSign = -1;
  plan.linking = LinkingOrder::OneDirection;
  p.tools = {Tool{}, Tool{.name = "ball", .kind = ToolKind::Sphere}};
  PathPose pose;
  pose.pose.translation() = ddf::Vec3(1, 2, 3);
  pose.contact = ddf::Vec3(1, 2, -2);
  p.paths = {ToolPath{.name = "zig", .tool = 1, .poses = {pose, pose, pose}, .passStarts = {0, 2}}};
  p.states = {SimulationState{"stock", p.part->allHeights()}};
  p.surfaces = {NamedSurface{"mould", smallPlane()}};
  return p;
}

void expectRejected(const Project& p, const std::string& mention) {
  try {
    validateProject(p);
    ADD_FAILURE() << "accepted; expected an error mentioning " << mention;
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
  }
}

TEST(Project, ValidProjectsAreAccepted) {
  EXPECT_NO_THROW(validateProject(smallProject()));
  EXPECT_NO_THROW(validateProject(Project{}));
  EXPECT_NO_THROW(validateProject(demoProject()));
}

TEST(Project, EachBrokenInvariantIsRejectedNamingTheItem) {
  const std::vector<std::pair<std::string, std::function<void(Project&)>>> cases = {
      {"field 'height': 12 values, expected 120",
       [](Project& p) { p.fields[0].values.resize(12); }},
      {"state 'stock'", [](Project& p) { p.states[0].heights.push_back(0.0f); }},
      {"region 'left'", [](Project& p) { p.regions[0].faces.push_back(8); }},
      {"region 'left'",
       [](Project& p) {
         p.regions[0].faces = {0, 3, 3};
       }},
      {"region 'left'",
       [](Project& p) {
         p.regions[0].faces = {-1, 2};
       }},
      {"region 'left'",
       [](Project& p) {
         p.regions[0].faces = {4, 2};
       }},
      {"region 'left' plan: tool index 2", [](Project& p) { p.regions[0].plan.tool = 2; }},
      {"region 'left' plan: tool index -2", [](Project& p) { p.regions[0].plan.tool = -2; }},
      {"region 'left' plan: spacing 0 mm", [](Project& p) { p.regions[0].plan.spacingMm = 0.0; }},
      {"region 'left' plan: spacing nan",
       [](Project& p) { p.regions[0].plan.spacingMm = std::nan(""); }},
      {"region 'left' plan: spacing inf",
       [](Project& p) { p.regions[0].plan.spacingMm = std::numeric_limits<double>::infinity(); }},
      {"region 'left' plan: scallop tolerance -1",
       [](Project& p) { p.regions[0].plan.scallopToleranceMm = -1.0; }},
      {"region 'left' plan: feed sign 0", [](Project& p) { p.regions[0].plan.feedSign = 0; }},
      {"region 'left' plan: feed sign 2", [](Project& p) { p.regions[0].plan.feedSign = 2; }},
      {"region 'left' plan: the fixed flow direction",
       [](Project& p) { p.regions[0].plan.fixedDirection = ddf::Vec3::Zero(); }},
      {"region 'left' plan: the fixed flow direction",
       [](Project& p) { p.regions[0].plan.fixedDirection.y() = std::nan(""); }},
      {"region 'left' plan: stroke 1 point 0",
       [](Project& p) { p.regions[0].plan.strokes[1][0].z() = std::nan(""); }},
      {"region 'left' plan: smoothness weight -0.5",
       [](Project& p) { p.regions[0].plan.smoothnessWeight = -0.5; }},
      {"region 'left' plan: unknown flow field source 7",
       [](Project& p) { p.regions[0].plan.flowSource = static_cast<FlowFieldSource>(7); }},
      {"region 'left' plan: unknown spacing mode -1",
       [](Project& p) { p.regions[0].plan.spacingMode = static_cast<SpacingMode>(-1); }},
      {"region 'left' plan: unknown linking order 2",
       [](Project& p) { p.regions[0].plan.linking = static_cast<LinkingOrder>(2); }},
      {"region 'left' plan: tool index 1 out of range (1 tools",
       [](Project& p) { p.tools.pop_back(), p.paths.clear(); }},
      {"path 'zig'", [](Project& p) { p.paths[0].tool = 2; }},
      {"path 'zig'", [](Project& p) { p.paths[0].tool = -1; }},
      {"path 'zig'",
       [](Project& p) {
         p.paths[0].passStarts = {0, 2, 1};
       }},
      {"path 'zig'",
       [](Project& p) {
         p.paths[0].passStarts = {0, 3};
       }},
      {"path 'zig'",
       [](Project& p) {
         p.paths[0].passStarts = {1, 2};
       }},
      {"path 'zig'", [](Project& p) { p.paths[0].passStarts.clear(); }},
      {"tool 'ball'", [](Project& p) { p.tools[1].radiusMm = -1.0; }},
      {"design mesh", [](Project& p) { p.designMesh->triangles[0][2] = 3; }},
      {"field 'height'", [](Project& p) { p.part.reset(); }},
      {"state 'stock'", [](Project& p) { p.part.reset(), p.fields.clear(); }},
      {"region 'left'", [](Project& p) { p.part.reset(), p.fields.clear(), p.states.clear(); }},
  };
  Project noTool = smallProject();
  noTool.regions[0].plan.tool = -1;
  noTool.regions[0].plan.smoothnessWeight = 0.0;
  EXPECT_NO_THROW(validateProject(noTool));
  for (const auto& [mention, breakIt] : cases) {
    Project p = smallProject();
    breakIt(p);
    expectRejected(p, mention);
  }
}

template <class T>
void flipLowestBit(T& value) {
  using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
  value = std::bit_cast<T>(std::bit_cast<Bits>(value) ^ Bits{1});
}

TEST(Project, EqualityDetectsEveryOneBitChange) {
  const Project base = smallProject();
  EXPECT_TRUE(projectsEqual(base, smallProject()));
  const std::vector<std::pair<std::string, std::function<void(Project&)>>> changes = {
      {"part height", [](Project& p) { flipLowestBit(p.part->allHeights()[37]); }},
      {"part vector",
       [](Project& p) {
         auto v = p.part->vectors();
         flipLowestBit(v[4].y());
         p.part->setVectors(v);
       }},
      {"surface height", [](Project& p) { flipLowestBit(p.surfaces[0].ddf.allHeights()[3]); }},
      {"path pose", [](Project& p) { flipLowestBit(p.paths[0].poses[1].pose.matrix()(1, 2)); }},
      {"path contact", [](Project& p) { flipLowestBit(p.paths[0].poses[2].contact.z()); }},
      {"field value", [](Project& p) { flipLowestBit(p.fields[0].values[119]); }},
      {"state height", [](Project& p) { flipLowestBit(p.states[0].heights[0]); }},
      {"design vertex", [](Project& p) { flipLowestBit(p.designMesh->vertices[1].x()); }},
      {"tool radius", [](Project& p) { flipLowestBit(p.tools[0].radiusMm); }},
      {"region colour", [](Project& p) { flipLowestBit(p.regions[0].color[1]); }},
      {"feed", [](Project& p) { flipLowestBit(p.paths[0].feedMmPerMin); }},
      {"plan tool", [](Project& p) { p.regions[0].plan.tool = 0; }},
      {"plan source",
       [](Project& p) { p.regions[0].plan.flowSource = FlowFieldSource::FixedDirection; }},
      {"plan direction", [](Project& p) { flipLowestBit(p.regions[0].plan.fixedDirection.z()); }},
      {"plan stroke point", [](Project& p) { flipLowestBit(p.regions[0].plan.strokes[0][1].y()); }},
      {"plan stroke count", [](Project& p) { p.regions[0].plan.strokes.pop_back(); }},
      {"plan stroke length",
       [](Project& p) { p.regions[0].plan.strokes[1].push_back(ddf::Vec3(2, 2, 0)); }},
      {"plan smoothing", [](Project& p) { p.regions[0].plan.smoothField = false; }},
      {"plan weight", [](Project& p) { flipLowestBit(p.regions[0].plan.smoothnessWeight); }},
      {"plan mode", [](Project& p) { p.regions[0].plan.spacingMode = SpacingMode::FixedSpacing; }},
      {"plan spacing", [](Project& p) { flipLowestBit(p.regions[0].plan.spacingMm); }},
      {"plan tolerance", [](Project& p) { flipLowestBit(p.regions[0].plan.scallopToleranceMm); }},
      {"plan feed sign", [](Project& p) { p.regions[0].plan.feedSign = 1; }},
      {"plan linking", [](Project& p) { p.regions[0].plan.linking = LinkingOrder::ZigZag; }},
      {"plan signed zero", [](Project& p) { p.regions[0].plan.strokes[0][0].x() = -0.0; }},
      {"signed zero", [](Project& p) { p.fields[0].values[5] = -0.0f; }},
      {"no design mesh", [](Project& p) { p.designMesh.reset(); }},
      {"part name", [](Project& p) { p.partName += " "; }},
      {"source", [](Project& p) { p.sourcePath.clear(); }},
      {"other part",
       [](Project& p) { p.part = ddf::planePatch({.cellsX = 2, .cellsY = 2, .m = 5}).ddf; }},
  };
  for (const auto& [what, change] : changes) {
    Project changed = smallProject();
    change(changed);
    EXPECT_FALSE(projectsEqual(base, changed)) << what;
    EXPECT_FALSE(projectsEqual(changed, base)) << what;
  }
}

TEST(Project, NanEqualsNanAtTheSamePlaceOnly) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Project a = smallProject(), b = smallProject();
  a.fields[0].values[7] = b.fields[0].values[7] = nan;
  a.part->allHeights()[9] = b.part->allHeights()[9] = nan;
  EXPECT_TRUE(projectsEqual(a, b));
  b.fields[0].values[7] = 0.5f;
  b.fields[0].values[8] = nan;
  EXPECT_FALSE(projectsEqual(a, b));
}

}  // namespace
}  // namespace ddfcam::planning
