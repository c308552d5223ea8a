// SPDX-License-Identifier: MIT
// ddfcam: contactNormals, correctPathPenetrations and prestonStage.
#include <ddfcam/planning/pipeline/simulation_stage.h>

#include <ddfcam/error.h>
#include <ddfcam/planning/placement/tangential_grid.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>

namespace ddfcam::planning {

std::vector<ddf::Vec3> contactNormals(const ddf::DisplacementField& surface,
                                      const ddf::TriangleMesh& toolMesh, const ToolPath& path,
                                      const std::vector<ddf::Vec3>& given) {
  if (toolMesh.vertices.empty()) throw InvalidInput("contact normals: the tool mesh is empty");
  const std::size_t count = path.poses.size();
  if (!given.empty() && given.size() != count)
    throw InvalidInput("contact normals: " + std::to_string(given.size()) + " normals for " +
                       std::to_string(count) + " poses");
  ddf::Vec3 centroid = ddf::Vec3::Zero();
  for (const ddf::Vec3& v : toolMesh.vertices) centroid += v;
  centroid /= static_cast<double>(toolMesh.vertices.size());
  // Indexing a large part costs a pass over its heights: only when a normal is missing.
  std::optional<SurfacePatchIndex> index;
  std::vector<ddf::Vec3> normals;
  normals.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const PathPose& pp = path.poses[i];
    const double length = given.empty() ? 0.0 : given[i].norm();
    ddf::Vec3 n;
    if (std::isfinite(length) && length > 0.0) {
      n = given[i] / length;
    } else {
      if (!index) index.emplace(surface);
      n = index->normalAt(pp.contact);
    }
    normals.push_back(n.dot(pp.pose * centroid - pp.contact) < 0.0 ? ddf::Vec3(-n) : n);
  }
  return normals;
}

CorrectedPath correctPathPenetrations(const ddf::DisplacementField& goal, const Tool& tool,
                                      ToolPath path, PenetrationCorrectionParams params) {
  const ddf::TriangleMesh mesh = toolMesh(tool);
  params.normals = contactNormals(goal, mesh, path, params.normals);
  CorrectedPath out;
  out.report = correctPenetrations(goal, mesh, path, params);
  out.path = std::move(path);
  return out;
}

PrestonStageResult prestonStage(ddf::DisplacementField workpiece, const Tool& tool,
                                const ToolPath& path, PrestonParams params) {
  const ddf::TriangleMesh mesh = toolMesh(tool);
  params.normals = contactNormals(workpiece, mesh, path, params.normals);
  PrestonStageResult out;
  out.report = applyPrestonRemoval(workpiece, mesh, path, params);
  out.workpiece = std::move(workpiece);
  return out;
}

}  // namespace ddfcam::planning
