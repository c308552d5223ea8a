// SPDX-License-Identifier: MIT
// ddfcam-bench: OpenVDB narrow-band level sets and CSG differences for the grinding peer.
#include "planning/openvdb_peer.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/MeshToVolume.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace ddfcam::bench {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

openvdb::FloatGrid::Ptr levelSet(const ddf::TriangleMesh& mesh,
                                 const openvdb::math::Transform& transform, double halfWidth) {
  std::vector<openvdb::Vec3s> points;
  points.reserve(mesh.vertices.size());
  // meshToLevelSet takes points in world space and maps them through the transform.
  for (const auto& v : mesh.vertices)
    points.emplace_back(static_cast<float>(v.x()), static_cast<float>(v.y()),
                        static_cast<float>(v.z()));
  std::vector<openvdb::Vec3I> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    triangles.emplace_back(static_cast<unsigned>(t[0]), static_cast<unsigned>(t[1]),
                           static_cast<unsigned>(t[2]));
  return openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(transform, points, triangles,
                                                            static_cast<float>(halfWidth));
}

}  // namespace

struct VdbPart::Impl {
  VdbLevelSetParams params;
  openvdb::math::Transform::Ptr transform;
  openvdb::FloatGrid::Ptr initial;
  openvdb::FloatGrid::Ptr grid;
};

VdbPart::VdbPart(const ddf::TriangleMesh& part, const VdbLevelSetParams& params)
    : impl_(std::make_unique<Impl>()) {
  openvdb::initialize();
  impl_->params = params;
  impl_->transform = openvdb::math::Transform::createLinearTransform(params.voxelMm);
  impl_->initial = levelSet(part, *impl_->transform, params.halfWidthVoxels);
  reset();
}

VdbPart::~VdbPart() = default;

void VdbPart::reset() {
  impl_->grid = impl_->initial->deepCopy();
}

VdbCsgTimes VdbPart::subtractTools(const ddf::TriangleMesh& tool,
                                   std::span<const Eigen::Isometry3d> poses) {
  VdbCsgTimes times;
  for (const auto& pose : poses) {
    auto start = Clock::now();
    openvdb::FloatGrid::Ptr toolGrid =
        levelSet(tool.transformed(pose), *impl_->transform, impl_->params.halfWidthVoxels);
    times.meshToLevelSetSeconds += secondsSince(start);
    start = Clock::now();
    // The result is left in the part grid; the tool grid is emptied (and then dropped).
    openvdb::tools::csgDifference(*impl_->grid, *toolGrid);
    times.csgSeconds += secondsSince(start);
  }
  return times;
}

std::size_t VdbPart::memoryBytes() const {
  return impl_->grid->memUsage();
}

std::size_t VdbPart::activeVoxels() const {
  return impl_->grid->activeVoxelCount();
}

std::optional<double> VdbPart::surfaceZ(double x, double y, double zTop, double zBottom) const {
  const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(
      *impl_->grid);
  const double step = impl_->params.voxelMm;
  double zPrev = zTop;
  double fPrev = sampler.wsSample(openvdb::Vec3d(x, y, zTop));
  if (fPrev <= 0.0) return std::nullopt;  // the column starts inside: no crossing from outside
  for (double z = zTop - step; z >= zBottom - 0.5 * step; z -= step) {
    const double f = sampler.wsSample(openvdb::Vec3d(x, y, z));
    if (f <= 0.0) return zPrev + (z - zPrev) * fPrev / (fPrev - f);
    zPrev = z;
    fPrev = f;
  }
  return std::nullopt;
}

ddf::TriangleMesh extrudedSlab(const std::function<double(double, double)>& height,
                               const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double bottomZ,
                               double cellMm) {
  const int nx = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / cellMm)));
  const int ny = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / cellMm)));
  ddf::TriangleMesh mesh;
  // Top grid vertices (i, j) at index j (nx+1) + i, then the bottom grid the same way.
  for (int bottom = 0; bottom < 2; ++bottom)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const double x = lo.x() + (hi.x() - lo.x()) * i / nx;
        const double y = lo.y() + (hi.y() - lo.y()) * j / ny;
        mesh.vertices.emplace_back(x, y, bottom ? bottomZ : height(x, y));
      }
  const int layer = (nx + 1) * (ny + 1);
  auto top = [&](int i, int j) { return j * (nx + 1) + i; };
  auto quad = [&](int a, int b, int c, int d) {  // counter-clockwise seen from outside
    mesh.triangles.push_back({a, b, c});
    mesh.triangles.push_back({a, c, d});
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      quad(top(i, j), top(i + 1, j), top(i + 1, j + 1), top(i, j + 1));
      quad(layer + top(i, j), layer + top(i, j + 1), layer + top(i + 1, j + 1),
           layer + top(i + 1, j));
    }
  for (int i = 0; i < nx; ++i) {  // walls y = lo (outward -y) and y = hi (outward +y)
    quad(top(i, 0), layer + top(i, 0), layer + top(i + 1, 0), top(i + 1, 0));
    quad(top(i + 1, ny), layer + top(i + 1, ny), layer + top(i, ny), top(i, ny));
  }
  for (int j = 0; j < ny; ++j) {  // walls x = lo (outward -x) and x = hi (outward +x)
    quad(top(0, j + 1), layer + top(0, j + 1), layer + top(0, j), top(0, j));
    quad(top(nx, j), layer + top(nx, j), layer + top(nx, j + 1), top(nx, j + 1));
  }
  return mesh;
}

}  // namespace ddfcam::bench
