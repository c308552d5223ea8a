// SPDX-License-Identifier: MIT
// ddfcam: curvature of flat-faced DDFs from quadric fits at the support vertices.
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/vertex_curvature.h>

#include "curvature_tensor.h"
#include "curvature_wedges.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <optional>
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

struct VertexShape {
  Mat3 tensor = Mat3::Zero();  // sum kappa_i t_i t_i^T, tool-side signs
  Vec3 normal = Vec3::UnitZ();
  bool valid = false;
};

// The corners of @p faces other than v, without repeats.
std::vector<int> neighbourVertices(const ddf::DisplacementField& ddf, const std::vector<int>& faces,
                                   int v) {
  std::vector<int> out;
  for (const int f : faces)
    for (const int u : ddf.faceVertices(f))
      if (u != v) out.push_back(u);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Area-weighted normal of the represented triangles of @p faces, on the +v side of vertex v.
Vec3 wedgeNormal(const ddf::DisplacementField& ddf, const std::vector<Vec3>& q,
                 const std::vector<int>& faces, int v) {
  Vec3 sum = Vec3::Zero();
  for (const int f : faces) {
    const auto& fv = ddf.faceVertices(f);
    sum += (q[fv[1]] - q[fv[0]]).cross(q[fv[2]] - q[fv[0]]);
  }
  if (sum.dot(ddf.vector(v)) < 0.0) sum = -sum;
  return sum.norm() > 0.0 ? Vec3(sum.normalized()) : Vec3(ddf.vector(v).normalized());
}

using Vec5 = Eigen::Matrix<double, 5, 1>;
using Mat5 = Eigen::Matrix<double, 5, 5>;

// Weighted normal equations of the Monge quadric z = a x^2 + b x y + c y^2 + d x + e y in a
// frame (t1, t2, n) at p, x and y divided by the RMS extents sx, sy of the vertex samples along
// their principal axes t1, t2: a strip vertex's neighbours spread 60x further along the strip
// than across it, and unscaled the well-determined cross curvature would look undetermined.
struct QuadricSystem {
  Vec3 p, t1, t2, n;
  double sx = 1.0, sy = 1.0, sigma = 0.0;
  Mat5 normal = Mat5::Zero();
  Vec5 rhs = Vec5::Zero();

  double weightOf(const Vec3& d) const {
    return sigma > 0.0 ? std::exp(-d.squaredNorm() / (sigma * sigma)) : 1.0;
  }
  void add(const Vec3& point, double weight) {
    const Vec3 d = point - p;
    weight *= weightOf(d);
    const double x = d.dot(t1) / sx, y = d.dot(t2) / sy;
    Vec5 r;
    r << x * x, x * y, y * y, x, y;
    normal.noalias() += weight * weight * r * r.transpose();
    rhs += weight * weight * r * d.dot(n);
  }
  // Principal axes and extents of the weighted tangential spread of @p points.
  void alignTo(const std::vector<Vec3>& points) {
    const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
    Eigen::Matrix2d spread = Eigen::Matrix2d::Zero();
    double total = 0.0;
    for (const Vec3& point : points) {
      const Vec3 d = point - p;
      const double weight = weightOf(d) * weightOf(d);
      const Eigen::Vector2d x(d.dot(u), d.dot(w));
      spread += weight * x * x.transpose(), total += weight;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(spread / std::max(total, 1e-300));
    const Eigen::Vector2d major = eig.eigenvectors().col(1);
    t1 = (major[0] * u + major[1] * w).normalized();
    t2 = n.cross(t1);
    sx = std::sqrt(std::max(eig.eigenvalues()[1], 0.0));
    sy = std::max(std::sqrt(std::max(eig.eigenvalues()[0], 0.0)), 1e-3 * sx);
    if (!(sx > 0.0)) sx = sy = 1.0;
  }
  // Coefficients in mm from those of the scaled coordinates.
  Vec5 unscale(const Vec5& c) const {
    Vec5 out;
    out << c[0] / (sx * sx), c[1] / (sx * sy), c[2] / (sy * sy), c[3] / sx, c[4] / sy;
    return out;
  }
};

// Least squares of the vertex samples @p a; the directions of coefficient space that they
// leave undetermined (normal-matrix eigenvalues below minRatio^2 of the largest: a strip of
// triangles spanning a cylinder has its vertices on two lines only, so a y and a y^2 term are
// indistinguishable) are taken from the samples @p b of the represented faces, which the
// tessellation keeps within its chord deflection of the surface. Without the split, b's
// points inside flat faces would bias the well-sampled curvatures by the faces' sagitta.
std::optional<Vec5> solveLexicographic(const QuadricSystem& a, const QuadricSystem& b,
                                       double minRatio) {
  const Eigen::SelfAdjointEigenSolver<Mat5> ea(a.normal);
  const double largest = ea.eigenvalues()[4];
  if (!(largest > 0.0)) return std::nullopt;
  Vec5 c = Vec5::Zero();
  int undetermined = 0;
  while (undetermined < 5 && ea.eigenvalues()[undetermined] < minRatio * minRatio * largest)
    ++undetermined;
  for (int i = undetermined; i < 5; ++i)
    c += ea.eigenvectors().col(i) * (ea.eigenvectors().col(i).dot(a.rhs) / ea.eigenvalues()[i]);
  if (undetermined == 0) return c;
  const Eigen::MatrixXd null = ea.eigenvectors().leftCols(undetermined);
  const Eigen::MatrixXd m = null.transpose() * b.normal * null;
  // b spreads further than a (face samples along the whole strip), so its own scale decides
  // only whether it pins the undetermined directions at all.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> em(m);
  const double bLargest = Eigen::SelfAdjointEigenSolver<Mat5>(b.normal).eigenvalues()[4];
  if (!(bLargest > 0.0) || !(em.eigenvalues()[0] > 1e-12 * bLargest)) return std::nullopt;
  const Eigen::VectorXd y = m.ldlt().solve(null.transpose() * (b.rhs - b.normal * c));
  return c + null * y;
}

// Shape of the quadric with coefficients @p c (unscaled) in the frame of @p s; kappa = -II.
VertexShape quadricShape(const QuadricSystem& s, const Vec5& c) {
  VertexShape out;
  const double fx = c[3], fy = c[4], w = std::sqrt(1.0 + fx * fx + fy * fy);
  Eigen::Matrix2d first, second;
  first << 1.0 + fx * fx, fx * fy, fx * fy, 1.0 + fy * fy;
  second << 2.0 * c[0], c[1], c[1], 2.0 * c[2];
  second /= w;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> eig(second, first);
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector2d x = eig.eigenvectors().col(i);
    const Vec3 t = (x[0] * (s.t1 + fx * s.n) + x[1] * (s.t2 + fy * s.n)).normalized();
    out.tensor -= eig.eigenvalues()[i] * t * t.transpose();
  }
  out.normal = (s.n - fx * s.t1 - fy * s.t2).normalized();
  out.valid = out.tensor.allFinite() && out.normal.allFinite();
  return out;
}

// Sub-lattice (at most 4 steps per edge) of face points, corners excluded, with the share of
// the face's represented area each one stands for.
void addFaceSamples(const ddf::DisplacementField& ddf, int f, const std::vector<Vec3>& q,
                    QuadricSystem& b) {
  const int n = ddf.raster().steps(), p = std::min(n, 4);
  const auto& fv = ddf.faceVertices(f);
  const double area = 0.5 * (q[fv[1]] - q[fv[0]]).cross(q[fv[2]] - q[fv[0]]).norm();
  const double weight = std::sqrt(area / ((p + 1) * (p + 2) / 2 - 3));
  for (int s = 0; s <= p; ++s)
    for (int t = 0; t <= p - s; ++t) {
      if ((s == p && t == 0) || (s == 0 && t == 0) || (s == 0 && t == p)) continue;
      b.add(ddf.surfacePoint(f, (s * n + p / 2) / p, (t * n + p / 2) / p), weight);
    }
}

// Fit at wedge w: vertex samples of its neighbourhood, completed by face samples.
VertexShape fitWedge(const ddf::DisplacementField& ddf, const std::vector<Vec3>& q,
                     const detail::CurvatureWedges& wedges, int w,
                     const VertexCurvatureParams& params) {
  const int v = wedges.vertex[static_cast<std::size_t>(w)];
  const std::vector<int>& own = wedges.faces[static_cast<std::size_t>(w)];
  QuadricSystem a;
  a.p = q[static_cast<std::size_t>(v)];
  a.n = wedgeNormal(ddf, q, own, v);
  std::vector<int> firstRing = neighbourVertices(ddf, own, v);
  double mean = 0.0;
  double longest = 0.0;
  for (const int u : firstRing) {
    const double d = (q[static_cast<std::size_t>(u)] - a.p).norm();
    mean += d, longest = std::max(longest, d);
  }
  mean /= std::max<double>(1.0, static_cast<double>(firstRing.size()));
  a.sigma = params.weightRadius * mean;
  VertexShape out;
  out.normal = a.n;
  // A wedge at the corner of a CAD face may hold one or two triangles: widen its reach.
  std::vector<int> faces, nbrs;
  for (int rings = params.rings; rings <= params.rings + 2 && nbrs.size() < 5; ++rings) {
    faces = detail::wedgeNeighbourhood(ddf, wedges, w, rings);
    nbrs = neighbourVertices(ddf, faces, v);
  }
  if (nbrs.size() < 5) return out;
  std::vector<Vec3> points;
  for (const int u : nbrs) points.push_back(q[static_cast<std::size_t>(u)]);
  a.alignTo(points);
  QuadricSystem b = a;
  // The face samples must reach the far end of a strip (the first ring's longest edge): the
  // mean first-ring distance of a strip vertex can be that of its short edges only.
  b.sigma = params.weightRadius * longest;
  for (const Vec3& point : points) a.add(point, 1.0);
  for (const int f : faces) addFaceSamples(ddf, f, q, b);
  const std::optional<Vec5> c = solveLexicographic(a, b, params.minSingularRatio);
  if (!c || !c->allFinite()) return out;
  return quadricShape(a, a.unscale(*c));
}

std::vector<VertexShape> wedgeShapes(const ddf::DisplacementField& ddf,
                                     const detail::CurvatureWedges& wedges,
                                     const std::vector<Vec3>& q,
                                     const VertexCurvatureParams& params) {
  std::vector<VertexShape> out(static_cast<std::size_t>(wedges.count()));
  auto body = [&](const tbb::blocked_range<int>& r) {
    for (int w = r.begin(); w < r.end(); ++w)
      out[static_cast<std::size_t>(w)] = fitWedge(ddf, q, wedges, w, params);
  };
  const tbb::blocked_range<int> all(0, wedges.count(), 256);
  params.parallel ? tbb::parallel_for(all, body) : body(all);
  return out;
}

void storePoint(const Mat3& s, const Vec3& n, const VertexCurvatureParams& params,
                CurvatureField& out, std::size_t at) {
  detail::storeCurvatureTensor(s, n, params.umbilicTolerance, params.flatCurvaturePerMm, out, at);
}

// Corners whose fit failed drop out of the blend (their share goes to the others), so that
// one bad corner does not pull a face's curvature towards 0; their points are flagged.
void blendFace(const ddf::DisplacementField& ddf, int face, const detail::CurvatureWedges& wedges,
               const std::vector<VertexShape>& shapes, const VertexCurvatureParams& params,
               CurvatureField& out) {
  const auto& fv = ddf.faceVertices(face);
  const VertexShape* s[3];
  Vec3 use;
  for (int c = 0; c < 3; ++c) {
    s[c] = &shapes[static_cast<std::size_t>(wedges.at(ddf, fv[c], face))];
    use[c] = s[c]->valid ? 1.0 : 0.0;
  }
  const bool valid = use.sum() == 3.0;
  if (use.sum() == 0.0) use.setOnes();
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  const std::size_t base = static_cast<std::size_t>(face) * ddf.pointsPerFace();
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n - k; ++i) {
      Vec3 mu = ddf.rasterBary(i, k).cwiseProduct(use);
      mu = mu.sum() > 0.0 ? Vec3(mu / mu.sum()) : Vec3(use / use.sum());
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
  if (!params.faceLabels.empty() &&
      params.faceLabels.size() != static_cast<std::size_t>(ddf.faceCount()))
    throw InvalidInput("computeVertexCurvature: " + std::to_string(params.faceLabels.size()) +
                       " face labels for " + std::to_string(ddf.faceCount()) + " faces");
  if (!(params.weightRadius >= 0.0))
    throw InvalidInput("computeVertexCurvature: weightRadius must be >= 0");
  const std::vector<Vec3> q = vertexPoints(ddf);
  const detail::CurvatureWedges wedges =
      detail::curvatureWedges(ddf, q, params.faceLabels, std::cos(params.creaseAngleRad));
  const std::vector<VertexShape> shapes = wedgeShapes(ddf, wedges, q, params);
  reportProgress(params.progress, 0.3);
  const std::size_t size = ddf.allHeights().size();
  CurvatureField out;
  detail::resizeCurvatureField(out, size);
  out.step = 1;
  out.method = CurvatureMethod::VertexQuadricFit;
  auto body = [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) blendFace(ddf, f, wedges, shapes, params, out);
  };
  const tbb::blocked_range<int> all(0, ddf.faceCount(), 64);
  params.parallel ? tbb::parallel_for(all, body) : body(all);
  reportProgress(params.progress, 1.0);
  return out;
}

}  // namespace ddfcam::planning
