// SPDX-License-Identifier: MIT
// ddfcam-bench: the turbine blade grinding workload (ray-cast contacts on the shared mesh).
#include "planning/blade_workload.h"

#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <algorithm>
#include <filesystem>
#include <limits>

namespace ddfcam::bench {
namespace {

using ddf::Vec3;

constexpr int kPoses = 217;

struct Hit {
  Vec3 point, normal;
};

std::vector<Vec3> vertexNormals(const ddf::TriangleMesh& mesh) {
  std::vector<Vec3> normals(mesh.vertices.size(), Vec3::Zero());
  for (const auto& t : mesh.triangles) {
    const Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                       .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);  // area weighted
    for (int v : t) normals[v] += n;
  }
  for (auto& n : normals) n.normalize();
  return normals;
}

/// First hit of the ray origin + s dir (s > 0) with the mesh (Moeller-Trumbore, brute force).
std::optional<Hit> castRay(const ddf::TriangleMesh& mesh, const std::vector<Vec3>& normals,
                           const Vec3& origin, const Vec3& dir) {
  double best = std::numeric_limits<double>::infinity();
  std::optional<Hit> hit;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Vec3 e1 = b - a, e2 = c - a, p = dir.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-300) continue;
    const Vec3 s = origin - a;
    const double u = s.dot(p) / det;
    if (u < 0.0 || u > 1.0) continue;
    const Vec3 q = s.cross(e1);
    const double v = dir.dot(q) / det, dist = e2.dot(q) / det;
    if (v < 0.0 || u + v > 1.0 || dist <= 0.0 || dist >= best) continue;
    best = dist;
    const Vec3 n = (1 - u - v) * normals[t[0]] + u * normals[t[1]] + v * normals[t[2]];
    hit = Hit{origin + dist * dir, n.normalized()};
  }
  return hit;
}

}  // namespace

std::optional<BladeWorkload> bladeWorkload(int resolution) {
  const auto path =
      std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "turbine-blade-jigsaw.stl";
  if (!std::filesystem::exists(path)) return std::nullopt;
  const ddf::TriangleMesh mesh = io::readMesh(path);
  const auto [lo, hi] = mesh.bounds();
  const Vec3 extent = hi - lo;
  int order[3] = {0, 1, 2};  // axes by decreasing extent
  std::sort(order, order + 3, [&](int a, int b) { return extent[a] > extent[b]; });
  const Vec3 feed = Vec3::Unit(order[0]), down = -Vec3::Unit(order[2]);
  const Vec3 centre = 0.5 * (lo + hi);
  const std::vector<Vec3> normals = vertexNormals(mesh);
  auto rayAt = [&](double s) {
    Vec3 origin = centre + (s - centre[order[0]]) * feed;
    origin[order[2]] = hi[order[2]] + 0.1 * extent[order[2]];
    return castRay(mesh, normals, origin, down);
  };
  // The span along the feed where the middle line crosses the blade, then 217 rays inside it.
  double first = hi[order[0]], last = lo[order[0]];
  for (int i = 0; i <= 200; ++i) {
    const double s = lo[order[0]] + extent[order[0]] * i / 200.0;
    if (rayAt(s)) first = std::min(first, s), last = std::max(last, s);
  }
  BladeWorkload w;
  w.size = extent[order[0]];
  w.radius = 0.04 * w.size;
  w.width = 0.08 * w.size;
  w.depth = 0.003 * w.size;
  w.tool = planning::makeCylinderTool({w.radius, w.width, 50});
  for (int i = 0; i < kPoses; ++i)
    if (const auto hit = rayAt(first + (last - first) * i / (kPoses - 1.0)))
      w.poses.push_back(
          planning::rollPoseAtContact(hit->point, hit->normal, feed, w.radius, w.depth));
  io::LoadPartParams load;
  load.conversion.resolution = resolution;
  w.ddf = io::loadPart(path, load);
  w.initialHeights = w.ddf.allHeights();
  return w;
}

}  // namespace ddfcam::bench
