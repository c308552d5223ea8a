// SPDX-License-Identifier: MIT
// ddfcam: the tolerance tries of a mesh conversion with a reduced support.
#include "conversion_tolerance.h"

#include <ddfcam/log.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "conversion_accuracy.h"
#include "conversion_resolution.h"

namespace ddfcam::ddf::detail {
namespace {

// Reductions tried for a tolerance, each with a shorter support edge bound.
constexpr int kReductionTries = 4;

double worstMm(const ConversionResult& r) {
  return std::max(r.accuracy.inputToDdfMm, r.accuracy.ddfToInputMm);
}

/// The factor the support edges must shrink by: at a crease or sharp edge inside a support face
/// the distance falls with the spacing, so by the measured ratio (with a margin), at least by
/// half and at most to a quarter.
double edgeFactor(double worst, double tol) {
  return std::clamp(0.9 * tol / worst, 0.25, 0.5);
}

/// What keeps the best of the reduced tries from the tolerance, for accuracy.note.
std::string reducedLimit(const ConversionResult& best, int tries, const std::string& stop) {
  std::string why = std::to_string(tries) + " reduced supports tried; " + stop;
  if (best.unfilledPoints > 0)
    why += "; " + std::to_string(best.unfilledPoints) +
           " stubbles miss the input and keep the support's position";
  return why;
}

bool overBudget(const ConversionResult& r, const ConversionParams& params) {
  return storedRasterPoints(r.ddf.faceCount(), params.resolution) > params.maxRasterPoints;
}

void logTry(const ConversionResult& r, double edge) {
  log(LogLevel::Info, "mesh conversion: reduced support with edges <= " + mm(edge) + ": " +
                          std::to_string(r.ddf.faceCount()) + " faces at m = " +
                          std::to_string(r.ddf.resolution()) + ", input -> DDF " +
                          mm(r.accuracy.inputToDdfMm) + " at " + at(r.accuracy.worstInputPoint) +
                          ", DDF -> input " + mm(r.accuracy.ddfToInputMm) + ", " +
                          std::to_string(r.unfilledPoints) + " stubbles missed");
}

}  // namespace

double medianEdgeMm(const TriangleMesh& mesh) {
  std::vector<double> lengths;
  lengths.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const double l = (mesh.vertices[t[(k + 1) % 3]] - mesh.vertices[t[k]]).norm();
      if (l > 0.0 && std::isfinite(l)) lengths.push_back(l);
    }
  if (lengths.empty()) return 0.0;
  const auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), mid, lengths.end());
  return *mid;
}

// The reduction checks its stubbles at m = params.resolution, where its coverage checks (m^2
// rays per new face) are cheap; a finer raster on the reduced support is the cheaper way to a
// smaller spacing (the fill finds every stubble's hit again and the distances are measured at
// the raised m). Reducing again at a larger m instead contracts more (its coverage checks pass
// more easily), so the faces grow and the spacing gains little. Where raising m stops paying (a
// crease or sharp edge inside a support face, which the raster cuts at any spacing) only
// shorter support edges help: the next try reduces with a shorter edge bound.
ConversionResult convertReducedForTolerance(const ConversionParams& params, double spacingMm,
                                            const SingleConversion& once) {
  ConversionResult best;
  double edge = (params.resolution - 1) * spacingMm;
  if (params.reduction.maxEdgeMm > 0.0) edge = std::min(edge, params.reduction.maxEdgeMm);
  int tries = 0, resolutions = 0;
  std::string stop = "at most " + std::to_string(kReductionTries) + " reductions";
  while (tries < kReductionTries) {
    ConversionParams p = params;
    p.rasterSpacingMm = 0.0;
    p.reduction.maxEdgeMm = edge;
    const double from = 1.0 - std::pow(0.5, tries);
    const double to = tries + 1 == kReductionTries ? 1.0 : 1.0 - std::pow(0.5, tries + 1);
    p.progress = progressShare(params.progress, from, to);
    ConversionResult r = once(p);
    ++tries;
    resolutions += r.accuracy.resolutionTries;
    logTry(r, edge);
    // A support too fine for the point budget is no use even when it meets the tolerance.
    if (tries > 1 && overBudget(r, params)) {
      stop = "the raster point limit (" + std::to_string(params.maxRasterPoints) +
             ") rules out the " + std::to_string(r.ddf.faceCount()) +
             " faces of edges <= " + mm(edge);
      break;
    }
    const bool met = r.accuracy.toleranceMet;
    edge *= edgeFactor(worstMm(r), params.toleranceMm);
    if (tries == 1 || worstMm(r) < worstMm(best)) best = std::move(r);
    if (met) break;
  }
  best.accuracy.resolutionTries = resolutions;
  if (!best.accuracy.toleranceMet) {
    best.accuracy.note += "; " + reducedLimit(best, tries, stop);
    log(LogLevel::Warning, "mesh conversion: " + best.accuracy.note);
  }
  best.report.accuracy = best.accuracy;
  return best;
}

}  // namespace ddfcam::ddf::detail
