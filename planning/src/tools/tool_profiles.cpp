// SPDX-License-Identifier: MIT
// ddfcam: exact tool profiles (lines and circular arcs) and their sampling.
#include <ddfcam/planning/tools/tool_profiles.h>

#include <ddfcam/error.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace ddfcam::planning {
namespace {

constexpr double kPi = std::numbers::pi;
// Segments shorter than this (mm or rad) are dropped: they arise where a fillet or a crown
// degenerates (edge = width / 2, crown = width / 2) and would repeat a profile point.
constexpr double kNegligible = 1e-12;

ProfileSegment line(ProfilePoint from, ProfilePoint to) {
  ProfileSegment s;
  s.from = from;
  s.to = to;
  return s;
}

ProfileSegment arc(ProfilePoint centre, double radius, double startAngle, double sweepAngle) {
  ProfileSegment s;
  s.isArc = true;
  s.centre = centre;
  s.arcRadius = radius;
  s.startAngle = startAngle;
  s.sweepAngle = sweepAngle;
  s.from = s.at(0.0);
  s.to = s.at(1.0);
  // sin(pi) is 1.2e-16, not 0: an arc ending on the axis must end exactly there (a pole).
  for (ProfilePoint* p : {&s.from, &s.to})
    if (std::abs(p->radial) < 1e-12 * (radius + std::abs(centre.radial))) p->radial = 0.0;
  return s;
}

bool negligible(const ProfileSegment& s) {
  if (s.isArc) return std::abs(s.sweepAngle) * s.arcRadius < kNegligible;
  return std::hypot(s.to.axial - s.from.axial, s.to.radial - s.from.radial) < kNegligible;
}

/// Appends @p s unless it is negligible; its start is snapped to the previous end so the
/// profile is exactly connected.
void push(std::vector<ProfileSegment>& out, ProfileSegment s) {
  if (negligible(s)) return;
  if (!out.empty()) s.from = out.back().to;
  out.push_back(s);
}

/// Whether @p angle lies within the sweep of @p s (angles modulo 2 pi).
bool inSweep(const ProfileSegment& s, double angle) {
  const double lo = std::min(s.startAngle, s.startAngle + s.sweepAngle);
  const double hi = std::max(s.startAngle, s.startAngle + s.sweepAngle);
  const double k = std::ceil((lo - angle) / (2.0 * kPi));
  return angle + 2.0 * kPi * k <= hi;
}

std::vector<ProfileSegment> wheelSegments(const Tool& t) {
  const double h = 0.5 * t.widthMm, r = t.radiusMm, e = t.edgeRadiusMm, c = t.crownRadiusMm;
  std::vector<ProfileSegment> out;
  if (c > 0.0) {
    const ProfilePoint k{0.0, r - c};  // crown centre
    // Fillet centre at axial h - e, internally tangent to the crown circle.
    const double yc = k.radial + std::sqrt((c - e) * (c - e) - (h - e) * (h - e));
    const double phi = std::atan2(yc - k.radial, -(h - e));  // towards the left fillet centre
    push(out, line({-h, 0.0}, {-h, yc}));
    push(out, arc({-(h - e), yc}, e, kPi, phi - kPi));
    push(out, arc(k, c, phi, (kPi - phi) - phi));
    push(out, arc({h - e, yc}, e, kPi - phi, -(kPi - phi)));
    push(out, line({h, yc}, {h, 0.0}));
  } else {
    push(out, line({-h, 0.0}, {-h, r - e}));
    push(out, arc({-h + e, r - e}, e, kPi, -0.5 * kPi));
    push(out, line({-h + e, r}, {h - e, r}));
    push(out, arc({h - e, r - e}, e, 0.5 * kPi, -0.5 * kPi));
    push(out, line({h, r - e}, {h, 0.0}));
  }
  return out;
}

/// A cutter from the tip at (0, 0) along +axial: @p bottom corner radius (0 = flat end, r =
/// ball end), then the straight flank to the top of the cutting part.
std::vector<ProfileSegment> cutterSegments(double r, double corner, double width) {
  std::vector<ProfileSegment> out;
  push(out, line({0.0, 0.0}, {0.0, r - corner}));
  push(out, arc({corner, r - corner}, corner, kPi, -0.5 * kPi));
  push(out, line({corner, r}, {width, r}));
  push(out, line({width, r}, {width, 0.0}));
  return out;
}

struct CylinderPiece {
  double from = 0.0, to = 0.0, radius = 0.0;  // axial range and radius, mm
};

/// The union of coaxial cylinders as stepped profiles, one per connected run.
std::vector<ToolProfile> steppedProfiles(const std::vector<CylinderPiece>& pieces,
                                         RevolveAxis axis) {
  std::vector<double> cuts;
  for (const CylinderPiece& p : pieces)
    if (p.radius > 0.0 && p.to > p.from) cuts.insert(cuts.end(), {p.from, p.to});
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<ToolProfile> out;
  ToolProfile run{axis, {}};
  double previous = 0.0;  // radius of the run so far at the current cut
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    double r = 0.0;
    for (const CylinderPiece& p : pieces)
      if (p.to > p.from && p.from <= cuts[i] && cuts[i + 1] <= p.to) r = std::max(r, p.radius);
    if (r != previous) push(run.segments, line({cuts[i], previous}, {cuts[i], r}));
    if (r > 0.0) push(run.segments, line({cuts[i], r}, {cuts[i + 1], r}));
    if (r == 0.0 && !run.segments.empty()) out.push_back(std::exchange(run, {axis, {}}));
    previous = r;
  }
  if (!cuts.empty() && previous > 0.0) {
    push(run.segments, line({cuts.back(), previous}, {cuts.back(), 0.0}));
    out.push_back(run);
  }
  return out;
}

}  // namespace

ProfilePoint ProfileSegment::at(double u) const {
  if (!isArc)
    return {from.axial + u * (to.axial - from.axial), from.radial + u * (to.radial - from.radial)};
  const double a = startAngle + u * sweepAngle;
  return {centre.axial + arcRadius * std::cos(a), centre.radial + arcRadius * std::sin(a)};
}

double ToolProfile::radiusAt(double axial) const {
  double best = 0.0;
  for (const ProfileSegment& s : segments) {
    if (!s.isArc) {
      const double lo = std::min(s.from.axial, s.to.axial), hi = std::max(s.from.axial, s.to.axial);
      if (axial < lo || axial > hi) continue;
      const double u = hi > lo ? (axial - s.from.axial) / (s.to.axial - s.from.axial) : 0.0;
      best = std::max({best, s.at(u).radial, hi > lo ? 0.0 : std::max(s.from.radial, s.to.radial)});
      continue;
    }
    const double d = axial - s.centre.axial;
    if (std::abs(d) > s.arcRadius) continue;
    const double up = std::sqrt(s.arcRadius * s.arcRadius - d * d);
    for (const double r : {s.centre.radial + up, s.centre.radial - up})
      if (inSweep(s, std::atan2(r - s.centre.radial, d))) best = std::max(best, r);
  }
  return best;
}

std::pair<double, double> ToolProfile::axialRange() const {
  double lo = INFINITY, hi = -INFINITY;
  for (const ProfileSegment& s : segments) {
    lo = std::min({lo, s.from.axial, s.to.axial});
    hi = std::max({hi, s.from.axial, s.to.axial});
    if (s.isArc && inSweep(s, 0.0)) hi = std::max(hi, s.centre.axial + s.arcRadius);
    if (s.isArc && inSweep(s, kPi)) lo = std::min(lo, s.centre.axial - s.arcRadius);
  }
  return {lo, hi};
}

double ToolProfile::maxRadius() const {
  double best = 0.0;
  for (const ProfileSegment& s : segments) {
    best = std::max({best, s.from.radial, s.to.radial});
    if (s.isArc && inSweep(s, 0.5 * kPi)) best = std::max(best, s.centre.radial + s.arcRadius);
  }
  return best;
}

ToolProfile toolProfile(const Tool& tool) {
  validateTool(tool);
  const double r = tool.radiusMm;
  switch (tool.kind) {
    case ToolKind::CylinderRoll:
    case ToolKind::BeltContactWheel:
      return {RevolveAxis::X, wheelSegments(tool)};
    case ToolKind::Sphere:
      return {RevolveAxis::Z,
              {arc({0.0, 0.0}, r, kPi, -0.5 * kPi), arc({0.0, 0.0}, r, 0.5 * kPi, -0.5 * kPi)}};
    case ToolKind::BallEnd:
      return {RevolveAxis::Z, cutterSegments(r, r, tool.widthMm)};
    case ToolKind::FlatEnd:
      return {RevolveAxis::Z, cutterSegments(r, 0.0, tool.widthMm)};
    case ToolKind::TorusCutter:
      return {RevolveAxis::Z, cutterSegments(r, tool.edgeRadiusMm, tool.widthMm)};
  }
  throw InvalidInput("tool '" + tool.name + "': unknown tool kind");  // validateTool rejects it
}

std::vector<ToolProfile> nonCuttingProfiles(const Tool& tool) {
  validateTool(tool);
  const Tool& t = tool;
  if (t.kind == ToolKind::Sphere) return {};
  if (t.kind == ToolKind::CylinderRoll || t.kind == ToolKind::BeltContactWheel) {
    const double h = 0.5 * t.widthMm;
    return steppedProfiles({{-h - t.shankLengthMm, -h, t.shankRadiusMm},
                            {-h - t.holderLengthMm, -h, t.holderRadiusMm},
                            {h, h + t.shankLengthMm, t.shankRadiusMm},
                            {h, h + t.holderLengthMm, t.holderRadiusMm}},
                           RevolveAxis::X);
  }
  const double top = t.widthMm + t.shankLengthMm;
  return steppedProfiles(
      {{t.widthMm, top, t.shankRadiusMm}, {top, top + t.holderLengthMm, t.holderRadiusMm}},
      RevolveAxis::Z);
}

namespace {

/// Appends the points of arc @p s after its start, in pieces that meet both limits.
void sampleArc(const ProfileSegment& s, double tolerance, double maxStep,
               std::vector<ProfilePoint>& out) {
  // Sagitta rho (1 - cos(step / 2)) <= tolerance.
  const double byChord =
      tolerance > 0.0 ? 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance / s.arcRadius)) : INFINITY;
  const double step = std::min(byChord, maxStep > 0.0 ? maxStep : INFINITY);
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(s.sweepAngle) / step - 1e-9)));
  for (int i = 1; i < n; ++i) out.push_back(s.at(static_cast<double>(i) / n));
  out.push_back(s.to);
}

}  // namespace

std::vector<ProfilePoint> sampleProfile(const ToolProfile& profile, double chordToleranceMm,
                                        double maxArcStepRad) {
  if (!(chordToleranceMm > 0.0) && !(maxArcStepRad > 0.0))
    throw InvalidInput("profile sampling needs a chord tolerance or an angular step");
  std::vector<ProfilePoint> out;
  for (const ProfileSegment& s : profile.segments) {
    if (out.empty()) out.push_back(s.from);
    if (!s.isArc) {
      out.push_back(s.to);
      continue;
    }
    // Split at the crest (angle pi / 2) so the largest radius is a vertex.
    const double crest = 0.5 * kPi;
    const double end = s.startAngle + s.sweepAngle;
    if (inSweep(s, crest) && std::abs(crest - s.startAngle) > 1e-12 &&
        std::abs(crest - end) > 1e-12) {
      const double first = crest - s.startAngle;
      sampleArc(arc(s.centre, s.arcRadius, s.startAngle, first), chordToleranceMm, maxArcStepRad,
                out);
      out.back() = {s.centre.axial, s.centre.radial + s.arcRadius};
      sampleArc(arc(s.centre, s.arcRadius, crest, s.sweepAngle - first), chordToleranceMm,
                maxArcStepRad, out);
    } else {
      sampleArc(s, chordToleranceMm, maxArcStepRad, out);
    }
    out.back() = s.to;  // exact end, the next segment's start
  }
  return out;
}

int segmentsForChordTolerance(double radiusMm, double chordToleranceMm, int maxSegments) {
  if (!(radiusMm > 0.0) || !(chordToleranceMm > 0.0))
    throw InvalidInput("facet count: radius and chord tolerance must be positive");
  const double x = 1.0 - chordToleranceMm / radiusMm;
  int s = 8;
  if (x > -1.0) {
    const double needed = kPi / std::acos(x);
    if (!(needed < maxSegments))
      throw InvalidInput("a chord tolerance of " + std::to_string(chordToleranceMm) +
                         " mm at radius " + std::to_string(radiusMm) + " mm needs more than " +
                         std::to_string(maxSegments) + " facets");
    s = std::max(8, 4 * static_cast<int>(std::ceil(needed / 4.0 - 1e-12)));
  }
  if (s > maxSegments)
    throw InvalidInput("a chord tolerance of " + std::to_string(chordToleranceMm) +
                       " mm at radius " + std::to_string(radiusMm) + " mm needs " +
                       std::to_string(s) + " facets, more than " + std::to_string(maxSegments));
  return s;
}

}  // namespace ddfcam::planning
