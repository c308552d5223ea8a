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

// Interpolating polynomial of total degree P over the raster sub-triangle (j0 + p, k0 + q),
// p + q <= P. The node list doubles as the list of monomials s^p t^q (q-major), so the Vandermonde
// matrix is square; coordinates are taken relative to the sub-triangle's centroid, which keeps
// that matrix well conditioned.
template <int P>
class PolyCell {
 public:
  static constexpr int kNodes = (P + 1) * (P + 2) / 2;
  static constexpr double kCentre = P / 3.0;

  void fit(std::span<const float> heights, const ddf::Raster& raster, int j0, int k0) {
    if (j0 == j0_ && k0 == k0_) return;
    j0_ = j0;
    k0_ = k0;
    const int n = raster.steps();
    Vec values;
    for (int r = 0; r < kNodes; ++r) {
      const int j = j0 + nodes()[r][0];
      const int k = k0 + nodes()[r][1];
      values[r] = heights[raster.index(n - j - k, k)];
    }
    coeffs_.noalias() = inverse() * values;
  }

  /// Value at continuous lattice coordinates (a, b) = (j, k), with its partial derivatives:
  /// nested Horner schemes in s within each power of t (the nodes are listed t-power-major).
  double eval(double a, double b, double& da, double& db) const {
    const double s = a - j0_ - kCentre, t = b - k0_ - kCentre;
    double value = 0.0;
    da = db = 0.0;
    int end = kNodes;
    for (int q = P; q >= 0; --q) {
      const int begin = end - (P - q + 1);
      double pv = 0.0, pd = 0.0;
      for (int r = end - 1; r >= begin; --r) {
        pd = pd * s + pv;
        pv = pv * s + coeffs_[r];
      }
      db = db * t + value;
      value = value * t + pv;
      da = da * t + pd;
      end = begin;
    }
    return value;
  }

  /// The sub-triangle serving continuous lattice point (a, b): centred on it where possible,
  /// shifted inwards at the face boundary. The half-integer offset keeps lattice nodes away
  /// from the rounding boundary, so the choice does not flip with the part's scale.
  static std::array<int, 2> cellFor(double a, double b, int n) {
    const int j0 = std::clamp(static_cast<int>(std::floor(a - kCentre + 0.5)), 0, n - P);
    const int k0 = std::clamp(static_cast<int>(std::floor(b - kCentre + 0.5)), 0, n - P - j0);
    return {j0, k0};
  }

 private:
  using Mat = Eigen::Matrix<double, kNodes, kNodes>;
  using Vec = Eigen::Matrix<double, kNodes, 1>;

  static const std::array<std::array<int, 2>, kNodes>& nodes() {
    static const auto list = [] {
      std::array<std::array<int, 2>, kNodes> out{};
      int r = 0;
      for (int q = 0; q <= P; ++q)
        for (int p = 0; p <= P - q; ++p) out[r++] = {p, q};
      return out;
    }();
    return list;
  }

  static const Mat& inverse() {
    static const Mat inv = [] {
      Mat v;
      for (int r = 0; r < kNodes; ++r)
        for (int c = 0; c < kNodes; ++c)
          v(r, c) = std::pow(nodes()[r][0] - kCentre, nodes()[c][0]) *
                    std::pow(nodes()[r][1] - kCentre, nodes()[c][1]);
      return Mat(v.fullPivLu().inverse());
    }();
    return inv;
  }

  int j0_ = -1;
  int k0_ = -1;
  Vec coeffs_ = Vec::Zero();
};

// The open-boundary fallback and the Newton start extrapolate a face's own heights with a
// cubic: higher degrees amplify the height rounding too much a band width outside the data.
using OwnCell = PolyCell<3>;

// A neighbouring face in lattice-step units: g = p0 + a e1 + b e2, vector = v0 + a w1 + b w2.
template <int P>
struct Neighbour {
  int face = -1;
  Vec3 p0, e1, e2, v0, w1, w2;
  Eigen::Matrix2d gramInverse;
  std::span<const float> heights;
  PolyCell<P> cell;

  /// Smallest barycentric coordinate of the orthogonal foot of @p x on the support plane.
  double planarDepth(const Vec3& x, int n) const {
    const Vec3 r = x - p0;
    const Eigen::Vector2d ab = gramInverse * Eigen::Vector2d(e1.dot(r), e2.dot(r));
    return std::min({1.0 - (ab[0] + ab[1]) / n, ab[0] / n, ab[1] / n});
  }
};

template <int P>
Neighbour<P> neighbourOf(const ddf::DisplacementField& ddf, int face) {
  Neighbour<P> nb;
  nb.face = face;
  const auto& vs = ddf.faceVertices(face);
  const int n = ddf.raster().steps();
  nb.p0 = ddf.position(vs[0]);
  nb.v0 = ddf.vector(vs[0]);
  nb.e1 = (ddf.position(vs[1]) - nb.p0) / n;
  nb.e2 = (ddf.position(vs[2]) - nb.p0) / n;
  nb.w1 = (ddf.vector(vs[1]) - nb.v0) / n;
  nb.w2 = (ddf.vector(vs[2]) - nb.v0) / n;
  Eigen::Matrix2d gram;
  gram << nb.e1.dot(nb.e1), nb.e1.dot(nb.e2), nb.e1.dot(nb.e2), nb.e2.dot(nb.e2);
  nb.gramInverse = gram.inverse();
  nb.heights = ddf.heights(face);
  return nb;
}

struct Meeting {
  double t = 0.0;
  double minBary = -1e300;  // smallest barycentric coordinate of the foot on the other face
};

// Newton's method on g'(a, b) + H(a, b) v'(a, b) = G + t V over (a, b, t) of face @p nb.
template <int P>
Meeting meetFace(Neighbour<P>& nb, const ddf::Raster& raster, const Vec3& G, const Vec3& V,
                 double t0) {
  const int n = raster.steps();
  // Start from the foot of the guess point along the vector at its orthogonal foot (Cramer's
  // rule on [e1 e2 v]), which lands within a small fraction of a raster step of the solution.
  const Vec3 r0 = G + t0 * V - nb.p0;
  Eigen::Vector2d ab = nb.gramInverse * Eigen::Vector2d(nb.e1.dot(r0), nb.e2.dot(r0));
  {
    const Vec3 v = nb.v0 + ab[0] * nb.w1 + ab[1] * nb.w2;
    const Vec3 e2v = nb.e2.cross(v);
    const double det = nb.e1.dot(e2v);
    if (std::abs(det) > 0.0) ab = Eigen::Vector2d(r0.dot(e2v), nb.e1.dot(r0.cross(v))) / det;
  }
  double t = t0;
  for (int it = 0; it < 12; ++it) {
    const auto c = PolyCell<P>::cellFor(ab[0], ab[1], n);
    nb.cell.fit(nb.heights, raster, c[0], c[1]);
    double ha = 0.0, hb = 0.0;
    const double h = nb.cell.eval(ab[0], ab[1], ha, hb);
    const Vec3 vb = nb.v0 + ab[0] * nb.w1 + ab[1] * nb.w2;
    const Vec3 res = nb.p0 + ab[0] * nb.e1 + ab[1] * nb.e2 + h * vb - G - t * V;
    // Cramer's rule on the 3 x 3 Jacobian [q_a q_b -V]: cheaper than a pivoting LU and as
    // accurate for this well-conditioned system (the stubble line crosses the surface).
    const Vec3 ca = nb.e1 + h * nb.w1 + ha * vb;
    const Vec3 cb = nb.e2 + h * nb.w2 + hb * vb;
    const Vec3 cbV = cb.cross(V);
    const double det = -ca.dot(cbV);
    const Eigen::Vector3d step(res.dot(cbV) / det, ca.dot(res.cross(V)) / det,
                               -ca.dot(cb.cross(res)) / det);
    if (!step.allFinite()) return {};
    ab += step.head<2>();
    t += step[2];
    if (ab.minCoeff() < -n || ab.sum() > 2.0 * n) return {};  // diverged far off the face
    // Quadratic convergence with a residual that is nearly linear over a raster step: after a
    // step this small the remaining error is below 1e-12.
    if (step.head<2>().cwiseAbs().sum() < 1e-4 && std::abs(step[2]) < 1e-6) break;
  }
  return {t, std::min({1.0 - (ab[0] + ab[1]) / n, ab[0] / n, ab[1] / n})};
}

// Faces around @p face: the neighbours across local edges 0..2 first (index -1 in
// acrossEdge on a boundary), then all other faces sharing a vertex.
template <int P>
struct Neighbourhood {
  std::array<int, 3> acrossEdge = {-1, -1, -1};
  std::vector<Neighbour<P>> faces;
  std::vector<std::pair<double, int>> order;  // scratch: (-planar depth, index into faces)
  int lastMet = -1;                           // index of the face the last ghost met
};

template <int P>
void neighbourhoodOf(const ddf::DisplacementField& ddf, int face, Neighbourhood<P>& nb) {
  const auto& topo = ddf.topology();
  nb.faces.clear();
  nb.lastMet = -1;
  auto add = [&](int f) {
    for (std::size_t a = 0; a < nb.faces.size(); ++a)
      if (nb.faces[a].face == f) return static_cast<int>(a);
    nb.faces.push_back(neighbourOf<P>(ddf, f));
    return static_cast<int>(nb.faces.size()) - 1;
  };
  for (int e = 0; e < 3; ++e) {
    const auto& sides = topo.edgeFaces(topo.faceEdge(face, e));
    const int other = sides[0] == face ? sides[1] : sides[0];
    nb.acrossEdge[e] = other < 0 ? -1 : add(other);
  }
  for (int v : topo.faceVertices(face))
    for (int f : topo.vertexFaces(v))
      if (f != face) add(f);
}

// Where the stubble line G + t V meets the surface over the faces of @p nb: the face that
// the previous ghost met first (consecutive ghosts mostly share it), then Newton on the faces
// in the order of how deep inside them the guess projects onto their support planes (vectors
// oblique to a coarse support shift the true foot by many raster steps, so only faces missed
// by half their size are skipped). Returns the best meeting found.
template <int P>
Meeting meetNeighbourhood(Neighbourhood<P>& nb, const ddf::Raster& raster, const Vec3& G,
                          const Vec3& V, double t0) {
  Meeting best;
  if (nb.lastMet >= 0) {
    best = meetFace(nb.faces[nb.lastMet], raster, G, V, t0);
    if (best.minBary >= -1e-9) return best;
  }
  const Vec3 guess = G + t0 * V;
  nb.order.clear();
  for (int a = 0; a < static_cast<int>(nb.faces.size()); ++a) {
    const double depth = nb.faces[a].planarDepth(guess, raster.steps());
    if (depth > -0.5 && a != nb.lastMet) nb.order.emplace_back(-depth, a);
  }
  std::sort(nb.order.begin(), nb.order.end());
  for (const auto& [negDepth, a] : nb.order) {
    const Meeting mt = meetFace(nb.faces[a], raster, G, V, t0);
    if (mt.minBary > best.minBary) best = mt;
    if (mt.minBary >= -1e-9) {
      nb.lastMet = a;
      break;
    }
  }
  return best;
}

// Height of the ghost lattice point (i, j, k) (some coordinate negative) of @p face, whose
// corner positions and vectors are @p p and @p v.
template <int P>
double ghostHeight(const ddf::DisplacementField& ddf, int face, const std::array<Vec3, 3>& p,
                   const std::array<Vec3, 3>& v, Neighbourhood<P>& nb, OwnCell& own, int i, int j,
                   int k) {
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  const auto c = OwnCell::cellFor(j, k, n);
  own.fit(ddf.heights(face), raster, c[0], c[1]);
  double da = 0.0, db = 0.0;
  const double extrapolated = own.eval(j, k, da, db);
  // Local edge e is opposite the coordinate that vanishes on it: k (e = 0), i (1), j (2).
  const std::array<int, 3> edgeCoord = {k, i, j};
  const int first =
      nb.acrossEdge[std::min_element(edgeCoord.begin(), edgeCoord.end()) - edgeCoord.begin()];
  // Beyond an open boundary edge (and not in a corner wedge) no face can be met.
  const bool corner = (i < 0) + (j < 0) + (k < 0) > 1;
  if (first < 0 && !corner) return extrapolated;
  const Vec3 bary = Vec3(i, j, k) / n;
  const Vec3 G = bary[0] * p[0] + bary[1] * p[1] + bary[2] * p[2];
  const Vec3 V = bary[0] * v[0] + bary[1] * v[1] + bary[2] * v[2];
  const Meeting best = meetNeighbourhood(nb, raster, G, V, extrapolated);
  // Half a raster step outside a face is still a close polynomial extrapolation of that face.
  return best.minBary >= -0.5 / n ? best.t : extrapolated;
}

template <int P>
void fillWithDegree(const ddf::DisplacementField& ddf, int face, int band, ExtendedRaster& out) {
  const ddf::Raster& raster = ddf.raster();
  const auto heights = ddf.heights(face);
  const auto& vs = ddf.faceVertices(face);
  std::array<Vec3, 3> p, v;
  for (int a = 0; a < 3; ++a) {
    p[a] = ddf.position(vs[a]);
    v[a] = ddf.vector(vs[a]);
  }
  thread_local Neighbourhood<P> nb;
  neighbourhoodOf(ddf, face, nb);
  OwnCell own;
  auto ghost = [&](int j, int k) {
    out.at(j, k) = ghostHeight(ddf, face, p, v, nb, own, out.n - j - k, j, k);
  };
  // Consecutive ghosts should step away from their edge rather than along it, so that their
  // feet share the neighbour's interpolation cell: the j < 0 strip is walked column-wise.
  for (int k = -band; k <= out.n + band; ++k)
    for (int j = -band; j < 0; ++j) ghost(j, k);
  for (int j = 0; j <= out.n + band; ++j) {
    for (int k = -band; k <= out.n + band; ++k) {
      const int i = out.n - j - k;
      if (i < -band) break;
      if (i >= 0 && k >= 0)
        out.at(j, k) = heights[raster.index(i, k)];
      else
        ghost(j, k);
    }
  }
}

}  // namespace

void fillExtendedRaster(const ddf::DisplacementField& ddf, int face, int band,
                        ExtendedRaster& out) {
  out.n = ddf.raster().steps();
  out.b = band;
  out.w = out.n + 2 * band + 1;
  out.h.assign(static_cast<std::size_t>(out.w) * out.w, 0.0);
  // Degree 6 makes the ghost error O(spacing^7), one order beyond what the fourth-order
  // second differences need, so seams are not the weak spot; coarse rasters get what fits.
  switch (std::min(out.n, 6)) {
    case 3:
      fillWithDegree<3>(ddf, face, band, out);
      break;
    case 4:
      fillWithDegree<4>(ddf, face, band, out);
      break;
    case 5:
      fillWithDegree<5>(ddf, face, band, out);
      break;
    default:
      fillWithDegree<6>(ddf, face, band, out);
      break;
  }
}

}  // namespace ddfcam::planning::detail
