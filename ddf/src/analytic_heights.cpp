// SPDX-License-Identifier: MIT
// ddfcam: heights of a DDF whose raster points lie on an exact analytic surface (fromAnalytic).
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <string>

namespace ddfcam::ddf {

namespace {

/// The implicit function along one stubble, phi(h) = value(g + h v), and its derivative.
struct Stubble {
  const AnalyticSurface& surface;
  Vec3 g;
  Vec3 v;

  double phi(double h) const { return surface.value(g + h * v); }
  double phiAndSlope(double h, double& slope) const {
    Vec3 grad;
    const double f = surface.valueAndGradient(g + h * v, grad);
    slope = grad.dot(v);
    return f;
  }
};

/// Root of the stubble in the bracket [a, b] (phi(a), phi(b) of opposite signs): Newton's
/// method, falling back to bisection whenever a step leaves the bracket or the slope vanishes.
double refineRoot(const Stubble& s, double a, double fa, double b, double fb) {
  constexpr double kTolerance = 1e-13;
  double h = a - fa * (b - a) / (fb - fa);  // regula falsi start: Newton then needs ~2 steps
  for (int iter = 0; iter < 100; ++iter) {
    double slope = 0.0;
    const double f = s.phiAndSlope(h, slope);
    if (f == 0.0) return h;
    if ((f < 0.0) == (fa < 0.0)) {
      a = h, fa = f;
    } else {
      b = h;
    }
    double next = (slope != 0.0) ? h - f / slope : 0.5 * (a + b);
    if (!(next > std::min(a, b) && next < std::max(a, b))) next = 0.5 * (a + b);
    const double step = std::abs(next - h);
    h = next;
    if (step < kTolerance || std::abs(b - a) < kTolerance) break;
  }
  return h;
}

/// The root of the stubble in [-1, 1] nearest to h = 0, if the surface crosses it: rings of
/// width 1/8 are scanned outwards from 0 (a tangential double root inside one ring is missed).
std::optional<double> solveStubble(const Stubble& s) {
  constexpr int kRings = 8;
  const double f0 = s.phi(0.0);
  if (f0 == 0.0) return 0.0;
  double hPos = 0.0, fPos = f0, hNeg = 0.0, fNeg = f0;
  for (int r = 1; r <= kRings; ++r) {
    const double outPos = static_cast<double>(r) / kRings, outNeg = -outPos;
    const double fOutPos = s.phi(outPos), fOutNeg = s.phi(outNeg);
    std::optional<double> best;
    if (fOutPos == 0.0 || (fOutPos < 0.0) != (fPos < 0.0)) {
      best = fOutPos == 0.0 ? outPos : refineRoot(s, hPos, fPos, outPos, fOutPos);
    }
    if (fOutNeg == 0.0 || (fOutNeg < 0.0) != (fNeg < 0.0)) {
      const double h = fOutNeg == 0.0 ? outNeg : refineRoot(s, hNeg, fNeg, outNeg, fOutNeg);
      if (!best || std::abs(h) < std::abs(*best)) best = h;
    }
    if (best) return best;
    hPos = outPos, fPos = fOutPos, hNeg = outNeg, fNeg = fOutNeg;
  }
  return std::nullopt;
}

/// First (lowest-face) stubble that missed the surface, shared between worker threads.
struct Failure {
  std::mutex mutex;
  int face = std::numeric_limits<int>::max();
  int i = 0;
  int k = 0;

  void record(int f, int ii, int kk) {
    const std::lock_guard lock(mutex);
    if (f < face) face = f, i = ii, k = kk;
  }
};

/// Fills the heights of face @p f; returns false (after recording it) on the first miss.
bool fillFace(DisplacementField& ddf, const AnalyticSurface& surface, int f, Failure& failure) {
  const Raster& raster = ddf.raster();
  const int n = raster.steps();
  auto heights = ddf.heights(f);
  for (int k = 0; k <= n; ++k) {
    for (int i = 0; i <= n - k; ++i) {
      const Vec3 bary = ddf.rasterBary(i, k);
      const Stubble stubble{surface, ddf.basePoint(f, bary), ddf.vectorAt(f, bary)};
      const std::optional<double> h = solveStubble(stubble);
      if (!h) {
        failure.record(f, i, k);
        return false;
      }
      heights[raster.index(i, k)] = static_cast<float>(*h);
    }
  }
  return true;
}

}  // namespace

GeneratedSurface fromAnalytic(const SupportMesh& support, std::vector<Vec3> vectors, int m,
                              std::shared_ptr<const AnalyticSurface> surface) {
  if (!surface) throw InvalidInput("fromAnalytic: no analytic surface given");
  if (m < 2) throw InvalidInput("fromAnalytic: raster resolution m must be >= 2");
  GeneratedSurface out{DisplacementField(support, std::move(vectors), m), surface, surface};
  DisplacementField& ddf = out.ddf;
  Failure failure;
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount(), 16),
                    [&](const tbb::blocked_range<int>& range) {
                      for (int f = range.begin(); f != range.end(); ++f) {
                        fillFace(ddf, *surface, f, failure);
                      }
                    });
  if (failure.face != std::numeric_limits<int>::max()) {
    const int n = ddf.raster().steps();
    throw InvalidInput("fromAnalytic: the stubble of raster point (i=" + std::to_string(failure.i) +
                       ", j=" + std::to_string(n - failure.i - failure.k) +
                       ", k=" + std::to_string(failure.k) + ") of support face " +
                       std::to_string(failure.face) + " does not meet the surface '" +
                       surface->name() + "' within h in [-1, 1]");
  }
  ddf.synchronizeShared(SharedPolicy::Canonical);
  return out;
}

}  // namespace ddfcam::ddf
