// SPDX-License-Identifier: MIT
// ddfcam: hashed uniform grid of item ids (points, segments) for fixed-radius neighbour queries.
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace ddfcam::planning {

/// @brief Item ids in a hashed uniform grid of cubes of edge cellMm(): an item is entered in
/// every cell its axis-aligned box overlaps (a point in one cell, a segment in the cells of
/// its bounding box), and a query visits the ids in the cells overlapping a box. The caller
/// keeps the items and tests the exact distance, so a query finds every item within its
/// radius and some farther ones; an id entered in several cells may be visited more than once.
///
/// A grid rather than a k-d tree (such as nanoflann): the streamline tracers insert segments
/// while lines grow and ask for neighbours within a fixed radius of about one cell, which a
/// hashed grid answers with a few cell look-ups and no rebuilding; a tree suits static point
/// sets and nearest-neighbour queries, and holds points rather than segments.
class UniformGrid {
 public:
  using Cell = Eigen::Vector3i;  ///< integer cell coordinates, floor(p / cellMm())

  /// @param cellMm cell edge, mm (> 0).
  explicit UniformGrid(double cellMm) : cell_(cellMm) {}

  /// @brief Cell edge, mm.
  double cellMm() const { return cell_; }

  /// @brief The cell holding @p p, each coordinate clamped to +-2^30 (NaN counts as 0).
  Cell cellOf(const ddf::Vec3& p) const {
    const auto axis = [this](double v) {
      const double c = std::floor(v / cell_);
      return std::isnan(c) ? 0 : static_cast<int>(std::clamp(c, -kMaxCell, kMaxCell));
    };
    return {axis(p.x()), axis(p.y()), axis(p.z())};
  }

  /// @brief Enters @p id in every cell that the box [@p lo, @p hi] (mm) overlaps.
  void add(int id, const ddf::Vec3& lo, const ddf::Vec3& hi) {
    const Cell a = cellOf(lo), b = cellOf(hi);
    for (int x = a.x(); x <= b.x(); ++x)
      for (int y = a.y(); y <= b.y(); ++y)
        for (int z = a.z(); z <= b.z(); ++z) cells_[key({x, y, z})].push_back(id);
  }
  /// @brief Enters @p id in the cell of point @p p.
  void add(int id, const ddf::Vec3& p) { cells_[key(cellOf(p))].push_back(id); }

  /// @brief Calls @p pred(id) for the ids in the cells from @p lo to @p hi (inclusive) until it
  /// returns true; a range of more cells than are occupied visits every occupied cell instead.
  /// @returns whether @p pred returned true.
  template <class Pred>
  bool findInCells(const Cell& lo, const Cell& hi, Pred&& pred) const {
    if (cells_.empty()) return false;
    const Eigen::Vector3d extent = (hi.cast<double>() - lo.cast<double>()).array() + 1.0;
    if (extent.minCoeff() <= 0.0) return false;
    const auto visit = [&](const std::vector<int>& ids) {
      return std::any_of(ids.begin(), ids.end(), [&](int id) { return pred(id); });
    };
    if (extent.prod() > static_cast<double>(cells_.size())) {
      for (const auto& entry : cells_)
        if (visit(entry.second)) return true;
      return false;
    }
    for (int x = lo.x(); x <= hi.x(); ++x)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int z = lo.z(); z <= hi.z(); ++z)
          if (const auto it = cells_.find(key({x, y, z})); it != cells_.end() && visit(it->second))
            return true;
    return false;
  }

  /// @brief findInCells() over the cells that the ball of @p radiusMm around @p q overlaps.
  template <class Pred>
  bool findNear(const ddf::Vec3& q, double radiusMm, Pred&& pred) const {
    const ddf::Vec3 reach = ddf::Vec3::Constant(radiusMm);
    return findInCells(cellOf(q - reach), cellOf(q + reach), pred);
  }

  /// @brief Calls @p fn(id) for the ids in the cells that the box [@p lo, @p hi] overlaps.
  template <class Fn>
  void forEachInBox(const ddf::Vec3& lo, const ddf::Vec3& hi, Fn&& fn) const {
    findInCells(cellOf(lo), cellOf(hi), [&](int id) { return fn(id), false; });
  }

  /// @brief Calls @p fn(id) for the ids in the cells that the ball of @p radiusMm around @p q
  /// overlaps.
  template <class Fn>
  void forEachNear(const ddf::Vec3& q, double radiusMm, Fn&& fn) const {
    findNear(q, radiusMm, [&](int id) { return fn(id), false; });
  }

  /// @brief Number of occupied cells.
  std::size_t cellCount() const { return cells_.size(); }

 private:
  static constexpr double kMaxCell = 1 << 30;

  // 21 bits per axis: cells 2^21 apart share a key, which only adds candidates to a query.
  static std::int64_t key(const Cell& c) {
    const auto part = [](int v) { return static_cast<std::int64_t>(v + (1 << 20)) & 0x1FFFFF; };
    return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
  }

  double cell_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

}  // namespace ddfcam::planning
