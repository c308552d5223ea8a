// SPDX-License-Identifier: MIT
// ddfcam: families of streamlines seeded along a transverse streamline, and their smoothing.
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::SurfaceLocation;
using ddf::Vec3;

// Barycentric coordinates of @p loc in @p face: exact when every vertex carrying weight is
// also a vertex of @p face (the location lies on their shared edge or vertex).
std::optional<Vec3> baryInFace(const ddf::DisplacementField& ddf, const SurfaceLocation& loc,
                               int face) {
  if (loc.face == face) return loc.bary;
  const auto& from = ddf.faceVertices(loc.face);
  const auto& to = ddf.faceVertices(face);
  Vec3 out = Vec3::Zero();
  for (int c = 0; c < 3; ++c) {
    if (loc.bary[c] == 0.0) continue;
    const auto it = std::find(to.begin(), to.end(), from[c]);
    if (it == to.end()) return std::nullopt;
    out[it - to.begin()] = loc.bary[c];
  }
  return out;
}

// The location at fraction t of the segment from @p a to @p b, interpolated in a face that
// holds both (b's face: a segment of a traced line never spans more than one face).
SurfaceLocation between(const ddf::DisplacementField& ddf, const SurfaceLocation& a,
                        const SurfaceLocation& b, double t) {
  int face = b.face;
  std::optional<Vec3> ba = baryInFace(ddf, a, face);
  std::optional<Vec3> bb = b.bary;
  if (!ba) {
    face = a.face;
    ba = a.bary;
    bb = baryInFace(ddf, b, face);
  }
  if (!bb) return t < 0.5 ? a : b;  // not a traced segment; nearest end
  const Vec3 bary = (1.0 - t) * *ba + t * *bb;
  const double h = ddf::interpolateOnFace(ddf, ddf.allHeights(), face, bary);
  return {face, bary, h, ddf.pointAt(face, bary, h)};
}

// Locations every @p spacing of arc length from points[from] walking by @p dir (+-1).
void walk(const ddf::DisplacementField& ddf, const std::vector<SurfaceLocation>& points,
          std::size_t from, int dir, double spacing, std::vector<SurfaceLocation>& out) {
  double carried = 0.0;  // arc length since the last seed
  const auto size = static_cast<std::ptrdiff_t>(points.size());
  for (auto i = static_cast<std::ptrdiff_t>(from); i + dir >= 0 && i + dir < size; i += dir) {
    const SurfaceLocation& a = points[i];
    const SurfaceLocation& b = points[i + dir];
    const double len = (b.point - a.point).norm();
    double pos = spacing - carried;  // along this segment
    while (pos <= len && len > 0.0) {
      out.push_back(between(ddf, a, b, pos / len));
      pos += spacing;
    }
    carried = len - (pos - spacing);
  }
}

}  // namespace

std::vector<ddf::Vec3> Streamline::polyline() const {
  std::vector<ddf::Vec3> out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back(p.point);
  return out;
}

std::vector<ddf::SurfaceLocation> seedsAlong(const ddf::DisplacementField& ddf,
                                             const Streamline& transverse, double spacingMm) {
  if (!(spacingMm > 0.0))
    throw InvalidInput("seedsAlong: spacing " + std::to_string(spacingMm) + " mm is not > 0");
  if (transverse.points.empty()) return {};
  std::vector<SurfaceLocation> before, after;
  walk(ddf, transverse.points, transverse.seedIndex, -1, spacingMm, before);
  walk(ddf, transverse.points, transverse.seedIndex, +1, spacingMm, after);
  std::vector<SurfaceLocation> out(before.rbegin(), before.rend());
  out.push_back(transverse.points[transverse.seedIndex]);
  out.insert(out.end(), after.begin(), after.end());
  return out;
}

std::vector<Streamline> seedAlongTransverse(const ddf::DisplacementField& ddf,
                                            const LineField& field,
                                            const LineField& transverseField,
                                            const ddf::SurfaceLocation& seed, double spacingMm,
                                            const StreamlineParams& params) {
  if (!(spacingMm > 0.0)) {
    throw InvalidInput("seedAlongTransverse: spacing " + std::to_string(spacingMm) +
                       " mm is not > 0");
  }
  if (field.size() != transverseField.size()) {
    throw InvalidInput("seedAlongTransverse: field has " + std::to_string(field.size()) +
                       " entries, transverse field " + std::to_string(transverseField.size()));
  }
  StreamlineParams quiet = params;
  quiet.progress = nullptr;
  const Streamline transverse = traceStreamline(ddf, transverseField, seed, quiet);
  const std::vector<SurfaceLocation> seeds = seedsAlong(ddf, transverse, spacingMm);
  std::vector<Streamline> lines;
  lines.reserve(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    reportProgress(params.progress, static_cast<double>(i) / seeds.size());
    lines.push_back(traceStreamline(ddf, field, seeds[i], quiet));
  }
  reportProgress(params.progress, 1.0);
  return lines;
}

std::vector<ddf::Vec3> smoothMovingAverage(const std::vector<ddf::Vec3>& points, int halfWindow) {
  if (halfWindow < 0) {
    throw InvalidInput("smoothMovingAverage: half window " + std::to_string(halfWindow) +
                       " is negative");
  }
  const int count = static_cast<int>(points.size());
  std::vector<ddf::Vec3> out(points.size());
  for (int i = 0; i < count; ++i) {
    const int k = std::min({halfWindow, i, count - 1 - i});
    Vec3 sum = Vec3::Zero();
    for (int j = i - k; j <= i + k; ++j) sum += points[j];
    out[i] = sum / (2 * k + 1);
  }
  return out;
}

Streamline smoothOnSurface(const ddf::DisplacementField& ddf, const Streamline& line,
                           int halfWindow) {
  Streamline out = line;
  const std::vector<Vec3> smooth = smoothMovingAverage(line.polyline(), halfWindow);
  const auto count = static_cast<int>(smooth.size());
  out.lengthMm = 0.0;
  for (int i = 0; i < count; ++i) {
    double best = std::numeric_limits<double>::infinity();
    int lastFace = -1;
    for (int j = std::max(0, i - halfWindow); j <= std::min(count - 1, i + halfWindow); ++j) {
      // Consecutive points mostly share a face: locate on each face once.
      const int face = line.points[j].face;
      if (face == lastFace) continue;
      lastFace = face;
      const auto at = ddf::locateOnFace(ddf, face, smooth[i]);
      if (!at || (at->point - smooth[i]).norm() >= best) continue;
      best = (at->point - smooth[i]).norm();
      out.points[i] = *at;
    }
    if (i > 0) out.lengthMm += (out.points[i].point - out.points[i - 1].point).norm();
  }
  return out;
}

std::vector<Streamline> smoothOnSurface(const ddf::DisplacementField& ddf,
                                        const std::vector<Streamline>& lines, int halfWindow) {
  std::vector<Streamline> out;
  out.reserve(lines.size());
  for (const Streamline& line : lines) out.push_back(smoothOnSurface(ddf, line, halfWindow));
  return out;
}

}  // namespace ddfcam::planning
