// SPDX-License-Identifier: MIT
// ddfcam: incremental uniform grid of polyline segments for distance queries (private).
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace ddfcam::planning::detail {

/// @brief What a query ignores: segments facing away (normal dot < 0) and, on polyline
/// @c line, segments whose arc position is within @c arcGapMm of @c arcMm.
struct SeparationSkip {
  int line = -1;
  double arcMm = 0.0;
  double arcGapMm = 0.0;
};

/// @brief Segments of accepted polylines in a hashed uniform grid (cell size c, mm). Each
/// segment is entered in every cell its bounding box overlaps, so a query of radius r looks at
/// the (2 ceil(r / c) + 1)^3 cells around the point. Segments carry the surface normal at their
/// start, the polyline they belong to and their arc position, so a query can ignore the far
/// side of a thin wall and the neighbourhood of its own position on the same line.
class SeparationGrid {
 public:
  explicit SeparationGrid(double cellMm) : cell_(cellMm) {}

  /// @brief Adds segment a -> b of polyline @p line starting at arc length @p arcMm.
  void add(const ddf::Vec3& a, const ddf::Vec3& b, const ddf::Vec3& normal, int line,
           double arcMm) {
    const auto id = static_cast<int>(segments_.size());
    segments_.push_back({a, b, normal, line, arcMm});
    const Eigen::Vector3i lo = cellOf(a.cwiseMin(b)), hi = cellOf(a.cwiseMax(b));
    for (int x = lo.x(); x <= hi.x(); ++x)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int z = lo.z(); z <= hi.z(); ++z) cells_[key({x, y, z})].push_back(id);
  }

  /// @brief Smallest distance from @p q (surface normal @p normal) to a segment, if one is
  /// closer than @p radiusMm; otherwise +infinity. @p nearestId receives that segment (or -1).
  double distance(const ddf::Vec3& q, const ddf::Vec3& normal, double radiusMm,
                  const SeparationSkip& skip = {}, int* nearestId = nullptr) const {
    double best = std::numeric_limits<double>::infinity();
    int bestId = -1;
    if (!segments_.empty()) {
      const int reach = std::max(1, static_cast<int>(std::ceil(radiusMm / cell_)));
      const Eigen::Vector3i c = cellOf(q);
      for (int x = -reach; x <= reach; ++x)
        for (int y = -reach; y <= reach; ++y)
          for (int z = -reach; z <= reach; ++z) {
            const auto it = cells_.find(key(c + Eigen::Vector3i(x, y, z)));
            if (it == cells_.end()) continue;
            for (const int id : it->second) {
              const Segment& s = segments_[id];
              if (s.normal.dot(normal) < 0.0) continue;
              if (s.line == skip.line && std::abs(s.arcMm - skip.arcMm) < skip.arcGapMm) continue;
              const double d = segmentDistance(q, s);
              if (d < best) best = d, bestId = id;
            }
          }
    }
    if (!(best < radiusMm)) best = std::numeric_limits<double>::infinity(), bestId = -1;
    if (nearestId) *nearestId = bestId;
    return best;
  }

  /// @brief Whether segment @p id (from distance()) faces like @p normal and lies closer than
  /// @p radiusMm to @p q: a cheap test of a previous query's answer for a nearby point.
  bool within(int id, const ddf::Vec3& q, const ddf::Vec3& normal, double radiusMm) const {
    if (id < 0) return false;
    const Segment& s = segments_[static_cast<std::size_t>(id)];
    return s.normal.dot(normal) >= 0.0 && segmentDistance(q, s) < radiusMm;
  }

  std::size_t size() const { return segments_.size(); }

 private:
  struct Segment {
    ddf::Vec3 a, b, normal;
    int line;
    double arcMm;
  };

  Eigen::Vector3i cellOf(const ddf::Vec3& p) const {
    return (p / cell_).array().floor().cast<int>();
  }
  static std::int64_t key(const Eigen::Vector3i& c) {
    // 21 bits per axis: +-1e6 cells, far more than any part at a sensible spacing.
    const auto part = [](int v) { return static_cast<std::int64_t>(v + (1 << 20)) & 0x1FFFFF; };
    return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
  }
  static double segmentDistance(const ddf::Vec3& q, const Segment& s) {
    const ddf::Vec3 ab = s.b - s.a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((q - s.a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (s.a + t * ab - q).norm();
  }

  double cell_;
  std::vector<Segment> segments_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

}  // namespace ddfcam::planning::detail
