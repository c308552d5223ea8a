// SPDX-License-Identifier: MIT
// ddfcam: the built-in demo session (demo part, default roll, three passes, design mesh).
#include <ddfcam/error.h>
#include <ddfcam/planning/model/demo_project.h>
#include <ddfcam/planning/placement/tool_placement.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ddfcam::planning {
namespace {

constexpr double kDesignGridStepMm = 0.25;

void checkPassParams(const DemoPassesParams& p) {
  if (!(p.depthMm >= 0.0)) throw InvalidInput("demo passes: depthMm must not be negative");
  if (!(p.stepMm > 0.0)) throw InvalidInput("demo passes: stepMm must be positive");
  if (!(p.endYMm >= p.startYMm))
    throw InvalidInput("demo passes: endYMm must not lie below startYMm");
  if (p.passXMm.empty()) throw InvalidInput("demo passes: passXMm lists no pass");
}

/// x-y bounding rectangle (min, max) of the support vertices, mm.
std::array<Eigen::Vector2d, 2> supportRectangle(const ddf::DisplacementField& ddf) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    lo = lo.cwiseMin(ddf.position(v).head<2>());
    hi = hi.cwiseMax(ddf.position(v).head<2>());
  }
  return {lo, hi};
}

/// Regular grid triangulation of a graph surface over [lo, hi] with cells of at most @p stepMm,
/// vertices on the surface, triangles counter-clockwise seen from +z: the front (+z) side of a
/// HeightFieldSurface, which is also the side the demo part's support and raster mesh face.
ddf::TriangleMesh graphMesh(const ddf::HeightFieldSurface& surface, const Eigen::Vector2d& lo,
                            const Eigen::Vector2d& hi, double stepMm) {
  const Eigen::Vector2d size = hi - lo;
  const int nx = std::max(1, static_cast<int>(std::ceil(size.x() / stepMm - 1e-9)));
  const int ny = std::max(1, static_cast<int>(std::ceil(size.y() / stepMm - 1e-9)));
  ddf::TriangleMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(nx + 1) * (ny + 1));
  for (int b = 0; b <= ny; ++b)
    for (int a = 0; a <= nx; ++a)
      mesh.vertices.push_back(
          surface.pointAbove(lo.x() + a * size.x() / nx, lo.y() + b * size.y() / ny));
  auto at = [nx](int a, int b) { return b * (nx + 1) + a; };
  mesh.triangles.reserve(2 * static_cast<std::size_t>(nx) * ny);
  for (int b = 0; b < ny; ++b)
    for (int a = 0; a < nx; ++a) {
      mesh.triangles.push_back({at(a, b), at(a + 1, b), at(a + 1, b + 1)});
      mesh.triangles.push_back({at(a, b), at(a + 1, b + 1), at(a, b + 1)});
    }
  return mesh;
}

}  // namespace

ToolPath demoPasses(const ddf::AnalyticSurface& design, const Tool& tool,
                    const DemoPassesParams& params) {
  const auto* graph = dynamic_cast<const ddf::HeightFieldSurface*>(&design);
  if (graph == nullptr)
    throw InvalidInput("demo passes need a height-field design surface, got " + design.name());
  validateTool(tool);
  checkPassParams(params);
  const int steps = static_cast<int>(std::round((params.endYMm - params.startYMm) / params.stepMm));
  ToolPath path;
  path.name = "demo passes";
  path.poses.reserve(params.passXMm.size() * static_cast<std::size_t>(steps + 1));
  for (double x : params.passXMm) {
    path.passStarts.push_back(static_cast<int>(path.poses.size()));
    for (int s = 0; s <= steps; ++s) {
      PathPose pose;
      pose.contact = graph->pointAbove(x, params.startYMm + s * params.stepMm);
      pose.pose = rollPoseAtContact(pose.contact, graph->normal(pose.contact), ddf::Vec3::UnitY(),
                                    tool.radiusMm, params.depthMm);
      path.poses.push_back(pose);
    }
  }
  return path;
}

Project demoProject() {
  ddf::GeneratedSurface part = ddf::demoPart();
  const auto* design = dynamic_cast<const ddf::HeightFieldSurface*>(part.design.get());
  if (design == nullptr) throw InvalidInput("demo part: the design surface is not a height field");
  Project project;
  project.partName = "demo part";
  const auto [lo, hi] = supportRectangle(part.ddf);
  project.designMesh = graphMesh(*design, lo, hi, kDesignGridStepMm);
  project.tools = {Tool{}};
  project.paths = {demoPasses(*design, project.tools.front())};
  project.states = {SimulationState{"stock", part.ddf.allHeights()}};
  project.part = std::move(part.ddf);
  return project;
}

}  // namespace ddfcam::planning
