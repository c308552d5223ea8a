// SPDX-License-Identifier: MIT
// ddfcam: unique projection during the support reduction (sec. 6.2, sec. 4.4).
#include "reduction_constraints.h"

#include "reduction_items.h"

#include <ddfcam/ddf/crust.h>
#include <ddfcam/ddf/displacement_field.h>

#include <algorithm>
#include <cmath>

namespace ddfcam::ddf::detail {
namespace {

bool feasible(std::span<NewFace> faces, const Vec3& direction, double length) {
  for (NewFace& f : faces) {
    f.corners.v[f.newCorner] = length * direction;
    const auto& c = f.corners;
    if (crustHeights(c.p[0], c.p[1], c.p[2], c.v[0], c.v[1], c.v[2]).min() < kReductionMinH0)
      return false;
  }
  return true;
}

Vec3 normalOf(const FaceCorners& f) {
  return (f.p[1] - f.p[0]).cross(f.p[2] - f.p[0]);
}

bool separatedAlong(const std::array<Vec3, 6>& a, const std::array<Vec3, 6>& b, const Vec3& axis) {
  double aLo = a[0].dot(axis), aHi = aLo, bLo = b[0].dot(axis), bHi = bLo;
  for (int i = 1; i < 6; ++i) {
    const double x = a[i].dot(axis), y = b[i].dot(axis);
    aLo = std::min(aLo, x), aHi = std::max(aHi, x), bLo = std::min(bLo, y), bHi = std::max(bHi, y);
  }
  return aHi < bLo || bHi < aLo;
}

// A quick separating-axis test of the crusts' hulls (support normals and side-wall normals)
// before the exact test, which builds a field.
bool hullsSeparated(const FaceCorners& s, const FaceCorners& t) {
  std::array<Vec3, 6> cs, ct;
  for (int i = 0; i < 3; ++i) {
    cs[2 * i] = s.p[i] + s.v[i], cs[2 * i + 1] = s.p[i] - s.v[i];
    ct[2 * i] = t.p[i] + t.v[i], ct[2 * i + 1] = t.p[i] - t.v[i];
  }
  if (separatedAlong(cs, ct, normalOf(s)) || separatedAlong(cs, ct, normalOf(t))) return true;
  for (const FaceCorners* f : {&s, &t})
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (separatedAlong(cs, ct, (f->p[j] - f->p[i]).cross(f->v[i] + f->v[j]))) return true;
    }
  return false;
}

}  // namespace

std::optional<double> chooseNewVectorLength(std::span<NewFace> faces, const Vec3& direction,
                                            double maxLength) {
  // h0 falls as the new vector grows once it dominates, but a vector much shorter than its
  // neighbours can fold the crust too: scan down geometrically, then refine the first step
  // that works against the one above it.
  constexpr double kStep = 0.7;
  constexpr int kSteps = 24;
  double length = maxLength;
  int k = 0;
  while (k < kSteps && !feasible(faces, direction, length)) length *= kStep, ++k;
  if (k == kSteps) return std::nullopt;
  if (k > 0) {
    double lo = length, hi = length / kStep;
    for (int it = 0; it < 8; ++it) {
      const double mid = 0.5 * (lo + hi);
      (feasible(faces, direction, mid) ? lo : hi) = mid;
    }
    length = lo;
  }
  // As the safety factor of sec. 4.4: the faces the new vector limits keep h0 ~ 1.25, room
  // for the next contraction around them (a face at h0 = 1 refuses any change that lowers it).
  if (feasible(faces, direction, kNewVectorSafety * length)) return kNewVectorSafety * length;
  feasible(faces, direction, length);  // leaves the chosen vector in the faces
  return length;
}

Eigen::Vector3i CrustBoxHash::cellOf(const Vec3& p) const {
  return {static_cast<int>(std::floor(p.x() / cell_)), static_cast<int>(std::floor(p.y() / cell_)),
          static_cast<int>(std::floor(p.z() / cell_))};
}

CrustBoxHash::Key CrustBoxHash::key(int x, int y, int z) {
  const auto u = [](int c) { return static_cast<Key>(static_cast<std::uint32_t>(c) & 0x1fffff); };
  return u(x) | u(y) << 21 | u(z) << 42;
}

void CrustBoxHash::set(int face, const Eigen::AlignedBox3d& box) {
  remove(face);
  if (face >= static_cast<int>(boxes_.size())) {
    boxes_.resize(face + 1);
    present_.resize(face + 1, 0);
    stamp_.resize(face + 1, 0);
  }
  boxes_[face] = box;
  present_[face] = 1;
  const Eigen::Vector3i lo = cellOf(box.min()), hi = cellOf(box.max());
  for (int x = lo.x(); x <= hi.x(); ++x)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int z = lo.z(); z <= hi.z(); ++z) cells_[key(x, y, z)].push_back(face);
}

void CrustBoxHash::remove(int face) {
  if (face >= static_cast<int>(present_.size()) || !present_[face]) return;
  present_[face] = 0;
  const Eigen::AlignedBox3d& box = boxes_[face];
  const Eigen::Vector3i lo = cellOf(box.min()), hi = cellOf(box.max());
  for (int x = lo.x(); x <= hi.x(); ++x)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int z = lo.z(); z <= hi.z(); ++z) {
        const auto it = cells_.find(key(x, y, z));
        if (it == cells_.end()) continue;
        auto& list = it->second;
        list.erase(std::remove(list.begin(), list.end(), face), list.end());
        if (list.empty()) cells_.erase(it);
      }
}

void CrustBoxHash::query(const Eigen::AlignedBox3d& box, std::vector<int>& out) {
  out.clear();
  ++now_;
  const Eigen::Vector3i lo = cellOf(box.min()), hi = cellOf(box.max());
  for (int x = lo.x(); x <= hi.x(); ++x)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int z = lo.z(); z <= hi.z(); ++z) {
        const auto it = cells_.find(key(x, y, z));
        if (it == cells_.end()) continue;
        for (int f : it->second) {
          if (stamp_[f] == now_) continue;
          stamp_[f] = now_;
          if (boxes_[f].intersects(box)) out.push_back(f);
        }
      }
}

bool crustsConflict(const FaceCorners& s, const FaceCorners& t) {
  if (!crustBox(s).intersects(crustBox(t)) || hullsSeparated(s, t)) return false;
  std::vector<Vec3> points, vectors;
  for (const FaceCorners* f : {&s, &t})
    for (int i = 0; i < 3; ++i) points.push_back(f->p[i]), vectors.push_back(f->v[i]);
  const DisplacementField pair(makeSupportMesh(points, {{0, 1, 2}, {3, 4, 5}}), vectors, 2);
  return crustsIntersect(pair, 0, 1);
}

}  // namespace ddfcam::ddf::detail
