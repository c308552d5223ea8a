// SPDX-License-Identifier: MIT
// ddfcam: where a placed tool of an imported program touches the part (nearest points, feet
// on the smooth surface, contact of a pose).
#include "imported_path_contacts.h"

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/path_sampling.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace ddfcam::planning::detail {
namespace {

using ddf::Vec3;

constexpr int kRimSamples = 16;

}  // namespace

PartSurface::PartSurface(const ddf::DisplacementField& part)
    : part_(part), raster_(ddf::extractRasterMesh(part)), distance_(raster_.mesh) {
  const int m = part.resolution();
  perFace_ = (m - 1) * (m - 1);
  const ddf::TriangleMesh support = ddf::extractSupportMesh(part);
  outward_.resize(static_cast<std::size_t>(part.faceCount()));
  for (int f = 0; f < part.faceCount(); ++f) {
    const auto& t = support.triangles[static_cast<std::size_t>(f)];
    const Vec3 a = support.vertices[t[0]], b = support.vertices[t[1]], c = support.vertices[t[2]];
    const Vec3 v = part.vector(t[0]) + part.vector(t[1]) + part.vector(t[2]);
    outward_[static_cast<std::size_t>(f)] = (b - a).cross(c - a).dot(v) >= 0 ? 1.0 : -1.0;
  }
}

PartSurface::Hit PartSurface::nearest(const Vec3& p) const {
  const auto c = distance_.closestPoint(p);
  if (!c) throw InvalidInput("placing a program: a tool position is not finite");
  const int face = c->triangle / perFace_;
  return {c->point, outward_[static_cast<std::size_t>(face)] * c->signedDistance, face};
}

Vec3 PartSurface::normal(const Hit& hit) const {
  if (const auto loc = ddf::locateOnFace(part_, hit.face, hit.point))
    return smoothSurfaceNormal(part_, *loc);
  const Vec3 v = part_.vectorAt(hit.face, Vec3::Constant(1.0 / 3.0));
  return v.normalized();
}

// The facets' normals jump, which shifts the nearest point of a distant c sideways by up to
// |c - hit| times the jump. Fixed-point steps: project c onto the tangent plane at the foot
// and find the mesh there.
std::pair<PartSurface::Hit, Vec3> PartSurface::smoothFoot(const Vec3& c, Hit hit) const {
  Vec3 n = normal(hit);
  for (int step = 0; step < 4; ++step) {
    const Vec3 q = c - (c - hit.point).dot(n) * n;
    const Hit next = nearest(q);
    const double moved = (next.point - hit.point).norm();
    hit = next;
    n = normal(hit);
    if (moved < 1e-9) break;
  }
  // The length, not the normal component: a tool beside the part's border is far from it.
  hit.signedDistance = std::copysign((c - hit.point).norm(), (c - hit.point).dot(n));
  return {hit, n};
}

std::vector<std::pair<Vec3, double>> coreSamples(const Tool& tool) {
  const double r = tool.radiusMm;
  switch (tool.kind) {
    case ToolKind::BallEnd:
      return {{Vec3(0, 0, r), r}};
    case ToolKind::FlatEnd:
    case ToolKind::TorusCutter: {
      const bool torus = tool.kind == ToolKind::TorusCutter;
      const double e = torus ? tool.edgeRadiusMm : 0.0;
      std::vector<std::pair<Vec3, double>> out{{Vec3::Zero(), 0.0}};
      for (int i = 0; i < kRimSamples; ++i) {
        const double phi = 2 * std::numbers::pi * i / kRimSamples;
        out.push_back({Vec3((r - e) * std::cos(phi), (r - e) * std::sin(phi), e), e});
      }
      return out;
    }
    default:
      return {{Vec3::Zero(), r}};
  }
}

PoseContact contactOf(const PartSurface& surface, const Eigen::Isometry3d& pose,
                      const std::vector<std::pair<Vec3, double>>& samples) {
  PartSurface::Hit best{};
  Vec3 core = Vec3::Zero();
  double bestGap = std::numeric_limits<double>::infinity(), reach = 0.0;
  for (const auto& [local, sampleReach] : samples) {
    const Vec3 c = pose * local;
    const PartSurface::Hit hit = surface.nearest(c);
    if (hit.signedDistance - sampleReach < bestGap - 1e-9) {
      best = hit;
      core = c;
      reach = sampleReach;
      bestGap = hit.signedDistance - sampleReach;
    }
  }
  const auto [foot, n] = surface.smoothFoot(core, best);
  return {foot.point, n, foot.signedDistance - reach, besideBorder(core, foot.point, n)};
}

bool besideBorder(const Vec3& c, const Vec3& foot, const Vec3& n) {
  const Vec3 offset = c - foot;
  const double length = offset.norm();
  return length > 1e-3 && std::abs(offset.dot(n)) < 0.9 * length;
}

}  // namespace ddfcam::planning::detail
