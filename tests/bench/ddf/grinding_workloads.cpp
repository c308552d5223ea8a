// SPDX-License-Identifier: MIT
#include "ddf/grinding_workloads.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/tools/tool_shapes.h>

namespace ddfcam::bench {
namespace {

// Roll of radius 5 mm, width 10 mm, 50 segments -> 200 triangles; axis along tool +x.
ddf::TriangleMesh roll() {
  return planning::makeCylinderTool({5.0, 10.0, 50});
}

// Roll pose touching the design surface at (x, y), depth mm below it, feed along @p feed.
Eigen::Isometry3d rollPose(const ddf::HeightFieldSurface& s, double x, double y,
                           const ddf::Vec3& feed, double radius, double depth) {
  const ddf::Vec3 p = s.pointAbove(x, y);
  return planning::rollPoseAtContact(p, s.normal(p), feed, radius, depth);
}

std::vector<Eigen::Isometry3d> linePoses(const ddf::HeightFieldSurface& s, Eigen::Vector2d from,
                                         Eigen::Vector2d to, int count, double depth) {
  std::vector<Eigen::Isometry3d> poses;
  const Eigen::Vector2d d = to - from;
  const ddf::Vec3 feed(d.x(), d.y(), 0.0);
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2d at = from + d * (static_cast<double>(i) / (count - 1));
    poses.push_back(rollPose(s, at.x(), at.y(), feed, 5.0, depth));
  }
  return poses;
}

}  // namespace

GrindingWorkload fig8_16Workload() {
  ddf::FreeformPatchParams params;
  params.shape.size = {50.0, 25.0};
  params.shape.spansX = 5;
  params.shape.spansY = 3;
  params.shape.amplitudeMm = 2.0;
  params.cellsX = 10;
  params.cellsY = 5;  // 100 support triangles
  params.m = 50;
  auto generated = ddf::freeformPatch(params);
  auto design = std::dynamic_pointer_cast<const ddf::HeightFieldSurface>(generated.design);
  GrindingWorkload w{std::move(generated.ddf), design, roll(), {}, {}};
  w.poses = linePoses(*design, {4.0, 12.5}, {46.0, 12.5}, 217, 0.3);
  w.initialHeights = w.ddf.allHeights();
  return w;
}

GrindingWorkload fig8_14Workload() {
  // One flat support triangle with parallel vectors of 5 mm carrying a B-spline bump surface.
  const std::vector<ddf::Vec3> corners = {{0, 0, 0}, {100, 0, 0}, {0, 100, 0}};
  auto support = ddf::makeSupportMesh(corners, {{0, 1, 2}});
  ddf::BumpPatchParams shape;
  shape.amplitudeMm = 2.5;
  auto design = std::make_shared<const ddf::BSplinePatch>(ddf::makeBumpPatch(shape));
  auto generated = ddf::fromAnalytic(support, std::vector<ddf::Vec3>(3, {0, 0, 5}), 400, design);
  GrindingWorkload w{std::move(generated.ddf), design, roll(), {}, {}};
  w.poses = linePoses(*design, {10.0, 20.0}, {60.0, 30.0}, 216, 0.3);
  w.initialHeights = w.ddf.allHeights();
  return w;
}

}  // namespace ddfcam::bench
