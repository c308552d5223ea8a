// SPDX-License-Identifier: MIT
// ddfcam: heights of a converted DDF at the resolution the accuracy asks for, stock crust fit.
#include "conversion_resolution.h"

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/stock_crust.h>
#include <ddfcam/ddf/v_shooting.h>
#include <ddfcam/ddf/validation.h>
#include <ddfcam/log.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "conversion_accuracy.h"

namespace ddfcam::ddf::detail {
namespace {

constexpr int kMaxResolution = 256;
// A try that does not bring the distance below this share of the previous one is not worth
// another: the chord error of a smooth surface falls to 1 / 1.5^2 = 0.44 per try, and even the
// linear error at a crease inside a support face falls to 0.67.
constexpr double kStallRatio = 0.8;
constexpr int kMaxTries = 10;

bool measures(const ConversionParams& params) {
  return params.toleranceMm > 0.0 || params.rasterSpacingMm > 0.0 ||
         params.support == SupportChoice::Reduced;
}

// Barycentric tolerance of the second look at a missed stubble: that of the reduction's hit
// check, which lets a ray through a shared or boundary input edge hit.
constexpr double kLambdaTolerance = 1e-7;
// Ray-triangle tests the second look may spend (missed stubbles x input triangles).
constexpr double kSecondLookBudget = 2e8;

/// The nearest hit within |h| <= 1 of the stubble of raster point (i, k) of face @p f, shot in
/// double against every input triangle whose box meets the stubble.
std::optional<double> secondLook(const DisplacementField& ddf, int f, int i, int k,
                                 const TriangleMesh& mesh) {
  const Vec3 bary = ddf.rasterBary(i, k);
  const Vec3 g = ddf.basePoint(f, bary), v = ddf.vectorAt(f, bary);
  Eigen::AlignedBox3d stubble(g - v);
  stubble.extend(g + v);
  std::optional<double> best;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    Eigen::AlignedBox3d box(a);
    box.extend(b), box.extend(c);
    if (!box.intersects(stubble)) continue;
    const auto shot = vShootLine(g, v, a, b, c);
    if (shot && std::abs(shot->h) <= 1.0 && shot->lambda.minCoeff() >= -kLambdaTolerance &&
        (!best || std::abs(shot->h) < std::abs(*best)))
      best = shot->h;
  }
  return best;
}

// The fill runs in float with exact barycentric bounds, so a stubble through an input edge (on
// the input's boundary above all) can miss where the reduction's double check counted a hit;
// those few get a second look with the reduction's tolerance. Returns the stubbles still missed.
std::size_t fillMissed(const TriangleMesh& mesh, const FillReport& report, DisplacementField& ddf) {
  if (report.missing == 0) return 0;
  if (double(report.missing) * double(mesh.triangles.size()) > kSecondLookBudget)
    return report.missing;
  const int n = ddf.raster().steps();
  std::vector<std::array<int, 2>> lattice;  // (i, k) in Raster order: row k, then i
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i + k <= n; ++i) lattice.push_back({i, k});
  const std::size_t perFace = ddf.pointsPerFace();
  std::size_t missed = 0;
  for (std::size_t p = 0; p < report.missingMask.size(); ++p) {
    if (!report.missingMask[p]) continue;
    const int f = static_cast<int>(p / perFace);
    const auto& ik = lattice[p % perFace];
    const auto h = secondLook(ddf, f, ik[0], ik[1], mesh);
    if (h)
      ddf.heights(f)[p % perFace] = static_cast<float>(*h);
    else
      ++missed;
  }
  // Every copy of a shared point was missed and looked at again on its own: one value for all.
  ddf.synchronizeShared(SharedPolicy::Canonical);
  return missed;
}

// Heights from the input mesh along the stubbles (the depth buffer's fill mode): with the mesh
// as support they come out ~0; a reduced support and the input's dropped triangles are honoured
// the same way. Stubbles that miss keep h = 0, i.e. the support itself.
void fillFromInput(const TriangleMesh& mesh, ConversionResult& result,
                   const ProgressCallback& progress) {
  const CrustHash hash(result.ddf);
  FillParams fill;
  fill.progress = progress;
  const FillReport report = fillFromMesh(result.ddf, hash, mesh, fill);
  const std::size_t missed = fillMissed(mesh, report, result.ddf);
  result.filledPoints = report.filled + (report.missing - missed);
  result.unfilledPoints = missed;
  result.report.unfilledPoints = missed;
}

/// The same support and vectors at resolution @p m, heights refilled from the input.
void refill(const TriangleMesh& mesh, int m, ConversionResult& result,
            const ProgressCallback& progress) {
  result.ddf = DisplacementField(SupportMesh(result.ddf.support()), result.ddf.vectors(), m, 0.0f);
  fillFromInput(mesh, result, progress);
}

/// Largest m the limits allow for @p faces faces.
int largestResolution(int faces, std::size_t maxRasterPoints) {
  int m = kMaxResolution;
  while (m > 2 && storedRasterPoints(faces, m) > maxRasterPoints) --m;
  return m;
}

/// The next m: the chord error falls with the square of the spacing, so the steps m - 1 grow by
/// the root of the measured ratio (with a margin), at least x1.5 and at most x4.
int nextResolution(int m, double ratio) {
  const double grow = std::clamp(1.1 * std::sqrt(ratio), 1.5, 4.0);
  return static_cast<int>(std::ceil((m - 1) * grow)) + 1;
}

void record(const MeasuredDistances& d, double longestEdgeMm, const DisplacementField& ddf,
            ConversionAccuracy& accuracy) {
  accuracy.measured = true;
  accuracy.inputToDdfMm = d.inputToDdfMm;
  accuracy.ddfToInputMm = d.ddfToInputMm;
  accuracy.worstInputPoint = d.worstInputPoint;
  accuracy.worstRasterPoint = d.worstRasterPoint;
  accuracy.resolution = ddf.resolution();
  accuracy.rasterSpacingMm = longestEdgeMm / (ddf.resolution() - 1);
}

/// Measures both ways and records the result.
class Meter {
 public:
  Meter(const TriangleMesh& mesh, std::span<const int> keptTriangles, const ConversionResult& r)
      : bvh_(mesh),
        samples_(inputSamples(mesh, keptTriangles)),
        longestEdgeMm_(longestSupportEdgeMm(r.ddf.support())) {}
  MeasuredDistances measure(ConversionResult& result, const ProgressCallback& progress) const {
    const MeasuredDistances d = measureDistances(result.ddf, samples_, bvh_, progress);
    record(d, longestEdgeMm_, result.ddf, result.accuracy);
    return d;
  }

 private:
  TriangleBvh bvh_;
  std::vector<Vec3> samples_;
  double longestEdgeMm_;
};

/// The parts of a result a refill changes: what a finer raster that does worse goes back to.
struct FillState {
  DisplacementField ddf;
  ConversionAccuracy accuracy;
  std::size_t filled = 0, unfilled = 0;
};

FillState saved(const ConversionResult& r) {
  return {r.ddf, r.accuracy, r.filledPoints, r.unfilledPoints};
}

void restore(FillState&& state, ConversionResult& r) {
  const int tries = r.accuracy.resolutionTries;
  r.ddf = std::move(state.ddf);
  r.accuracy = state.accuracy;
  r.accuracy.resolutionTries = tries;
  r.filledPoints = state.filled;
  r.unfilledPoints = r.report.unfilledPoints = state.unfilled;
}

/// Why the raise from m to @p next stops (empty: go on); restores the coarser raster when the
/// finer one is worse or has stubbles that miss the input where the coarser had none (a reduced
/// support was checked at its own m only, and a missed stubble keeps the support's position).
/// @param capLimit empty, or the limit that cut the step short: a short step says little about
/// how the distance falls, so a stall is reported as that limit.
std::string judgeRaise(FillState&& before, const MeasuredDistances& d, const MeasuredDistances& now,
                       double tol, const std::string& capLimit, ConversionResult& result) {
  const int m = before.ddf.resolution(), next = result.ddf.resolution();
  if (result.unfilledPoints > before.unfilled) {
    const std::size_t missed = result.unfilledPoints;
    restore(std::move(before), result);
    return "at m = " + std::to_string(next) + " " + std::to_string(missed) +
           " stubbles miss the input, so m stays at " + std::to_string(m);
  }
  if (!(now.worstMm() > kStallRatio * d.worstMm()) || now.worstMm() <= tol) return {};
  if (now.worstMm() > d.worstMm()) restore(std::move(before), result);
  if (!capLimit.empty()) return capLimit;
  return "the distance stopped shrinking with the resolution (" + mm(d.worstMm()) +
         " at m = " + std::to_string(m) + ", " + mm(now.worstMm()) +
         " at m = " + std::to_string(next) +
         "): the support cannot follow the input there (a crease or an edge that one support "
         "face spans)";
}

/// Raises m until both distances are within params.toleranceMm; returns why not (empty: met).
std::string raiseResolutionFor(const TriangleMesh& mesh, const ConversionParams& params,
                               const Meter& meter, MeasuredDistances d, ConversionResult& result) {
  const double tol = params.toleranceMm;
  const int largest = largestResolution(result.ddf.faceCount(), params.maxRasterPoints);
  double share = 0.75;
  while (d.worstMm() > tol) {
    const int m = result.ddf.resolution();
    const int wanted = nextResolution(m, d.worstMm() / tol), next = std::min(wanted, largest);
    const std::string limit =
        "the resolution reached its limit (m = " + std::to_string(std::max(m, next)) +
        ": at most m = " + std::to_string(kMaxResolution) + " and " +
        std::to_string(params.maxRasterPoints) + " raster points)";
    if (next <= m) return limit;
    if (result.accuracy.resolutionTries >= kMaxTries)
      return std::to_string(kMaxTries) + " resolutions were tried";
    FillState before = saved(result);
    const double end = share + 0.5 * (0.93 - share);
    refill(mesh, next, result, progressShare(params.progress, share, share + 0.6 * (end - share)));
    const MeasuredDistances now =
        meter.measure(result, progressShare(params.progress, share + 0.6 * (end - share), end));
    share = end;
    ++result.accuracy.resolutionTries;
    const std::string why =
        judgeRaise(std::move(before), d, now, tol, next < wanted ? limit : "", result);
    if (!why.empty()) return why;
    d = now;
  }
  return {};
}

// The stock fit changes support offsets and vectors and refills the heights; the check of the
// constraints is repeated so that report.validation describes the field that is returned.
void fitStock(const TriangleMesh& mesh, const ConversionParams& params, ConversionResult& result,
              const ProgressCallback& progress) {
  if (!(params.stockMm > 0.0)) return;
  StockCrustParams stock;
  stock.stockMm = params.stockMm;
  stock.progress = progress;
  result.stock = fitCrustToStock(result.ddf, mesh, stock);
  if (!result.stock->holds)
    log(LogLevel::Warning,
        "mesh conversion: stock allowance not held: " +
            (result.stock->limit ? result.stock->limit->message : std::string("no limit named")));
  if (result.report.validated) result.report.validation = validate(result.ddf, params.validation);
}

}  // namespace

std::string mm(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g mm", x);
  return text;
}

std::string at(const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", p.x(), p.y(), p.z());
  return text;
}

std::string toleranceNote(const ConversionAccuracy& a, const std::string& why) {
  return "tolerance " + mm(a.toleranceMm) + " not met at m = " + std::to_string(a.resolution) +
         " (raster spacing " + mm(a.rasterSpacingMm) + "): input -> DDF " + mm(a.inputToDdfMm) +
         " at " + at(a.worstInputPoint) + ", DDF -> input " + mm(a.ddfToInputMm) + " at " +
         at(a.worstRasterPoint) + "; " + why;
}

ProgressCallback progressShare(const ProgressCallback& progress, double from, double to) {
  if (!progress) return {};
  return [progress, from, to](double x) { return progress(from + (to - from) * x); };
}

void fillHeights(const TriangleMesh& mesh, const ConversionParams& params,
                 std::span<const int> keptTriangles, ConversionResult& result, bool warnOnMiss) {
  fillFromInput(mesh, result, progressShare(params.progress, 0.6, 0.7));
  ConversionAccuracy& accuracy = result.accuracy;
  accuracy.toleranceMm = params.toleranceMm;
  if (!measures(params)) {
    fitStock(mesh, params, result, progressShare(params.progress, 0.7, 1.0));
    return;
  }
  const Meter meter(mesh, keptTriangles, result);
  const MeasuredDistances first = meter.measure(result, progressShare(params.progress, 0.7, 0.75));
  accuracy.resolutionTries = 1;
  std::string why;
  if (params.toleranceMm > 0.0) why = raiseResolutionFor(mesh, params, meter, first, result);
  if (params.stockMm > 0.0) {
    fitStock(mesh, params, result, progressShare(params.progress, 0.93, 0.95));
    meter.measure(result, progressShare(params.progress, 0.95, 1.0));
  }
  if (params.toleranceMm > 0.0) {
    accuracy.toleranceMet =
        std::max(accuracy.inputToDdfMm, accuracy.ddfToInputMm) <= params.toleranceMm;
    if (!accuracy.toleranceMet) {
      accuracy.note = toleranceNote(
          accuracy, why.empty() ? "the stock fit moved the surface beyond the tolerance" : why);
      if (warnOnMiss) log(LogLevel::Warning, "mesh conversion: " + accuracy.note);
    }
  }
}

}  // namespace ddfcam::ddf::detail
