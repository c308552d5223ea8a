// SPDX-License-Identifier: MIT
// ddfcam: what an imported program's vectors and points stand for (tool axis, approach
// direction or surface normal; contact or tool reference point), detected from the part.
#include "imported_path_convention.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/placement/tool_orientation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;
using detail::isCutter;
using detail::isWheel;

constexpr std::size_t kMaxSamples = 512;
// |v . n| above this is a vector clearly out of or into the part (60 deg from the surface
// plane would be 0.87; 0.5 still tells a reversed vector from a tilted one).
constexpr double kClearCosine = 0.5;
// Reference heights below this cannot tell a contact from a tool reference point, mm.
constexpr double kMinReferenceHeightMm = 0.1;

constexpr std::array<std::pair<PathVectorMeaning, std::string_view>, 4> kVectorNames = {
    {{PathVectorMeaning::Auto, "auto"},
     {PathVectorMeaning::ToolAxis, "axis"},
     {PathVectorMeaning::ApproachDirection, "approach"},
     {PathVectorMeaning::SurfaceNormal, "normal"}}};
constexpr std::array<std::pair<PathPointMeaning, std::string_view>, 4> kPointNames = {
    {{PathPointMeaning::Declared, "file"},
     {PathPointMeaning::Auto, "auto"},
     {PathPointMeaning::Contact, "contact"},
     {PathPointMeaning::ToolReference, "tip"}}};

std::string vectorsText(PathVectorMeaning m) {
  switch (m) {
    case PathVectorMeaning::ApproachDirection:
      return "approach directions";
    case PathVectorMeaning::SurfaceNormal:
      return "surface normals";
    default:
      return "tool axes (tip to holder)";
  }
}

std::string pointsText(ClPointKind k) {
  return k == ClPointKind::Contact ? "contacts" : "tool reference points";
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

std::string ofSampled(int count, const PathConvention& c) {
  return std::to_string(count) + " of " + std::to_string(c.sampled) + " sampled points";
}

/// Fills the evidence fields of @p c from up to kMaxSamples cut points (all points if none
/// cuts).
void gatherEvidence(const detail::PartSurface& surface, const std::vector<detail::PlacedPoint>& pts,
                    const Tool& tool, const PlaceProgramParams& params, PathConvention& c) {
  std::vector<std::size_t> candidates;
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (pts[k].cut) candidates.push_back(k);
  if (candidates.empty())
    for (std::size_t k = 0; k < pts.size(); ++k) candidates.push_back(k);
  const std::size_t stride = (candidates.size() + kMaxSamples - 1) / kMaxSamples;
  const bool revolvedCentre = isWheel(tool.kind) || tool.kind == ToolKind::Sphere;
  const double h = c.referenceHeightMm = revolvedCentre ? tool.radiusMm : 0.0;
  const double farMm = h + params.contactSearchMm + tool.radiusMm + tool.widthMm;
  std::vector<double> distances;
  for (std::size_t i = 0; i < candidates.size(); i += stride) {
    const detail::PlacedPoint& p = pts[candidates[i]];
    const auto [foot, n] = surface.smoothFoot(p.position, surface.nearest(p.position));
    // Beside the border the nearest normal says nothing about the point's side.
    const double s = foot.signedDistance;
    if (detail::besideBorder(p.position, foot.point, n) || std::abs(s) > farMm) {
      ++c.leftOut;
      continue;
    }
    distances.push_back(s);
    ++c.sampled;
    if (p.axis) {
      const double cosine = p.axis->dot(n);
      c.vectorsOut += cosine > kClearCosine;
      c.vectorsIn += cosine < -kClearCosine;
    }
    if (h < kMinReferenceHeightMm ||
        std::min(std::abs(s), std::abs(s - h)) > params.contactSearchMm)
      continue;
    (std::abs(s) <= std::abs(s - h) ? c.pointsOnSurface : c.pointsAtReference)++;
  }
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  c.medianPointDistanceMm = distances.empty() ? 0.0 : distances[distances.size() / 2];
}

/// True if enough sampled points lie over the part for a verdict.
bool enoughOverThePart(const PathConvention& c) {
  return c.sampled > 0 && 3 * c.sampled >= c.leftOut;
}

std::string fewOverThePart(const PathConvention& c) {
  return "only " + std::to_string(c.sampled) + " of " + std::to_string(c.sampled + c.leftOut) +
         " sampled points lie over the part, the others beside its border or far off";
}

/// The meaning the evidence asks for: into the part, approach; out of it, tool axis (wheels,
/// whose axis lies along the surface: surface normal); empty without a 2:1 majority.
std::optional<PathVectorMeaning> vectorVerdict(const PathConvention& c, ToolKind kind) {
  if (!enoughOverThePart(c)) return std::nullopt;
  if (c.vectorsIn > 0 && c.vectorsIn >= 2 * c.vectorsOut)
    return PathVectorMeaning::ApproachDirection;
  if (c.vectorsOut > 0 && c.vectorsOut >= 2 * c.vectorsIn)
    return isWheel(kind) ? PathVectorMeaning::SurfaceNormal : PathVectorMeaning::ToolAxis;
  return std::nullopt;
}

/// True if @p given reads vectors the way @p verdict says they point (out of the part, a
/// cutter's axis and the normal are alike).
bool fits(PathVectorMeaning given, PathVectorMeaning verdict, ToolKind kind) {
  if (given == verdict) return true;
  return verdict == PathVectorMeaning::ToolAxis && !isWheel(kind) &&
         given == PathVectorMeaning::SurfaceNormal;
}

std::optional<ClPointKind> pointVerdict(const PathConvention& c) {
  if (!enoughOverThePart(c)) return std::nullopt;
  if (c.pointsOnSurface > 0 && c.pointsOnSurface >= 2 * c.pointsAtReference)
    return ClPointKind::Contact;
  if (c.pointsAtReference > 0 && c.pointsAtReference >= 2 * c.pointsOnSurface)
    return ClPointKind::ToolReference;
  return std::nullopt;
}

std::string vectorEvidence(const PathConvention& c, PathVectorMeaning verdict) {
  return verdict == PathVectorMeaning::ApproachDirection
             ? "they point into the part at " + ofSampled(c.vectorsIn, c)
             : "they point out of the part at " + ofSampled(c.vectorsOut, c);
}

std::string pointEvidence(const PathConvention& c, ClPointKind verdict) {
  const std::string median = "; median distance " + number(c.medianPointDistanceMm) + " mm";
  return verdict == ClPointKind::Contact
             ? "they lie on the surface at " + ofSampled(c.pointsOnSurface, c) + median
             : "they lie about the tool's reference height " + number(c.referenceHeightMm) +
                   " mm off the part at " + ofSampled(c.pointsAtReference, c) + median;
}

void resolveVectors(const std::vector<detail::PlacedPoint>& pts, ToolKind kind,
                    const PlaceProgramParams& params, PathConvention& c, std::string& reason,
                    std::vector<ClMessage>& warnings) {
  const bool any = std::any_of(pts.begin(), pts.end(), [](const auto& p) { return p.axis; });
  const std::optional<PathVectorMeaning> verdict = vectorVerdict(c, kind);
  if (params.vectorMeaning == PathVectorMeaning::Auto) {
    c.vectors = verdict.value_or(PathVectorMeaning::ToolAxis);
    c.vectorsDetected = any;
    reason = "vectors: " + vectorsText(c.vectors);
    if (!any)
      reason += " (the program has none)";
    else if (verdict)
      reason += " (detected: " + vectorEvidence(c, *verdict) + ")";
    else if (!enoughOverThePart(c))
      reason += " (undecided: " + fewOverThePart(c) + ")";
    else
      reason += " (undecided: out of the part at " + ofSampled(c.vectorsOut, c) + ", into it at " +
                std::to_string(c.vectorsIn) + ")";
    return;
  }
  c.vectors = params.vectorMeaning;
  reason = "vectors: " + vectorsText(c.vectors) + " (as chosen)";
  if (verdict && !fits(c.vectors, *verdict, kind))
    warnings.push_back({0, "the vectors were read as " + vectorsText(c.vectors) + ", but " +
                               vectorEvidence(c, *verdict) + ", as " + vectorsText(*verdict) +
                               " do: choose that vector meaning (or auto)"});
}

void resolvePoints(ClPointKind declared, const PlaceProgramParams& params, PathConvention& c,
                   std::string& reason, std::vector<ClMessage>& warnings) {
  const std::optional<ClPointKind> verdict = pointVerdict(c);
  switch (params.pointMeaning) {
    case PathPointMeaning::Auto:
      c.points = verdict.value_or(declared);
      c.pointsDetected = verdict.has_value();
      reason += "; points: " + pointsText(c.points);
      if (verdict)
        reason += " (detected: " + pointEvidence(c, *verdict) + ")";
      else if (!enoughOverThePart(c))
        reason += " (as the program says: " + fewOverThePart(c) + ")";
      else if (c.referenceHeightMm < kMinReferenceHeightMm)
        reason +=
            " (as the program says: this tool's reference point touches the surface, so "
            "contacts and reference points look alike)";
      else
        reason += " (as the program says: undecided)";
      return;
    case PathPointMeaning::Declared:
      c.points = declared;
      reason += "; points: " + pointsText(c.points) + " (as the program says)";
      break;
    case PathPointMeaning::Contact:
    case PathPointMeaning::ToolReference:
      c.points = params.pointMeaning == PathPointMeaning::Contact ? ClPointKind::Contact
                                                                  : ClPointKind::ToolReference;
      reason += "; points: " + pointsText(c.points) + " (as chosen)";
      break;
  }
  if (verdict && *verdict != c.points)
    warnings.push_back({0, "the points were read as " + pointsText(c.points) + ", but " +
                               pointEvidence(c, *verdict) + ", as " + pointsText(*verdict) +
                               " do: choose that point meaning (or auto)"});
}

/// True if @p m turns the points' vectors into normals for @p kind (no axis left).
bool vectorsBecomeNormals(PathVectorMeaning m, ToolKind kind) {
  return m == PathVectorMeaning::SurfaceNormal ||
         (m == PathVectorMeaning::ApproachDirection && !isCutter(kind));
}

}  // namespace

std::string_view pathVectorMeaningName(PathVectorMeaning meaning) {
  for (const auto& [m, name] : kVectorNames)
    if (m == meaning) return name;
  return "axis";
}

std::string_view pathPointMeaningName(PathPointMeaning meaning) {
  for (const auto& [m, name] : kPointNames)
    if (m == meaning) return name;
  return "file";
}

std::optional<PathVectorMeaning> pathVectorMeaningFromName(std::string_view name) {
  for (const auto& [m, text] : kVectorNames)
    if (text == name) return m;
  return std::nullopt;
}

std::optional<PathPointMeaning> pathPointMeaningFromName(std::string_view name) {
  for (const auto& [m, text] : kPointNames)
    if (text == name) return m;
  return std::nullopt;
}

namespace detail {

bool isWheel(ToolKind kind) {
  return kind == ToolKind::CylinderRoll || kind == ToolKind::BeltContactWheel;
}

bool isCutter(ToolKind kind) {
  return kind == ToolKind::BallEnd || kind == ToolKind::FlatEnd || kind == ToolKind::TorusCutter;
}

Vec3 perpendicularTo(const Vec3& a) {
  Vec3 best = Vec3::UnitZ();
  for (const Vec3& e : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitY())})
    if (std::abs(e.dot(a)) < std::abs(best.dot(a)) - 1e-12) best = e;
  return (best - best.dot(a) * a).normalized();
}

Vec3 tangentialFeed(const Vec3& feed, const Vec3& n, const Vec3& hint) {
  for (const Vec3& d : {feed, hint}) {
    const Vec3 t = d - d.dot(n) * n;
    if (t.norm() > 1e-9 * std::max(1.0, d.norm())) return t.normalized();
  }
  return perpendicularTo(n);
}

Vec3 feedAt(const std::vector<PlacedPoint>& pts, std::size_t k) {
  if (k + 1 < pts.size() && !pts[k + 1].passStart) return pts[k + 1].position - pts[k].position;
  if (k > 0 && !pts[k].passStart) return pts[k].position - pts[k - 1].position;
  return Vec3::Zero();
}

PathConvention resolveConvention(const PartSurface& surface, const std::vector<PlacedPoint>& pts,
                                 const Tool& tool, ClPointKind declared,
                                 const PlaceProgramParams& params,
                                 std::vector<ClMessage>& warnings) {
  PathConvention c;
  gatherEvidence(surface, pts, tool, params, c);
  std::string reason;
  resolveVectors(pts, tool.kind, params, c, reason, warnings);
  resolvePoints(declared, params, c, reason, warnings);
  c.reason = std::move(reason);
  return c;
}

ClPointKind applyConvention(const PathConvention& convention, const Tool& tool,
                            const PartSurface& surface, std::vector<PlacedPoint>& pts) {
  const bool toNormals = vectorsBecomeNormals(convention.vectors, tool.kind);
  for (PlacedPoint& p : pts) {
    if (!p.axis || convention.vectors == PathVectorMeaning::ToolAxis) continue;
    const Vec3 v = *p.axis;
    if (toNormals) {
      p.normal = convention.vectors == PathVectorMeaning::SurfaceNormal ? v : Vec3(-v);
      p.axis.reset();
    } else {
      p.axis = -v;  // a cutter's approach direction: the reversed tool axis
    }
  }
  if (convention.points == ClPointKind::Contact || !toNormals) return convention.points;
  // Reference points with normals but no axes: the contacts the tool standing along the
  // normal would have, so that the contact placement orients it.
  std::vector<Vec3> contacts(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    PlacedPoint& p = pts[k];
    if (!p.normal) p.normal = surface.normal(surface.nearest(p.position));
    const Vec3 t = tangentialFeed(feedAt(pts, k), *p.normal, perpendicularTo(*p.normal));
    try {
      contacts[k] = p.position - placeToolDetailed(tool, p.position, *p.normal, t).referenceOffset;
    } catch (const InvalidInput&) {
      std::throw_with_nested(InvalidInput("placing a program: point " + std::to_string(p.source) +
                                          ": cannot find the contact of the reference point"));
    }
  }
  for (std::size_t k = 0; k < pts.size(); ++k) pts[k].position = contacts[k];
  return ClPointKind::Contact;
}

std::string conventionSummary(const PathConvention& convention) {
  return "vectors read as " + vectorsText(convention.vectors) + ", points as " +
         pointsText(convention.points);
}

}  // namespace detail
}  // namespace ddfcam::planning
