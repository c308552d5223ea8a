// SPDX-License-Identifier: MIT
// ddfcam: validation of stored tool descriptions and the meshes of their two parts.
#include <ddfcam/error.h>
#include <ddfcam/planning/tools/revolved_mesh.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/planning/tools/tool_profiles.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <utility>

namespace ddfcam::planning {
namespace {

// Bounds the mesh a hostile or mistyped project file can make us build (a 4096-segment ball
// already has 16.8 million triangles).
constexpr int kMaxSegments = 4096;

constexpr std::array<std::pair<ToolKind, std::string_view>, 6> kKindNames{{
    {ToolKind::CylinderRoll, "cylinder_roll"},
    {ToolKind::Sphere, "sphere"},
    {ToolKind::BeltContactWheel, "belt_contact_wheel"},
    {ToolKind::BallEnd, "ball_end"},
    {ToolKind::FlatEnd, "flat_end"},
    {ToolKind::TorusCutter, "torus_cutter"},
}};

[[noreturn]] void rejectTool(const Tool& tool, const std::string& why) {
  throw InvalidInput("tool '" + tool.name + "': " + why);
}

/// Shortest text that reads back to @p v, locale independent ("2.5", "1e-06").
std::string num(double v) {
  std::array<char, 32> buf{};
  const auto end = std::to_chars(buf.data(), buf.data() + buf.size(), v).ptr;
  return std::string(buf.data(), end);
}

bool isWheel(ToolKind kind) {
  return kind == ToolKind::CylinderRoll || kind == ToolKind::BeltContactWheel;
}

void checkFinite(const Tool& t) {
  const std::pair<double, const char*> fields[] = {{t.radiusMm, "radius"},
                                                   {t.widthMm, "width"},
                                                   {t.edgeRadiusMm, "edge radius"},
                                                   {t.crownRadiusMm, "crown radius"},
                                                   {t.shankRadiusMm, "shank radius"},
                                                   {t.shankLengthMm, "shank length"},
                                                   {t.holderRadiusMm, "holder radius"},
                                                   {t.holderLengthMm, "holder length"},
                                                   {t.chordToleranceMm, "chord tolerance"}};
  for (const auto& [value, what] : fields) {
    if (!std::isfinite(value)) rejectTool(t, std::string(what) + " is not a finite number");
  }
  // Width, edge and crown are checked by kind (a ball ignores them).
  for (const auto& [value, what] : std::span(fields).subspan(4)) {
    if (value < 0.0) rejectTool(t, std::string(what) + " " + num(value) + " mm is negative");
  }
}

void checkWheel(const Tool& t) {
  const double h = 0.5 * t.widthMm, e = t.edgeRadiusMm, c = t.crownRadiusMm;
  if (e < 0.0) rejectTool(t, "edge radius " + num(e) + " mm is negative");
  if (c < 0.0) rejectTool(t, "crown radius " + num(c) + " mm is negative");
  if (e > h)
    rejectTool(t, "edge radius " + num(e) + " mm exceeds half the width (" + num(h) + " mm)");
  if (c > 0.0 && c < h)
    rejectTool(t, "crown radius " + num(c) + " mm is below half the width (" + num(h) +
                      " mm; 0 means no crown)");
  if (c > 0.0 && e >= c)
    rejectTool(t, "edge radius " + num(e) + " mm is not below the crown radius " + num(c) + " mm");
  // Height of the side face: where the rim fillet (or the crown) meets it.
  const double side =
      c > 0.0 ? t.radiusMm - c + std::sqrt((c - e) * (c - e) - (h - e) * (h - e)) : t.radiusMm - e;
  if (!(side > 0.0))
    rejectTool(t, (c > 0.0 ? "crown radius " + num(c) : "edge radius " + num(e)) +
                      " mm is too large for the radius " + num(t.radiusMm) +
                      " mm: the rim would reach the axis");
  if (t.holderRadiusMm >= t.radiusMm)
    rejectTool(t, "holder (flange) radius " + num(t.holderRadiusMm) +
                      " mm is not below the radius " + num(t.radiusMm) + " mm");
}

void checkShape(const Tool& t) {
  if (!(t.radiusMm > 0.0)) rejectTool(t, "radius " + num(t.radiusMm) + " mm is not positive");
  if (t.kind == ToolKind::Sphere) return;
  if (!(t.widthMm > 0.0)) rejectTool(t, "width " + num(t.widthMm) + " mm is not positive");
  if (isWheel(t.kind)) {
    checkWheel(t);
  } else if (t.kind == ToolKind::BallEnd && t.widthMm < t.radiusMm) {
    rejectTool(
        t, "width " + num(t.widthMm) + " mm is below the ball radius " + num(t.radiusMm) + " mm");
  } else if (t.kind == ToolKind::TorusCutter) {
    const double e = t.edgeRadiusMm;
    if (!(e > 0.0) || !(e < t.radiusMm))
      rejectTool(t, "edge (corner) radius " + num(e) + " mm is not between 0 and the radius " +
                        num(t.radiusMm) + " mm");
    if (t.widthMm < e)
      rejectTool(t, "width " + num(t.widthMm) + " mm is below the corner radius " + num(e) + " mm");
  }
}

void checkFacets(const Tool& t) {
  if (!(t.chordToleranceMm > 0.0))
    rejectTool(t, "chord tolerance " + num(t.chordToleranceMm) + " mm is not positive");
  const int least = t.kind == ToolKind::Sphere ? 4 : 3;
  if (t.segments != 0 && (t.segments < least || t.segments > kMaxSegments))
    rejectTool(t, std::to_string(t.segments) + " segments, 0 or " + std::to_string(least) + ".." +
                      std::to_string(kMaxSegments) + " are allowed");
  if (t.segments == 0) {
    try {
      segmentsForChordTolerance(t.radiusMm, 0.5 * t.chordToleranceMm, kMaxSegments);
    } catch (const InvalidInput&) {
      rejectTool(t, "chord tolerance " + num(t.chordToleranceMm) + " mm needs more than " +
                        std::to_string(kMaxSegments) + " segments at the radius " +
                        num(t.radiusMm) + " mm");
    }
  }
}

/// Facets around for a solid of largest radius @p radius: the tool's count, or from the
/// tolerance (half of it; the other half goes to the profile arcs). Non-cutting parts larger
/// than the cutting part are capped at kMaxSegments rather than rejected.
int facetsFor(const Tool& t, double radius) {
  if (t.segments > 0) return t.segments;
  try {
    return segmentsForChordTolerance(radius, 0.5 * t.chordToleranceMm, kMaxSegments);
  } catch (const InvalidInput&) {
    return kMaxSegments;
  }
}

ddf::TriangleMesh revolveTool(const Tool& t, const ToolProfile& profile) {
  const int s = facetsFor(t, profile.maxRadius());
  const std::vector<ProfilePoint> points =
      t.segments > 0 ? sampleProfile(profile, 0.0, 2.0 * std::numbers::pi / s)
                     : sampleProfile(profile, 0.5 * t.chordToleranceMm, 0.0);
  return revolveProfile(points, profile.axis, s);
}

}  // namespace

std::string_view toolKindName(ToolKind kind) {
  for (const auto& [k, name] : kKindNames)
    if (k == kind) return name;
  return "unknown";
}

std::optional<ToolKind> toolKindFromName(std::string_view name) {
  for (const auto& [k, n] : kKindNames)
    if (n == name) return k;
  return std::nullopt;
}

// The generators' own messages speak of rings and profiles the user never set; checking here
// lets the message name the tool and its fields.
void validateTool(const Tool& tool) {
  if (toolKindName(tool.kind) == "unknown")
    rejectTool(tool, "unknown tool kind " + std::to_string(static_cast<int>(tool.kind)));
  checkFinite(tool);
  checkShape(tool);
  checkFacets(tool);
}

ddf::TriangleMesh toolMesh(const Tool& tool) {
  validateTool(tool);
  // Format-2 projects and the benchmarks count on the UV sphere's layout.
  if (tool.kind == ToolKind::Sphere && tool.segments > 0)
    return makeSphereTool(tool.radiusMm, tool.segments / 2, tool.segments);
  return revolveTool(tool, toolProfile(tool));
}

ToolMeshes toolMeshes(const Tool& tool) {
  ToolMeshes out{toolMesh(tool), {}};
  for (const ToolProfile& profile : nonCuttingProfiles(tool))
    appendMesh(out.nonCutting, revolveTool(tool, profile));
  return out;
}

}  // namespace ddfcam::planning
