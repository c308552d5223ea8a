// SPDX-License-Identifier: MIT
// ddfcam: ordering the paths of a region and linking them (zig-zag or one direction).
#include <ddfcam/planning/placement/path_linking.h>

#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline_path.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;
using Polylines = std::vector<std::vector<Vec3>>;

double polylineLength(const std::vector<Vec3>& pts) {
  double sum = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) sum += (pts[i] - pts[i - 1]).norm();
  return sum;
}

// Sign of an axis that does not depend on the sign it came with.
Vec3 canonicalSign(const Vec3& d) {
  int best = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(d[i]) > std::abs(d[best])) best = i;
  return d[best] < 0.0 ? Vec3(-d) : d;
}

// Unit eigenvector of the largest eigenvalue of sum v v^T (a sign-free mean direction);
// @p fallback when the vectors are all zero.
Vec3 principalAxis(const std::vector<Vec3>& vectors, const Vec3& fallback) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const Vec3& v : vectors) m += v * v.transpose();
  if (!(m.norm() > 0.0)) return fallback;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
  return canonicalSign(eig.eigenvectors().col(2).normalized());
}

// Length-weighted centroid of a polyline (the centre of a closed loop, not a point on it).
Vec3 centroid(const std::vector<Vec3>& pts) {
  Vec3 sum = Vec3::Zero();
  double total = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const double len = (pts[i] - pts[i - 1]).norm();
    sum += 0.5 * len * (pts[i] + pts[i - 1]), total += len;
  }
  return total > 0.0 ? Vec3(sum / total) : pts.front();
}

// Direction of a path: its chord, or its first segment when it closes on itself.
Vec3 chord(const std::vector<Vec3>& pts) {
  const Vec3 c = pts.back() - pts.front();
  return c.norm() > 1e-9 * polylineLength(pts) ? c : Vec3(pts[1] - pts[0]);
}

void checkParams(const LinkingParams& p) {
  if (p.feedSign != 1 && p.feedSign != -1)
    throw InvalidInput("linkPaths: feed sign " + std::to_string(p.feedSign) + " is not +-1");
  if (!(p.directLinkMaxMm >= 0.0) || !(p.clearanceMm >= 0.0) || !std::isfinite(p.clearanceMm))
    throw InvalidInput("linkPaths: direct link limit or clearance is negative or not finite");
  if (!p.feedDirection.allFinite() || !(p.retractDirection.norm() > 0.0) ||
      !p.retractDirection.allFinite())
    throw InvalidInput("linkPaths: feed direction not finite or retract direction zero");
}

class Linker {
 public:
  Linker(const Polylines& paths, const Polylines* normals, const LinkingParams& p)
      : paths_(paths), normals_(normals), p_(p) {
    for (int i = 0; i < static_cast<int>(paths.size()); ++i)
      if (paths[i].size() >= 2) usable_.push_back(i);
    std::vector<Vec3> chords, centres;
    for (const int i : usable_)
      chords.push_back(chord(paths[i])), centroids_.push_back(centroid(paths[i]));
    const Vec3 auto_ = principalAxis(chords, Vec3::UnitX());
    feed_ = p.feedSign * (p.feedDirection.norm() > 0.0 ? p.feedDirection.normalized() : auto_);
    Vec3 mean = Vec3::Zero();
    for (const Vec3& c : centroids_) mean += c;
    if (!centroids_.empty()) mean /= static_cast<double>(centroids_.size());
    for (const Vec3& c : centroids_) centres.push_back(c - mean);
    across_ = principalAxis(centres, Vec3::UnitY());
  }

  LinkedPaths run() {
    LinkedPaths out;
    std::vector<bool> done(usable_.size(), false);
    int first = -1;
    for (int u = 0; u < static_cast<int>(usable_.size()); ++u)
      if (first < 0 || centroids_[u].dot(across_) < centroids_[first].dot(across_)) first = u;
    if (first < 0) return out;
    bool reversed = chord(paths_[usable_[first]]).dot(feed_) < 0.0;
    for (std::size_t count = 0; count < usable_.size(); ++count) {
      if (count > 0) pickNext(out.moves.back(), done, first, reversed);
      done[first] = true;
      const int index = usable_[first];
      if (count > 0) {
        const PathMove& last = out.moves.back();
        addLink(out, last.points.back(), normalAt(last.path, last.reversed, false), index,
                reversed);
      }
      PathMove cut{MoveKind::Cut, paths_[index], index, reversed};
      if (reversed) std::reverse(cut.points.begin(), cut.points.end());
      out.cuttingLengthMm += polylineLength(cut.points);
      out.order.push_back(index);
      out.moves.push_back(std::move(cut));
      ++out.pathCount;
    }
    return out;
  }

 private:
  const Vec3& endOf(int index, bool reversed, bool atStart) const {
    const auto& pts = paths_[index];
    return (atStart != reversed) ? pts.front() : pts.back();
  }
  Vec3 normalAt(int index, bool reversed, bool atStart) const {
    if (!normals_) return p_.retractDirection.normalized();
    const auto& n = (*normals_)[index];
    return ((atStart != reversed) ? n.front() : n.back()).normalized();
  }

  // The nearest unvisited path from the end of @p last (see linkPaths()).
  void pickNext(const PathMove& last, const std::vector<bool>& done, int& next,
                bool& reversed) const {
    const Vec3& end = last.points.back();
    double best = std::numeric_limits<double>::infinity();
    for (int u = 0; u < static_cast<int>(usable_.size()); ++u) {
      if (done[u]) continue;
      const int index = usable_[u];
      for (const bool rev : {false, true}) {
        if (p_.order == LinkingOrder::OneDirection &&
            rev != (chord(paths_[index]).dot(feed_) < 0.0))
          continue;
        const double gap = (endOf(index, rev, true) - end).norm();
        if (gap < best) best = gap, next = u, reversed = rev;
      }
    }
  }

  void addMove(LinkedPaths& out, MoveKind kind, const Vec3& a, const Vec3& b) const {
    if ((b - a).norm() <= 0.0) return;
    out.idleLengthMm += (b - a).norm();
    out.moves.push_back({kind, {a, b}, -1, false});
  }

  // Link from the end @p a (normal @p na) of the last cut to the start of path @p index.
  void addLink(LinkedPaths& out, Vec3 a, Vec3 na, int index, bool reversed) const {
    const Vec3& b = endOf(index, reversed, true);
    const Vec3 nb = normalAt(index, reversed, true);
    ++out.linkCount;
    if ((b - a).norm() <= p_.directLinkMaxMm) {
      addMove(out, MoveKind::Link, a, b);
      return;
    }
    ++out.liftedLinkCount;
    const Vec3 a2 = a + p_.clearanceMm * na, b2 = b + p_.clearanceMm * nb;
    addMove(out, MoveKind::Link, a, a2);
    addMove(out, MoveKind::Rapid, a2, b2);
    addMove(out, MoveKind::Link, b2, b);
  }

  const Polylines& paths_;
  const Polylines* normals_;
  const LinkingParams& p_;
  std::vector<int> usable_;
  std::vector<Vec3> centroids_;
  Vec3 feed_ = Vec3::UnitX();
  Vec3 across_ = Vec3::UnitY();
};

}  // namespace

LinkedPaths linkPaths(const Polylines& paths, const LinkingParams& params) {
  checkParams(params);
  return Linker(paths, nullptr, params).run();
}

LinkedPaths linkPaths(const Polylines& paths, const Polylines& normals,
                      const LinkingParams& params) {
  checkParams(params);
  if (normals.size() != paths.size())
    throw InvalidInput("linkPaths: " + std::to_string(normals.size()) + " normal lists for " +
                       std::to_string(paths.size()) + " paths");
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (normals[i].size() != paths[i].size()) {
      throw InvalidInput("linkPaths: path " + std::to_string(i) + " has " +
                         std::to_string(paths[i].size()) + " points but " +
                         std::to_string(normals[i].size()) + " normals");
    }
  }
  return Linker(paths, &normals, params).run();
}

LinkedPaths linkStreamlines(const ddf::DisplacementField& ddf, const std::vector<Streamline>& lines,
                            const LinkingParams& params) {
  Polylines paths, normals;
  paths.reserve(lines.size()), normals.reserve(lines.size());
  for (const Streamline& line : lines) {
    paths.push_back(line.polyline());
    auto& n = normals.emplace_back();
    for (const auto& p : line.points) n.push_back(surfaceNormal(ddf, p));
  }
  return linkPaths(paths, normals, params);
}

}  // namespace ddfcam::planning
