// SPDX-License-Identifier: MIT
// ddfcam: the planning tool an APT cutter record describes (the inverse of aptCutter()).
#include <ddfcam/error.h>
#include <ddfcam/io/programs/cutter_tool.h>

#include <cmath>

namespace ddfcam::io {

planning::Tool toolFromCutter(const ClCutter& c, const std::string& name) {
  const double radius = 0.5 * c.diameterMm;
  if (!(radius > 0.0) || !(c.cornerRadiusMm >= 0.0) || c.cornerRadiusMm > radius + 1e-9)
    throw InvalidInput("CUTTER/" + std::to_string(c.diameterMm) + "," +
                       std::to_string(c.cornerRadiusMm) + " gives no usable tool");
  planning::Tool tool;
  tool.name = name.empty() ? "imported cutter" : name;
  tool.radiusMm = radius;
  tool.widthMm = c.heightMm > 0.0 ? c.heightMm : 2.0 * c.diameterMm;
  const double tolerance = 1e-6 * radius;
  if (std::abs(c.cornerRadiusMm - radius) <= tolerance) {
    tool.kind = planning::ToolKind::BallEnd;
  } else if (c.cornerRadiusMm <= tolerance) {
    tool.kind = planning::ToolKind::FlatEnd;
  } else {
    tool.kind = planning::ToolKind::TorusCutter;
    tool.edgeRadiusMm = c.cornerRadiusMm;
  }
  planning::validateTool(tool);
  return tool;
}

}  // namespace ddfcam::io
