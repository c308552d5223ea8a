// SPDX-License-Identifier: MIT
// ddfcam: curvature of flat-faced DDFs from quadric fits at the support vertices.
#include <ddfcam/error.h>
#include <ddfcam/planning/vertex_curvature.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;
using Mat3 = Eigen::Matrix3d;

// Raster coordinates (i, k) of local corner c: bary (i, j, k) / n puts p1 at i = n.
std::pair<int, int> cornerCoord(int c, int n) {
  return c == 0 ? std::pair{n, 0} : c == 1 ? std::pair{0, 0} : std::pair{0, n};
}

// Represented surface point of every support vertex (from its first incident face).
std::vector<Vec3> vertexPoints(const ddf::DisplacementField& ddf) {
  const int n = ddf.raster().steps();
  std::vector<Vec3> out(static_cast<std::size_t>(ddf.vertexCount()), Vec3::Zero());
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int c = 0; c < 3; ++c) {
      const auto [i, k] = cornerCoord(c, n);
      out[static_cast<std::size_t>(ddf.faceVertices(f)[c])] = ddf.surfacePoint(f, i, k);
    }
  return out;
}

// Area-weighted normal of the represented triangles around vertex v, on the +v side.
Vec3 vertexNormal(const ddf::DisplacementField& ddf, const std::vector<Vec3>& q, int v) {
  Vec3 sum = Vec3::Zero();
  for (const int f : ddf.topology().vertexFaces(v)) {
    const auto& fv = ddf.faceVertices(f);
    sum += (q[fv[1]] - q[fv[0]]).cross(q[fv[2]] - q[fv[0]]);
  }
  if (sum.dot(ddf.vector(v)) < 0.0) sum = -sum;
  return sum.norm() > 0.0 ? Vec3(sum.normalized()) : Vec3(ddf.vector(v).normalized());
}

// Vertices within @p rings rings of @p v (v excluded).
std::vector<int> ringNeighbours(const ddf::DisplacementField& ddf, int v, int rings) {
  std::vector<int> found{v};
  std::size_t frontBegin = 0;
  for (int r = 0; r < rings; ++r) {
    const std::size_t frontEnd = found.size();
    for (std::size_t a = frontBegin; a < frontEnd; ++a)
      for (const int f : ddf.topology().vertexFaces(found[a]))
        for (const int w : ddf.faceVertices(f))
          if (std::find(found.begin(), found.end(), w) == found.end()) found.push_back(w);
    frontBegin = frontEnd;
  }
  found.erase(found.begin());
  return found;
}

struct VertexShape {
  Mat3 tensor = Mat3::Zero();  // sum kappa_i t_i t_i^T, tool-side signs
  Vec3 normal = Vec3::UnitZ();
  bool valid = false;
};

// Monge quadric fit in the frame of @p n; kappa = -II with II taken along the +n side.
VertexShape fitVertex(const Vec3& p, const Vec3& n, const std::vector<Vec3>& q,
                      const std::vector<int>& nbrs, double sigma) {
  VertexShape out;
  out.normal = n;
  if (nbrs.size() < 5) return out;
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  Eigen::MatrixXd a(static_cast<Eigen::Index>(nbrs.size()), 5);
  Eigen::VectorXd z(static_cast<Eigen::Index>(nbrs.size()));
  for (std::size_t r = 0; r < nbrs.size(); ++r) {
    const Vec3 d = q[static_cast<std::size_t>(nbrs[r])] - p;
    const double x = d.dot(t1), y = d.dot(t2);
    const double weight = sigma > 0.0 ? std::exp(-d.squaredNorm() / (sigma * sigma)) : 1.0;
    a.row(static_cast<Eigen::Index>(r)) << x * x, x * y, y * y, x, y;
    a.row(static_cast<Eigen::Index>(r)) *= weight;
    z[static_cast<Eigen::Index>(r)] = weight * d.dot(n);
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(z);
  if (!c.allFinite()) return out;
  const double fx = c[3], fy = c[4], w = std::sqrt(1.0 + fx * fx + fy * fy);
  Eigen::Matrix2d first, second;
  first << 1.0 + fx * fx, fx * fy, fx * fy, 1.0 + fy * fy;
  second << 2.0 * c[0], c[1], c[1], 2.0 * c[2];
  second /= w;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> eig(second, first);
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector2d x = eig.eigenvectors().col(i);
    const Vec3 t = (x[0] * (t1 + fx * n) + x[1] * (t2 + fy * n)).normalized();
    out.tensor -= eig.eigenvalues()[i] * t * t.transpose();
  }
  out.normal = (n - fx * t1 - fy * t2).normalized();
  out.valid = true;
  return out;
}

std::vector<VertexShape> vertexShapes(const ddf::DisplacementField& ddf,
                                      const VertexCurvatureParams& params) {
  const std::vector<Vec3> q = vertexPoints(ddf);
  std::vector<VertexShape> out(q.size());
  auto body = [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      if (ddf.topology().vertexFaces(v).empty()) continue;
      const Vec3& p = q[static_cast<std::size_t>(v)];
      const std::vector<int> firstRing = ringNeighbours(ddf, v, 1);
      double mean = 0.0;
      for (const int w : firstRing) mean += (q[static_cast<std::size_t>(w)] - p).norm();
      const double sigma = params.weightRadius * mean / static_cast<double>(firstRing.size());
      out[static_cast<std::size_t>(v)] =
          fitVertex(p, vertexNormal(ddf, q, v), q, ringNeighbours(ddf, v, params.rings), sigma);
    }
  };
  const tbb::blocked_range<int> all(0, ddf.vertexCount(), 256);
  params.parallel ? tbb::parallel_for(all, body) : body(all);
  return out;
}

// The blended tensor's two tangential principal curvatures at one raster point.
void storePoint(const Mat3& s, const Vec3& n, const VertexCurvatureParams& params,
                CurvatureField& out, std::size_t at) {
  const Vec3 b1 = n.unitOrthogonal(), b2 = n.cross(b1);
  const double s11 = b1.dot(s * b1), s12 = b1.dot(s * b2), s22 = b2.dot(s * b2);
  const double mean = 0.5 * (s11 + s22);
  const double radius = std::hypot(0.5 * (s11 - s22), s12);
  const double angle = 0.5 * std::atan2(2.0 * s12, s11 - s22);
  const double kMax = mean + radius, kMin = mean - radius;
  out.kMax[at] = static_cast<float>(kMax);
  out.kMin[at] = static_cast<float>(kMin);
  out.mean[at] = static_cast<float>(mean);
  out.gaussian[at] = static_cast<float>(kMax * kMin);
  out.dirMax[at] = std::cos(angle) * b1 + std::sin(angle) * b2;
  out.dirMin[at] = n.cross(out.dirMax[at]);
  const double scale = std::max(std::abs(kMax), std::abs(kMin));
  out.umbilic[at] = kMax - kMin <= params.umbilicTolerance * scale + params.flatCurvaturePerMm;
}

void blendFace(const ddf::DisplacementField& ddf, int face, const std::vector<VertexShape>& shapes,
               const VertexCurvatureParams& params, CurvatureField& out) {
  const auto& fv = ddf.faceVertices(face);
  const VertexShape* s[3];
  bool valid = true;
  for (int c = 0; c < 3; ++c) {
    s[c] = &shapes[static_cast<std::size_t>(fv[c])];
    valid = valid && s[c]->valid;
  }
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  const std::size_t base = static_cast<std::size_t>(face) * ddf.pointsPerFace();
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n - k; ++i) {
      const Vec3 mu = ddf.rasterBary(i, k);
      const Mat3 t = mu[0] * s[0]->tensor + mu[1] * s[1]->tensor + mu[2] * s[2]->tensor;
      const Vec3 nb = (mu[0] * s[0]->normal + mu[1] * s[1]->normal + mu[2] * s[2]->normal);
      const std::size_t at = base + raster.index(i, k);
      storePoint(t, nb.normalized(), params, out, at);
      if (!valid) out.umbilic[at] = 1;
    }
}

}  // namespace

bool hasFlatFaces(const ddf::DisplacementField& ddf, double relativeTolerance) {
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const Vec3 a = ddf.surfacePoint(f, n, 0), b = ddf.surfacePoint(f, 0, 0),
               c = ddf.surfacePoint(f, 0, n);
    const Vec3 normal = (b - a).cross(c - a);
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    if (!(normal.norm() > 0.0)) return false;
    const Vec3 unit = normal.normalized();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i)
        if (std::abs((ddf.surfacePoint(f, i, k) - a).dot(unit)) > relativeTolerance * longest)
          return false;
  }
  return ddf.faceCount() > 0;
}

CurvatureField computeVertexCurvature(const ddf::DisplacementField& ddf,
                                      const VertexCurvatureParams& params) {
  if (ddf.faceCount() == 0) throw InvalidInput("computeVertexCurvature: the DDF has no faces");
  if (params.rings < 1)
    throw InvalidInput("computeVertexCurvature: rings must be >= 1, got " +
                       std::to_string(params.rings));
  if (!(params.weightRadius >= 0.0))
    throw InvalidInput("computeVertexCurvature: weightRadius must be >= 0");
  const std::vector<VertexShape> shapes = vertexShapes(ddf, params);
  reportProgress(params.progress, 0.3);
  const std::size_t size = ddf.allHeights().size();
  CurvatureField out;
  out.kMax.resize(size), out.kMin.resize(size), out.mean.resize(size);
  out.gaussian.resize(size), out.dirMax.resize(size), out.dirMin.resize(size);
  out.umbilic.resize(size);
  out.step = 1;
  out.method = CurvatureMethod::VertexQuadricFit;
  auto body = [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) blendFace(ddf, f, shapes, params, out);
  };
  const tbb::blocked_range<int> all(0, ddf.faceCount(), 64);
  params.parallel ? tbb::parallel_for(all, body) : body(all);
  reportProgress(params.progress, 1.0);
  return out;
}

}  // namespace ddfcam::planning
