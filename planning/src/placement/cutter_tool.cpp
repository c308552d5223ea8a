// SPDX-License-Identifier: MIT
// ddfcam: APT cutter records of planning tools, and the planning tool a cutter record describes.
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/cutter_tool.h>

#include <cmath>

namespace ddfcam::planning {

ClCutter aptCutter(const Tool& tool) {
  validateTool(tool);
  const double radius = tool.radiusMm;
  double corner = 0.0;
  double height = tool.widthMm;
  switch (tool.kind) {
    case ToolKind::BallEnd:
      corner = radius;
      break;
    case ToolKind::Sphere:
      corner = radius;
      height = 2.0 * radius;
      break;
    case ToolKind::FlatEnd:
      corner = 0.0;
      break;
    case ToolKind::TorusCutter:
    case ToolKind::CylinderRoll:
    case ToolKind::BeltContactWheel:
      corner = tool.edgeRadiusMm;
      break;
  }
  ClCutter cutter;
  cutter.diameterMm = 2.0 * radius;
  cutter.cornerRadiusMm = corner;
  cutter.eMm = radius - corner;
  cutter.fMm = corner;
  cutter.heightMm = height;
  return cutter;
}

Tool toolFromCutter(const ClCutter& c, const std::string& name) {
  const double radius = 0.5 * c.diameterMm;
  if (!(radius > 0.0) || !(c.cornerRadiusMm >= 0.0) || c.cornerRadiusMm > radius + 1e-9)
    throw InvalidInput("CUTTER/" + std::to_string(c.diameterMm) + "," +
                       std::to_string(c.cornerRadiusMm) + " gives no usable tool");
  Tool tool;
  tool.name = name.empty() ? "imported cutter" : name;
  tool.radiusMm = radius;
  tool.widthMm = c.heightMm > 0.0 ? c.heightMm : 2.0 * c.diameterMm;
  const double tolerance = 1e-6 * radius;
  if (std::abs(c.cornerRadiusMm - radius) <= tolerance) {
    tool.kind = ToolKind::BallEnd;
  } else if (c.cornerRadiusMm <= tolerance) {
    tool.kind = ToolKind::FlatEnd;
  } else {
    tool.kind = ToolKind::TorusCutter;
    tool.edgeRadiusMm = c.cornerRadiusMm;
  }
  validateTool(tool);
  return tool;
}

}  // namespace ddfcam::planning
