// SPDX-License-Identifier: MIT
// ddfcam: incremental grid of polyline segments for distance queries (private).
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/planning/surface/uniform_grid.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace ddfcam::planning::detail {

/// @brief What a query ignores: segments facing away (normal dot < 0) and, on polyline
/// @c line, segments whose arc position is within @c arcGapMm of @c arcMm.
struct SeparationSkip {
  int line = -1;
  double arcMm = 0.0;
  double arcGapMm = 0.0;
};

/// @brief Segments of accepted polylines in a UniformGrid (cell size c, mm), added while the
/// lines grow. Segments carry the surface normal at their start, the polyline they belong to
/// and their arc position, so a query can ignore the far side of a thin wall and the
/// neighbourhood of its own position on the same line.
class SeparationGrid {
 public:
  explicit SeparationGrid(double cellMm) : grid_(cellMm) {}

  /// @brief Adds segment a -> b of polyline @p line starting at arc length @p arcMm.
  void add(const ddf::Vec3& a, const ddf::Vec3& b, const ddf::Vec3& normal, int line,
           double arcMm) {
    grid_.add(static_cast<int>(segments_.size()), a.cwiseMin(b), a.cwiseMax(b));
    segments_.push_back({a, b, normal, line, arcMm});
  }

  /// @brief Smallest distance from @p q (surface normal @p normal) to a segment, if one is
  /// closer than @p radiusMm; otherwise +infinity. @p nearestId receives that segment (or -1).
  double distance(const ddf::Vec3& q, const ddf::Vec3& normal, double radiusMm,
                  const SeparationSkip& skip = {}, int* nearestId = nullptr) const {
    double best = std::numeric_limits<double>::infinity();
    int bestId = -1;
    grid_.forEachNear(q, radiusMm, [&](int id) {
      if (!counts(segments_[id], normal, skip)) return;
      const double d = segmentDistance(q, segments_[id]);
      if (d < best) best = d, bestId = id;
    });
    if (!(best < radiusMm)) best = std::numeric_limits<double>::infinity(), bestId = -1;
    if (nearestId) *nearestId = bestId;
    return best;
  }

  /// @brief Whether distance() would be finite: some segment lies closer than @p radiusMm
  /// (stops at the first one found).
  bool near(const ddf::Vec3& q, const ddf::Vec3& normal, double radiusMm,
            const SeparationSkip& skip = {}) const {
    return grid_.findNear(q, radiusMm, [&](int id) {
      return counts(segments_[id], normal, skip) && segmentDistance(q, segments_[id]) < radiusMm;
    });
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

  static bool counts(const Segment& s, const ddf::Vec3& normal, const SeparationSkip& skip) {
    return !(s.normal.dot(normal) < 0.0) &&
           !(s.line == skip.line && std::abs(s.arcMm - skip.arcMm) < skip.arcGapMm);
  }
  static double segmentDistance(const ddf::Vec3& q, const Segment& s) {
    const ddf::Vec3 ab = s.b - s.a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((q - s.a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (s.a + t * ab - q).norm();
  }

  UniformGrid grid_;
  std::vector<Segment> segments_;
};

}  // namespace ddfcam::planning::detail
