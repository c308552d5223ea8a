// SPDX-License-Identifier: MIT
// ddfcam: rigid alignment of a formed surface to the mould (point pairs, trimmed point-to-plane
// ICP).
#include <ddfcam/planning/mould/surface_alignment.h>

#include <ddfcam/error.h>
#include <ddfcam/planning/surface/mesh_distance.h>

#include <Eigen/Cholesky>
#include <Eigen/SVD>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ddfcam::planning {
namespace {

using Eigen::Vector3d;

// Second singular value of the centred points relative to their extent: zero for collinear or
// coincident points.
void requireSpread(const std::vector<Vector3d>& points, const char* which) {
  Vector3d centroid = Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - centroid) * (p - centroid).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(scatter);
  const auto s = svd.singularValues();  // squares of the point spread, descending
  if (!(s(0) > 0.0) || std::sqrt(s(1)) <= 1e-9 * std::sqrt(s(0)))
    throw InvalidInput(std::string("alignByPointPairs: the ") + which +
                       " points are collinear or coincident");
}

double pairRms(std::span<const std::array<Vector3d, 2>> pairs, const Eigen::Isometry3d& t) {
  double sum = 0.0;
  for (const auto& [from, to] : pairs) sum += (t * from - to).squaredNorm();
  return std::sqrt(sum / static_cast<double>(pairs.size()));
}

// One ICP pair: sample (in the current pose), closest point and normal of the fixed mesh.
struct IcpPair {
  Vector3d q, c, n;
  double distance = 0.0;
};

class BestFit {
 public:
  BestFit(const ddf::TriangleMesh& moving, const ddf::TriangleMesh& fixed,
          const BestFitParams& params)
      : fixed_(fixed), distance_(fixed), params_(params) {
    std::vector<char> used(moving.vertices.size(), 0);
    for (const auto& t : moving.triangles)
      for (const int v : t) {
        if (v < 0 || v >= static_cast<int>(used.size()))
          throw InvalidInput("alignBestFit: moving triangle refers to vertex " + std::to_string(v) +
                             " out of range");
        used[v] = 1;
      }
    std::vector<Vector3d> all;
    for (std::size_t v = 0; v < used.size(); ++v)
      if (used[v]) all.push_back(moving.vertices[v]);
    const std::size_t stride =
        std::max<std::size_t>(1, (all.size() + params.maxSamples - 1) / params.maxSamples);
    for (std::size_t i = 0; i < all.size(); i += stride) samples_.push_back(all[i]);
  }

  RigidAlignment run() {
    RigidAlignment result;
    result.converged = false;
    Eigen::Isometry3d pose = params_.initial;
    for (int iteration = 0; iteration < params_.maxIterations; ++iteration) {
      reportProgress(params_.progress, double(iteration) / params_.maxIterations);
      const std::vector<IcpPair> pairs = trimmedPairs(pose);
      if (iteration == 0) result.rmsBeforeMm = rms(pairs);
      if (pairs.size() < 6) break;
      const Eigen::Isometry3d step = solveStep(pairs);
      pose = step * pose;
      result.iterations = iteration + 1;
      double moved = 0.0;
      for (const auto& p : pairs) moved = std::max(moved, (step * p.q - p.q).norm());
      if (moved <= params_.toleranceMm) {
        result.converged = true;
        break;
      }
    }
    reportProgress(params_.progress, 1.0);
    result.transform = pose;
    result.rmsMm = rms(trimmedPairs(pose));
    if (result.iterations == 0) result.rmsBeforeMm = result.rmsMm;
    return result;
  }

 private:
  std::vector<IcpPair> trimmedPairs(const Eigen::Isometry3d& pose) const {
    std::vector<IcpPair> pairs(samples_.size());
    std::vector<char> found(samples_.size(), 0);
    tbb::parallel_for(std::size_t{0}, samples_.size(), [&](std::size_t i) {
      const Vector3d q = pose * samples_[i];
      const auto cp = distance_.closestPoint(q, params_.maxPairDistanceMm);
      if (!cp) return;
      const auto& t = fixed_.triangles[cp->triangle];
      const Vector3d& a = fixed_.vertices[t[0]];
      Vector3d n = (fixed_.vertices[t[1]] - a).cross(fixed_.vertices[t[2]] - a);
      if (!(n.norm() > 0.0)) return;
      pairs[i] = {q, cp->point, n.normalized(), cp->distance};
      found[i] = 1;
    });
    std::vector<IcpPair> kept;
    for (std::size_t i = 0; i < pairs.size(); ++i)
      if (found[i]) kept.push_back(pairs[i]);
    const auto keep = static_cast<std::size_t>(
        std::ceil((1.0 - params_.trimFraction) * static_cast<double>(kept.size())));
    if (keep < kept.size()) {
      std::nth_element(kept.begin(), kept.begin() + keep, kept.end(),
                       [](const IcpPair& x, const IcpPair& y) { return x.distance < y.distance; });
      kept.resize(keep);
    }
    return kept;
  }

  static double rms(const std::vector<IcpPair>& pairs) {
    if (pairs.empty()) return 0.0;
    double sum = 0.0;
    for (const auto& p : pairs) sum += p.distance * p.distance;
    return std::sqrt(sum / static_cast<double>(pairs.size()));
  }

  // Linearised point-to-plane step about the pairs' centroid (better conditioned than about
  // the origin): minimise sum ((q' + w x q' + t - c') . n)^2 over (w, t).
  static Eigen::Isometry3d solveStep(const std::vector<IcpPair>& pairs) {
    Vector3d centroid = Vector3d::Zero();
    for (const auto& p : pairs) centroid += p.q;
    centroid /= static_cast<double>(pairs.size());
    Eigen::Matrix<double, 6, 6> ata = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> atb = Eigen::Matrix<double, 6, 1>::Zero();
    for (const auto& p : pairs) {
      Eigen::Matrix<double, 6, 1> row;
      row << (p.q - centroid).cross(p.n), p.n;
      ata += row * row.transpose();
      atb -= row * (p.q - p.c).dot(p.n);
    }
    // A little damping keeps directions the surface does not constrain (a plane's in-plane
    // shift) at zero instead of letting them run off.
    ata.diagonal().array() += 1e-9 * ata.trace() + 1e-12;
    const Eigen::Matrix<double, 6, 1> x = ata.ldlt().solve(atb);
    const Vector3d w = x.head<3>();
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    if (w.norm() > 0.0) rotation = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
    Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
    step.linear() = rotation;
    step.translation() = centroid - rotation * centroid + x.tail<3>();
    return step;
  }

  const ddf::TriangleMesh& fixed_;
  MeshDistance distance_;
  BestFitParams params_;
  std::vector<Vector3d> samples_;
};

}  // namespace

RigidAlignment alignByPointPairs(std::span<const std::array<Eigen::Vector3d, 2>> pairs) {
  if (pairs.size() < 3)
    throw InvalidInput("alignByPointPairs: " + std::to_string(pairs.size()) +
                       " point pairs, at least 3 needed");
  std::vector<Vector3d> from, to;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (!pairs[i][0].allFinite() || !pairs[i][1].allFinite())
      throw InvalidInput("alignByPointPairs: pair " + std::to_string(i) + " is not finite");
    from.push_back(pairs[i][0]);
    to.push_back(pairs[i][1]);
  }
  requireSpread(from, "from");
  requireSpread(to, "to");
  Vector3d cf = Vector3d::Zero(), ct = Vector3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) cf += from[i], ct += to[i];
  cf /= static_cast<double>(from.size());
  ct /= static_cast<double>(to.size());
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) h += (from[i] - cf) * (to[i] - ct).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  // A reflection fits mirrored point sets better than any rotation; exclude it (Kabsch).
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  RigidAlignment result;
  result.transform.linear() = svd.matrixV() * d * svd.matrixU().transpose();
  result.transform.translation() = ct - result.transform.linear() * cf;
  result.rmsMm = pairRms(pairs, result.transform);
  result.rmsBeforeMm = pairRms(pairs, Eigen::Isometry3d::Identity());
  return result;
}

RigidAlignment alignBestFit(const ddf::TriangleMesh& moving, const ddf::TriangleMesh& fixed,
                            const BestFitParams& params) {
  if (moving.triangles.empty()) throw InvalidInput("alignBestFit: the moving mesh is empty");
  if (params.maxSamples < 3 || !(params.trimFraction >= 0.0 && params.trimFraction <= 0.9) ||
      params.maxIterations < 1 || !(params.toleranceMm > 0.0))
    throw InvalidInput(
        "alignBestFit: parameters out of range (maxSamples >= 3, trimFraction in "
        "[0, 0.9], maxIterations >= 1, toleranceMm > 0)");
  return BestFit(moving, fixed, params).run();
}

double rotationAngleDeg(const Eigen::Isometry3d& transform) {
  return Eigen::AngleAxisd(transform.rotation()).angle() * 180.0 / std::numbers::pi;
}

std::array<double, 16> toRowMajor(const Eigen::Isometry3d& transform) {
  std::array<double, 16> m{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[4 * r + c] = transform.matrix()(r, c);
  return m;
}

Eigen::Isometry3d fromRowMajor(const std::array<double, 16>& matrix) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) t.matrix()(r, c) = matrix[4 * r + c];
  return t;
}

}  // namespace ddfcam::planning
