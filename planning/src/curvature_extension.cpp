// SPDX-License-Identifier: MIT
// ddfcam: ghost heights across support edges so that curvature stencils stay symmetric at seams.
#include "curvature_extension.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace ddfcam::planning::detail {

namespace {

using ddf::Vec3;

// Nodes (p, q), p + q <= 3, of the cubic sub-triangle; the same list enumerates the monomials
// s^p t^q, so the Vandermonde matrix is square.
constexpr std::array<std::array<int, 2>, 10> kCubic = {
    {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {3, 0}, {2, 1}, {1, 2}, {0, 3}}};

using Mat10 = Eigen::Matrix<double, 10, 10>;
using Vec10 = Eigen::Matrix<double, 10, 1>;

const Mat10& inverseVandermonde() {
  static const Mat10 inverse = [] {
    Mat10 v;
    for (int r = 0; r < 10; ++r)
      for (int c = 0; c < 10; ++c)
        v(r, c) = std::pow(kCubic[r][0], kCubic[c][0]) * std::pow(kCubic[r][1], kCubic[c][1]);
    return Mat10(v.fullPivLu().inverse());
  }();
  return inverse;
}

// The cubic interpolant of one face's heights over the 10 raster points (j0 + p, k0 + q).
class CubicCell {
 public:
  void fit(std::span<const float> heights, const ddf::Raster& raster, int j0, int k0) {
    if (j0 == j0_ && k0 == k0_) return;
    j0_ = j0;
    k0_ = k0;
    const int n = raster.steps();
    Vec10 values;
    for (int r = 0; r < 10; ++r) {
      const int j = j0 + kCubic[r][0];
      const int k = k0 + kCubic[r][1];
      values[r] = heights[raster.index(n - j - k, k)];
    }
    coeffs_ = inverseVandermonde() * values;
  }
  /// Value at continuous lattice coordinates (a, b) = (j, k), with its partial derivatives.
  double eval(double a, double b, double& da, double& db) const {
    const double s = a - j0_, t = b - k0_;
    const std::array<double, 4> sp = {1.0, s, s * s, s * s * s};
    const std::array<double, 4> tp = {1.0, t, t * t, t * t * t};
    double value = 0.0;
    da = db = 0.0;
    for (int r = 0; r < 10; ++r) {
      const int p = kCubic[r][0], q = kCubic[r][1];
      value += coeffs_[r] * sp[p] * tp[q];
      if (p > 0) da += coeffs_[r] * p * sp[p - 1] * tp[q];
      if (q > 0) db += coeffs_[r] * q * sp[p] * tp[q - 1];
    }
    return value;
  }

 private:
  int j0_ = -1;
  int k0_ = -1;
  Vec10 coeffs_ = Vec10::Zero();
};

// The sub-triangle whose cubic serves continuous lattice point (a, b): centred on it where
// possible, shifted inwards at the face boundary (extrapolation beyond it). The nudge keeps
// the choice stable for feet that fall on a lattice node up to rounding, which would otherwise
// flip between cells with the part's scale.
std::array<int, 2> cellFor(double a, double b, int n) {
  const int j0 = std::clamp(static_cast<int>(std::floor(a + 1e-7)) - 1, 0, n - 3);
  const int k0 = std::clamp(static_cast<int>(std::floor(b + 1e-7)) - 1, 0, n - 3 - j0);
  return {j0, k0};
}

struct FaceFrame {
  std::array<Vec3, 3> p;
  std::array<Vec3, 3> v;
};

FaceFrame frameOf(const ddf::DisplacementField& ddf, int face) {
  FaceFrame fr;
  const auto& vs = ddf.faceVertices(face);
  for (int a = 0; a < 3; ++a) {
    fr.p[a] = ddf.position(vs[a]);
    fr.v[a] = ddf.vector(vs[a]);
  }
  return fr;
}

struct Meeting {
  double t = 0.0;
  double minBary = -1e300;  // smallest barycentric coordinate of the foot on the other face
};

// Newton's method on g'(mu) + H(mu) v'(mu) = G + t V over (a, b, t) of face @p other.
Meeting meetFace(const ddf::DisplacementField& ddf, int other, const Vec3& G, const Vec3& V,
                 double t0) {
  const FaceFrame fr = frameOf(ddf, other);
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  const auto heights = ddf.heights(other);
  const Vec3 e1 = (fr.p[1] - fr.p[0]) / n, e2 = (fr.p[2] - fr.p[0]) / n;
  const Vec3 w1 = (fr.v[1] - fr.v[0]) / n, w2 = (fr.v[2] - fr.v[0]) / n;
  // Start from the orthogonal foot of the guess on the support plane.
  const Vec3 r0 = G + t0 * V - fr.p[0];
  Eigen::Matrix2d gram;
  gram << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
  Eigen::Vector2d ab = gram.ldlt().solve(Eigen::Vector2d(e1.dot(r0), e2.dot(r0)));
  double t = t0;
  CubicCell cell;
  for (int it = 0; it < 10; ++it) {
    const auto c = cellFor(ab[0], ab[1], n);
    cell.fit(heights, raster, c[0], c[1]);
    double ha = 0.0, hb = 0.0;
    const double h = cell.eval(ab[0], ab[1], ha, hb);
    const Vec3 vb = fr.v[0] + ab[0] * w1 + ab[1] * w2;
    const Vec3 res = fr.p[0] + ab[0] * e1 + ab[1] * e2 + h * vb - G - t * V;
    Eigen::Matrix3d jac;
    jac.col(0) = e1 + h * w1 + ha * vb;
    jac.col(1) = e2 + h * w2 + hb * vb;
    jac.col(2) = -V;
    const Eigen::Vector3d step = jac.partialPivLu().solve(-res);
    if (!step.allFinite()) return {};
    ab += step.head<2>();
    t += step[2];
    if (ab.minCoeff() < -n || ab.sum() > 2.0 * n) return {};  // diverged far off the face
    if (step.head<2>().cwiseAbs().sum() < 1e-11 * n && std::abs(step[2]) < 1e-13) break;
  }
  return {t, std::min({1.0 - (ab[0] + ab[1]) / n, ab[0] / n, ab[1] / n})};
}

// Faces adjacent to @p face: across local edges 0..2 (-1 on a boundary), then all other faces
// sharing a vertex.
struct Neighbourhood {
  std::array<int, 3> acrossEdge = {-1, -1, -1};
  std::vector<int> aroundVertices;
};

Neighbourhood neighbourhoodOf(const ddf::DisplacementField& ddf, int face) {
  const auto& topo = ddf.topology();
  Neighbourhood nb;
  for (int e = 0; e < 3; ++e) {
    const auto& sides = topo.edgeFaces(topo.faceEdge(face, e));
    nb.acrossEdge[e] = sides[0] == face ? sides[1] : sides[0];
  }
  for (int v : topo.faceVertices(face))
    for (int f : topo.vertexFaces(v))
      if (f != face && std::find(nb.aroundVertices.begin(), nb.aroundVertices.end(), f) ==
                           nb.aroundVertices.end())
        nb.aroundVertices.push_back(f);
  return nb;
}

// Height of the ghost lattice point (i, j, k) (some coordinate negative) of @p face.
double ghostHeight(const ddf::DisplacementField& ddf, int face, const FaceFrame& fr,
                   const Neighbourhood& nb, CubicCell& own, int i, int j, int k) {
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  const auto c = cellFor(j, k, n);
  own.fit(ddf.heights(face), raster, c[0], c[1]);
  double da = 0.0, db = 0.0;
  const double extrapolated = own.eval(j, k, da, db);
  const Vec3 bary = Vec3(i, j, k) / n;
  const Vec3 G = bary[0] * fr.p[0] + bary[1] * fr.p[1] + bary[2] * fr.p[2];
  const Vec3 V = bary[0] * fr.v[0] + bary[1] * fr.v[1] + bary[2] * fr.v[2];
  // Local edge e is opposite the coordinate that vanishes on it: k (e = 0), i (1), j (2).
  const std::array<int, 3> edgeCoord = {k, i, j};
  const int first =
      static_cast<int>(std::min_element(edgeCoord.begin(), edgeCoord.end()) - edgeCoord.begin());
  Meeting best;
  auto tryFace = [&](int other) {
    if (other < 0) return false;
    const Meeting mt = meetFace(ddf, other, G, V, extrapolated);
    if (mt.minBary > best.minBary) best = mt;
    return best.minBary >= -1e-9;
  };
  if (!tryFace(nb.acrossEdge[first])) {
    for (int other : nb.aroundVertices)
      if (other != nb.acrossEdge[first] && tryFace(other)) break;
  }
  // Half a raster step outside a face is still a close cubic extrapolation of that face.
  return best.minBary >= -0.5 / n ? best.t : extrapolated;
}

}  // namespace

void fillExtendedRaster(const ddf::DisplacementField& ddf, int face, int d, ExtendedRaster& out) {
  const ddf::Raster& raster = ddf.raster();
  out.n = raster.steps();
  out.d = d;
  out.w = out.n + 2 * d + 1;
  out.h.assign(static_cast<std::size_t>(out.w) * out.w, 0.0);
  const auto heights = ddf.heights(face);
  const FaceFrame fr = frameOf(ddf, face);
  const Neighbourhood nb = neighbourhoodOf(ddf, face);
  CubicCell own;
  for (int j = -d; j <= out.n + d; ++j) {
    for (int k = -d; k <= out.n + d; ++k) {
      const int i = out.n - j - k;
      if (i < -d) break;
      if (i >= 0 && j >= 0 && k >= 0)
        out.at(j, k) = heights[raster.index(i, k)];
      else
        out.at(j, k) = ghostHeight(ddf, face, fr, nb, own, i, j, k);
    }
  }
}

}  // namespace ddfcam::planning::detail
