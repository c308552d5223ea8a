// SPDX-License-Identifier: MIT
// ddfcam: placing a cutter-location program read from a file on a part as a ToolPath.
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/imported_path.h>
#include <ddfcam/planning/placement/path_sampling.h>
#include <ddfcam/planning/placement/tool_orientation.h>
#include <ddfcam/planning/surface/mesh_distance.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>

#include "imported_path_contacts.h"
#include "imported_path_convention.h"

namespace ddfcam::planning {
namespace {

using ddf::Vec3;
using detail::contactOf;
using detail::coreSamples;
using detail::feedAt;
using detail::isCutter;
using detail::isWheel;
using detail::PartSurface;
using detail::perpendicularTo;
using detail::PlacedPoint;
using detail::PoseContact;
using detail::tangentialFeed;

Vec3 spindleInToolFrame(ToolKind kind) {
  return isCutter(kind) ? Vec3::UnitZ() : Vec3::UnitX();
}

std::string where(const ClProgram& program, int i) {
  const int line = program.points[static_cast<std::size_t>(i)].sourceLine;
  std::string s = "point " + std::to_string(i);
  if (line > 0) s += " (line " + std::to_string(line) + ")";
  return s;
}

std::string number(double v) {
  std::ostringstream out;
  out << v;  // 6 significant digits, "2" rather than "2.000000"
  return out.str();
}

Vec3 unitOrThrow(const Vec3& v, const std::string& what) {
  const double n = v.norm();
  if (!v.allFinite() || !(n > 1e-12)) throw InvalidInput("placing a program: " + what);
  return v / n;
}

void validate(const ClProgram& program, const Tool& tool, const PlaceProgramParams& params) {
  validateTool(tool);
  if (program.points.empty()) throw InvalidInput("placing a program: the program has no points");
  const Eigen::Matrix3d r = params.transform.linear();
  if (!params.transform.matrix().allFinite())
    throw InvalidInput("placing a program: the transform is not finite");
  if (!(r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-9) || r.determinant() < 0)
    throw InvalidInput(
        "placing a program: the transform is not a rigid motion (rotation and "
        "translation)");
  unitOrThrow(params.defaultAxis, "the default axis is zero or not finite");
  if (!std::isfinite(params.contactSearchMm) || !(params.contactSearchMm > 0))
    throw InvalidInput("placing a program: contact search distance " +
                       number(params.contactSearchMm) + " mm is not positive");
  if (!std::isfinite(params.gougeWarnMm) || !(params.gougeWarnMm > 0))
    throw InvalidInput("placing a program: gouge warning depth " + number(params.gougeWarnMm) +
                       " mm is not positive");
  if (!std::isfinite(params.angleSnapDeg) || params.angleSnapDeg < 0)
    throw InvalidInput("placing a program: angle snap " + number(params.angleSnapDeg) +
                       " deg is negative");
  if (params.toolIndex < 0)
    throw InvalidInput("placing a program: tool index " + std::to_string(params.toolIndex) +
                       " is negative");
}

/// Point @p i rescaled and moved into the part frame, with the tool axis in force there
/// (@p axis: its own, else the last one given before it).
PlacedPoint toPartFrame(const ClProgram& program, int i, const Eigen::Isometry3d& transform,
                        double scale, const std::optional<Vec3>& axis) {
  const ClPoint& p = program.points[static_cast<std::size_t>(i)];
  if (!p.positionMm.allFinite())
    throw InvalidInput("placing a program: " + where(program, i) + ": position is not finite");
  PlacedPoint q;
  q.source = i;
  q.position = transform * (scale * p.positionMm);
  if (axis)
    q.axis = transform.linear() *
             unitOrThrow(*axis, where(program, i) + ": tool axis is zero or not finite");
  if (p.normal)
    q.normal = transform.linear() *
               unitOrThrow(*p.normal, where(program, i) + ": normal is zero or not finite");
  return q;
}

/// Keeps the points the params ask for, rescaled and transformed; a pass starts at the first
/// point, after a dropped point, and where a Cut follows a Cut of another program path.
std::vector<PlacedPoint> keptPoints(const ClProgram& program, const PlaceProgramParams& params,
                                    double scale, std::vector<ClMessage>& warnings) {
  std::vector<PlacedPoint> out;
  int dropped = 0, firstDroppedLine = 0;
  bool gap = true;
  const ClPoint* previous = nullptr;
  std::optional<Vec3> axisInForce;  // a point without an axis keeps the last one, as in APT
  for (int i = 0; i < static_cast<int>(program.points.size()); ++i) {
    const ClPoint& p = program.points[static_cast<std::size_t>(i)];
    if (p.axis) axisInForce = p.axis;
    const bool keep = p.move == MoveKind::Cut ||
                      (p.move == MoveKind::Link && params.includeLinks) ||
                      (p.move == MoveKind::Rapid && params.includeRapids);
    if (!keep) {
      if (dropped++ == 0) firstDroppedLine = p.sourceLine;
      gap = true;
      continue;
    }
    PlacedPoint q = toPartFrame(program, i, params.transform, scale, axisInForce);
    q.cut = p.move == MoveKind::Cut;
    q.passStart = gap || (previous && previous->move == MoveKind::Cut && p.move == MoveKind::Cut &&
                          previous->path != p.path);
    out.push_back(q);
    previous = &p;
    gap = false;
  }
  if (dropped > 0)
    warnings.push_back({firstDroppedLine, std::to_string(dropped) +
                                              " link or rapid points left out; the path "
                                              "starts a new pass after each"});
  if (out.empty()) throw InvalidInput("placing a program: no point is left to place");
  return out;
}

struct Reference {
  Vec3 point;
  Vec3 axis;
};

/// Placement parameters and feed that turn @p tool's spindle axis onto @p axis at normal @p n.
std::pair<PlacementParams, Vec3> anglesForAxis(ToolKind kind, const Vec3& n, const Vec3& t,
                                               const Vec3& axis) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  PlacementParams pp;
  if (isWheel(kind)) {
    const Vec3 across = axis - axis.dot(n) * n;
    if (across.norm() < 1e-9) throw InvalidInput("the wheel axis lies along the surface normal");
    pp.tiltDeg = std::asin(std::clamp(axis.dot(n), -1.0, 1.0)) * kDeg;
    return {pp, across.normalized().cross(n)};
  }
  if (kind == ToolKind::Sphere) return {pp, t};
  const Vec3 b = n.cross(t);
  pp.leadDeg = std::asin(std::clamp(axis.dot(t), -1.0, 1.0)) * kDeg;
  pp.tiltDeg = std::atan2(-axis.dot(b), axis.dot(n)) * kDeg;
  return {pp, t};
}

/// Reference point and axis of a Contact point.
Reference contactReference(const Tool& tool, const PartSurface& surface,
                           const std::vector<PlacedPoint>& pts, std::size_t k,
                           const PlaceProgramParams& params, const std::string& name) {
  const PlacedPoint& p = pts[k];
  Vec3 n;
  if (p.normal) {
    n = *p.normal;
  } else if (params.normalsFromPart) {
    n = surface.normal(surface.nearest(p.position));
  } else {
    throw InvalidInput("placing a program: " + name +
                       ": the contact program needs normals (the point has none)");
  }
  const Vec3 hint = p.axis.value_or(perpendicularTo(n));
  const Vec3 t = tangentialFeed(feedAt(pts, k), n, hint);
  PlacementParams pp;
  Vec3 feed = t;
  if (p.axis) std::tie(pp, feed) = anglesForAxis(tool.kind, n, t, *p.axis);
  if (params.contactAngles) {
    pp = *params.contactAngles;
  } else {
    // A flat bottom or a straight mantle touches with its rim at any non-zero angle: rounding
    // noise in axes and normals must not move the reference point by a radius or half a width.
    if (std::abs(pp.leadDeg) < params.angleSnapDeg) pp.leadDeg = 0.0;
    if (std::abs(pp.tiltDeg) < params.angleSnapDeg) pp.tiltDeg = 0.0;
  }
  const ToolPlacement placed = placeToolDetailed(tool, p.position, n, feed, pp);
  const Vec3 axis = placed.pose.linear() * spindleInToolFrame(tool.kind);
  const bool fileAxis = p.axis && tool.kind != ToolKind::Sphere && !params.contactAngles;
  return {placed.pose.translation(), fileAxis ? *p.axis : axis};
}

std::vector<Reference> references(const ClProgram& program, ClPointKind kind, const Tool& tool,
                                  const PartSurface& surface, const std::vector<PlacedPoint>& pts,
                                  const PlaceProgramParams& params) {
  const Vec3 defaultAxis = (params.transform.linear() * params.defaultAxis).normalized();
  std::vector<Reference> out;
  out.reserve(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (kind == ClPointKind::ToolReference) {
      out.push_back({pts[k].position, pts[k].axis.value_or(defaultAxis)});
      continue;
    }
    const std::string name = where(program, pts[k].source);
    try {
      out.push_back(contactReference(tool, surface, pts, k, params, name));
    } catch (const InvalidInput& e) {
      if (std::string(e.what()).starts_with("placing a program")) throw;
      std::throw_with_nested(
          InvalidInput("placing a program: " + name + ": cannot place the tool"));
    }
    if (k % 256 == 255) reportProgress(params.progress, 0.5 * double(k) / double(pts.size()));
  }
  return out;
}

/// Rotations mapping the spindle axis onto each reference axis, carried along by the smallest
/// rotation and re-orthonormalised so the spindle column is the axis to rounding.
std::vector<Eigen::Matrix3d> frames(ToolKind kind, const std::vector<Reference>& refs) {
  std::vector<Eigen::Matrix3d> out;
  out.reserve(refs.size());
  const bool cutter = isCutter(kind);
  const int spin = cutter ? 2 : 0, side = cutter ? 0 : 2;
  Vec3 sideVec = perpendicularTo(refs.front().axis);
  Vec3 previous = refs.front().axis;
  for (const Reference& r : refs) {
    const Vec3 a = r.axis.normalized();
    sideVec = Eigen::Quaterniond::FromTwoVectors(previous, a) * sideVec;
    sideVec = sideVec - sideVec.dot(a) * a;
    sideVec = sideVec.norm() > 1e-6 ? sideVec.normalized() : perpendicularTo(a);
    Eigen::Matrix3d m;
    m.col(spin) = a;
    m.col(side) = sideVec;
    m.col(1) = cutter ? a.cross(sideVec) : sideVec.cross(a);
    out.push_back(m);
    previous = a;
  }
  return out;
}

/// First source points of the off-part and gouging poses, -1 if none.
struct FirstPoints {
  int off = -1;
  int gouge = -1;
};

/// Counts a pose with contact @p c and unit spindle axis @p spindle into the figures of @p out.
void tally(const PoseContact& c, const Vec3& spindle, bool cutter, int source,
           const PlaceProgramParams& params, ImportedPath& out, FirstPoints& first) {
  const double d = c.distanceMm;
  out.maxAbsContactDistanceMm = std::max(out.maxAbsContactDistanceMm, std::abs(d));
  if (std::abs(d) > params.contactSearchMm) {
    if (out.pointsOffPart++ == 0) first.off = source;
  } else {
    out.maxOnPartContactDistanceMm =
        std::max(out.maxOnPartContactDistanceMm.value_or(0.0), std::abs(d));
  }
  // Beside an open part's border "behind" the surface is not inside the material. A cutter's
  // holder on the far side of the surface gouges however its tip touches.
  if (c.beside) return;
  out.maxGougeDepthMm = std::max(out.maxGougeDepthMm, -d);
  if (-d > params.gougeWarnMm || (cutter && spindle.dot(c.normal) < 0.0))
    if (out.gougingPoses++ == 0) first.gouge = source;
}

/// Off-part and gouge warnings and the feed of a placed program.
void summarize(const ClProgram& program, int kept, FirstPoints first, double scale,
               const PlaceProgramParams& params, ImportedPath& out) {
  ToolPath& path = out.path;
  const auto lineOf = [&](int i) { return program.points[static_cast<std::size_t>(i)].sourceLine; };
  if (out.gougingPoses > 0)
    out.warnings.push_back(
        {lineOf(first.gouge),
         std::to_string(out.gougingPoses) + " of " + std::to_string(kept) +
             " poses gouge the part (the tool reaches more than " + number(params.gougeWarnMm) +
             " mm into it, deepest " + number(out.maxGougeDepthMm) +
             " mm, or a cutter's axis points into it; first: " + where(program, first.gouge) +
             "): " + detail::conventionSummary(out.convention) +
             "; another vector or point meaning may fit"});
  if (out.pointsOffPart > 0)
    out.warnings.push_back(
        {lineOf(first.off), std::to_string(out.pointsOffPart) + " of " + std::to_string(kept) +
                                " points lie farther than " + number(params.contactSearchMm) +
                                " mm from the part (first: " + where(program, first.off) + ")"});
  const auto feed =
      std::find_if(program.points.begin(), program.points.end(),
                   [](const ClPoint& p) { return p.move == MoveKind::Cut && p.feedMmPerMin > 0; });
  if (feed != program.points.end()) {
    path.feedMmPerMin = feed->feedMmPerMin * scale;
  } else {
    out.warnings.push_back({0, "the program gives no cutting feed; the path keeps " +
                                   number(path.feedMmPerMin) + " mm/min"});
  }
}

/// A program with tool changes is placed with one tool: say so, naming the tools it has.
ClMessage toolChangeWarning(const ClProgram& program, const Tool& tool) {
  std::string tools = "T" + std::to_string(program.toolNumber);
  for (const ClToolChange& c : program.toolChanges) tools += ", T" + std::to_string(c.toolNumber);
  return {program.toolChanges.front().sourceLine,
          "the program changes tools " + std::to_string(program.toolChanges.size()) + " times (" +
              tools + "); every point is placed and simulated with '" + tool.name +
              "': split the file at its tool changes to check each tool with its own geometry"};
}

}  // namespace

ImportedPath placeProgram(const ClProgram& program, const Tool& tool,
                          const ddf::DisplacementField& part, const PlaceProgramParams& params) {
  validate(program, tool, params);
  ImportedPath out;
  const double scale = params.actualUnit
                           ? millimetresPer(*params.actualUnit) / millimetresPer(program.sourceUnit)
                           : 1.0;
  std::vector<PlacedPoint> pts = keptPoints(program, params, scale, out.warnings);
  if (!program.toolChanges.empty()) out.warnings.push_back(toolChangeWarning(program, tool));
  const PartSurface surface(part);
  out.convention =
      detail::resolveConvention(surface, pts, tool, program.pointKind, params, out.warnings);
  const ClPointKind kind = detail::applyConvention(out.convention, tool, surface, pts);
  const std::vector<Reference> refs = references(program, kind, tool, surface, pts, params);
  const std::vector<Eigen::Matrix3d> rot = frames(tool.kind, refs);
  const auto samples = coreSamples(tool);

  ToolPath& path = out.path;
  path.name = !params.name.empty()        ? params.name
              : !program.partName.empty() ? program.partName
                                          : "imported path";
  path.tool = params.toolIndex;
  FirstPoints first;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    PathPose pose;
    pose.pose.linear() = rot[k];
    pose.pose.translation() = refs[k].point;
    const PoseContact c = contactOf(surface, pose.pose, samples);
    pose.contact = c.point;
    if (pts[k].passStart) path.passStarts.push_back(static_cast<int>(k));
    path.poses.push_back(pose);
    out.normals.push_back(c.normal);
    out.contactDistancesMm.push_back(c.distanceMm);
    out.sourcePoints.push_back(pts[k].source);
    tally(c, rot[k].col(isCutter(tool.kind) ? 2 : 0), isCutter(tool.kind), pts[k].source, params,
          out, first);
    if (k % 256 == 255) reportProgress(params.progress, 0.5 + 0.5 * double(k) / double(pts.size()));
  }
  summarize(program, static_cast<int>(pts.size()), first, scale, params, out);
  reportProgress(params.progress, 1.0);
  return out;
}

}  // namespace ddfcam::planning
