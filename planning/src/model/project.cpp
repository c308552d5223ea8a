// SPDX-License-Identifier: MIT
// ddfcam: invariants and exact equality of the workbench document.
#include <ddfcam/error.h>
#include <ddfcam/planning/model/project.h>

#include "bitwise_equality.h"

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <type_traits>

namespace ddfcam::planning {
namespace {

using detail::sameBits;
using detail::sameEach;
using detail::sameOptional;

std::string quoted(const std::string& kind, const std::string& name) {
  return kind + " '" + name + "'";
}

void checkLayout(const std::string& item, std::size_t count, std::size_t expected) {
  if (count != expected)
    throw InvalidInput(item + ": " + std::to_string(count) + " values, expected " +
                       std::to_string(expected));
}

void checkRegion(const Region& region, int faceCount) {
  for (std::size_t i = 0; i < region.faces.size(); ++i) {
    const int f = region.faces[i];
    if (f < 0 || f >= faceCount)
      throw InvalidInput(quoted("region", region.name) + ": face " + std::to_string(f) +
                         " out of range [0, " + std::to_string(faceCount) + ")");
    if (i > 0 && f <= region.faces[i - 1])
      throw InvalidInput(quoted("region", region.name) + ": face " + std::to_string(f) +
                         " at position " + std::to_string(i) + " is not above its predecessor " +
                         std::to_string(region.faces[i - 1]) +
                         " (faces must be ascending, unique)");
  }
}

bool finiteVec(const ddf::Vec3& v) {
  return v.allFinite();
}

std::string text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void checkPlanEnums(const RegionPlan& plan, const std::string& item) {
  const int source = static_cast<int>(plan.flowSource);
  if (source < 0 || source > static_cast<int>(FlowFieldSource::UserStrokes))
    throw InvalidInput(item + ": unknown flow field source " + std::to_string(source));
  const int spacing = static_cast<int>(plan.spacingMode);
  if (spacing < 0 || spacing > static_cast<int>(SpacingMode::ScallopTolerance))
    throw InvalidInput(item + ": unknown spacing mode " + std::to_string(spacing));
  const int linking = static_cast<int>(plan.linking);
  if (linking < 0 || linking > static_cast<int>(LinkingOrder::OneDirection))
    throw InvalidInput(item + ": unknown linking order " + std::to_string(linking));
}

void checkPlanGeometry(const RegionPlan& plan, const std::string& item) {
  if (!finiteVec(plan.fixedDirection) || plan.fixedDirection.squaredNorm() == 0.0)
    throw InvalidInput(item + ": the fixed flow direction must be finite and non-zero");
  for (std::size_t s = 0; s < plan.strokes.size(); ++s)
    for (std::size_t p = 0; p < plan.strokes[s].size(); ++p)
      if (!finiteVec(plan.strokes[s][p]))
        throw InvalidInput(item + ": stroke " + std::to_string(s) + " point " + std::to_string(p) +
                           " is not finite");
}

void checkPlan(const RegionPlan& plan, const std::string& regionItem, std::size_t toolCount) {
  const std::string item = regionItem + " plan";
  if (plan.tool < -1 || (plan.tool >= 0 && static_cast<std::size_t>(plan.tool) >= toolCount))
    throw InvalidInput(item + ": tool index " + std::to_string(plan.tool) + " out of range (" +
                       std::to_string(toolCount) + " tools; -1 for none)");
  checkPlanEnums(plan, item);
  checkPlanGeometry(plan, item);
  if (!(plan.smoothnessWeight >= 0.0) || !std::isfinite(plan.smoothnessWeight))
    throw InvalidInput(item + ": smoothness weight " + text(plan.smoothnessWeight) +
                       " must be finite and >= 0");
  if (!(plan.spacingMm > 0.0) || !std::isfinite(plan.spacingMm))
    throw InvalidInput(item + ": spacing " + text(plan.spacingMm) + " mm must be finite and > 0");
  if (!(plan.scallopToleranceMm > 0.0) || !std::isfinite(plan.scallopToleranceMm))
    throw InvalidInput(item + ": scallop tolerance " + text(plan.scallopToleranceMm) +
                       " mm must be finite and > 0");
  if (plan.feedSign != 1 && plan.feedSign != -1)
    throw InvalidInput(item + ": feed sign " + std::to_string(plan.feedSign) + " must be +1 or -1");
}

void checkLinkedIdle(const ToolPath& path) {
  if (path.linkedIdleMm && (!std::isfinite(*path.linkedIdleMm) || *path.linkedIdleMm < 0.0))
    throw InvalidInput(quoted("path", path.name) + ": linked idle length " +
                       text(*path.linkedIdleMm) + " mm must be finite and >= 0");
}

void checkPath(const ToolPath& path, std::size_t toolCount) {
  const std::string item = quoted("path", path.name);
  if (path.tool < 0 || static_cast<std::size_t>(path.tool) >= toolCount)
    throw InvalidInput(item + ": tool index " + std::to_string(path.tool) + " out of range (" +
                       std::to_string(toolCount) + " tools)");
  const int poses = static_cast<int>(path.poses.size());
  if (poses > 0 && (path.passStarts.empty() || path.passStarts.front() != 0))
    throw InvalidInput(item + ": the first pass must start at pose 0");
  for (std::size_t i = 0; i < path.passStarts.size(); ++i) {
    const int s = path.passStarts[i];
    if (s < 0 || s >= poses)
      throw InvalidInput(item + ": pass start " + std::to_string(s) + " out of range (" +
                         std::to_string(poses) + " poses)");
    if (i > 0 && s <= path.passStarts[i - 1])
      throw InvalidInput(item + ": pass start " + std::to_string(s) + " at position " +
                         std::to_string(i) + " is not above its predecessor (must ascend)");
  }
  checkLinkedIdle(path);
}

// The raw lines are read back onto the part (smoothing, fairing): their faces must exist.
void checkRawLines(const ToolPath& path, int faceCount) {
  for (std::size_t l = 0; l < path.rawLines.size(); ++l) {
    const Streamline& line = path.rawLines[l];
    const std::string item = quoted("path", path.name) + ": raw line " + std::to_string(l);
    if (!line.points.empty() && line.seedIndex >= line.points.size())
      throw InvalidInput(item + ": seed index " + std::to_string(line.seedIndex) +
                         " out of range (" + std::to_string(line.points.size()) + " points)");
    for (const int stop : {static_cast<int>(line.stop), static_cast<int>(line.backwardStop)})
      if (stop < 0 || stop > static_cast<int>(Streamline::MaxLength))
        throw InvalidInput(item + ": unknown stop reason " + std::to_string(stop));
    for (std::size_t i = 0; i < line.points.size(); ++i) {
      const ddf::SurfaceLocation& p = line.points[i];
      if (p.face < 0 || p.face >= faceCount)
        throw InvalidInput(item + ": point " + std::to_string(i) + " on face " +
                           std::to_string(p.face) + " out of range [0, " +
                           std::to_string(faceCount) + ")");
      if (!finiteVec(p.bary) || !finiteVec(p.point) || !std::isfinite(p.h))
        throw InvalidInput(item + ": point " + std::to_string(i) + " is not finite");
    }
  }
}

void checkMesh(const ddf::TriangleMesh& mesh) {
  const int n = static_cast<int>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int v : mesh.triangles[t])
      if (v < 0 || v >= n)
        throw InvalidInput("design mesh: triangle " + std::to_string(t) + " references vertex " +
                           std::to_string(v) + " of " + std::to_string(n));
}

// Items that only make sense on a part: report the first one present.
void checkNeedsPart(const Project& project) {
  if (!project.fields.empty())
    throw InvalidInput(quoted("field", project.fields.front().name) + " without a part");
  if (!project.states.empty())
    throw InvalidInput(quoted("state", project.states.front().name) + " without a part");
  if (!project.regions.empty())
    throw InvalidInput(quoted("region", project.regions.front().name) + " without a part");
}

void checkPartItems(const Project& project) {
  const ddf::DisplacementField& part = *project.part;
  const std::size_t values = part.allHeights().size();
  for (const ScalarField& field : project.fields)
    checkLayout(quoted("field", field.name), field.values.size(), values);
  for (const SimulationState& state : project.states)
    checkLayout(quoted("state", state.name), state.heights.size(), values);
  for (const Region& region : project.regions) {
    checkRegion(region, part.faceCount());
    checkPlan(region.plan, quoted("region", region.name), project.tools.size());
  }
  for (const ToolPath& path : project.paths) checkRawLines(path, part.faceCount());
}

bool sameMesh(const ddf::TriangleMesh& a, const ddf::TriangleMesh& b) {
  return triangleMeshesEqual(a, b);
}

bool sameDdf(const ddf::DisplacementField& a, const ddf::DisplacementField& b) {
  return displacementFieldsEqual(a, b);
}

bool sameTool(const Tool& a, const Tool& b) {
  return a.name == b.name && a.kind == b.kind && sameBits(a.radiusMm, b.radiusMm) &&
         sameBits(a.widthMm, b.widthMm) && a.segments == b.segments;
}

bool samePose(const PathPose& a, const PathPose& b) {
  return sameBits(a.pose.matrix().data(), b.pose.matrix().data(), 16) &&
         sameBits(a.contact, b.contact);
}

bool sameLocation(const ddf::SurfaceLocation& a, const ddf::SurfaceLocation& b) {
  return a.face == b.face && sameBits(a.bary, b.bary) && sameBits(a.h, b.h) &&
         sameBits(a.point, b.point);
}

bool sameLine(const Streamline& a, const Streamline& b) {
  return a.stop == b.stop && a.backwardStop == b.backwardStop && a.seedIndex == b.seedIndex &&
         sameBits(a.lengthMm, b.lengthMm) && sameEach(a.points, b.points, sameLocation);
}

bool samePath(const ToolPath& a, const ToolPath& b) {
  return a.name == b.name && a.tool == b.tool && sameBits(a.feedMmPerMin, b.feedMmPerMin) &&
         a.passStarts == b.passStarts && sameEach(a.poses, b.poses, samePose) &&
         sameEach(a.rawLines, b.rawLines, sameLine) &&
         sameOptional(a.linkedIdleMm, b.linkedIdleMm,
                      [](double x, double y) { return sameBits(x, y); });
}

bool sameField(const ScalarField& a, const ScalarField& b) {
  return a.name == b.name && a.unit == b.unit && a.isSigned == b.isSigned &&
         sameBits(a.values, b.values) && a.heightsDigest == b.heightsDigest;
}

bool sameStroke(const std::vector<ddf::Vec3>& a, const std::vector<ddf::Vec3>& b) {
  return sameEach(a, b, [](const ddf::Vec3& p, const ddf::Vec3& q) { return sameBits(p, q); });
}

bool samePlan(const RegionPlan& a, const RegionPlan& b) {
  return a.tool == b.tool && a.flowSource == b.flowSource &&
         sameBits(a.fixedDirection, b.fixedDirection) &&
         sameEach(a.strokes, b.strokes, sameStroke) && a.smoothField == b.smoothField &&
         sameBits(a.smoothnessWeight, b.smoothnessWeight) && a.spacingMode == b.spacingMode &&
         sameBits(a.spacingMm, b.spacingMm) &&
         sameBits(a.scallopToleranceMm, b.scallopToleranceMm) && a.feedSign == b.feedSign &&
         a.linking == b.linking;
}

bool sameRegion(const Region& a, const Region& b) {
  return a.name == b.name && a.faces == b.faces &&
         sameBits(a.color.data(), b.color.data(), a.color.size()) && samePlan(a.plan, b.plan);
}

bool sameState(const SimulationState& a, const SimulationState& b) {
  return a.name == b.name && sameBits(a.heights, b.heights);
}

bool sameSurface(const NamedSurface& a, const NamedSurface& b) {
  return a.name == b.name && sameDdf(a.ddf, b.ddf);
}

}  // namespace

void validateProject(const Project& project) {
  if (project.part)
    checkPartItems(project);
  else
    checkNeedsPart(project);
  if (project.designMesh) checkMesh(*project.designMesh);
  for (const Tool& tool : project.tools) validateTool(tool);
  for (const ToolPath& path : project.paths) checkPath(path, project.tools.size());
  if (project.mould) validateMouldStudy(*project.mould);
}

bool projectsEqual(const Project& a, const Project& b) {
  return a.partName == b.partName && a.sourcePath == b.sourcePath && a.sourceUnit == b.sourceUnit &&
         a.cadFaceOfSupportFace == b.cadFaceOfSupportFace && a.cadFaceNames == b.cadFaceNames &&
         sameOptional(a.part, b.part, sameDdf) &&
         sameOptional(a.designMesh, b.designMesh, sameMesh) &&
         sameEach(a.fields, b.fields, sameField) && sameEach(a.regions, b.regions, sameRegion) &&
         sameEach(a.tools, b.tools, sameTool) && sameEach(a.paths, b.paths, samePath) &&
         sameEach(a.states, b.states, sameState) && sameEach(a.surfaces, b.surfaces, sameSurface) &&
         sameOptional(a.mould, b.mould, mouldStudiesEqual);
}

}  // namespace ddfcam::planning
