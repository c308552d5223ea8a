// SPDX-License-Identifier: MIT
// ddfcam: the cutting mesh of a stored tool description.
#include <ddfcam/error.h>
#include <ddfcam/planning/tool.h>
#include <ddfcam/planning/tool_shapes.h>

#include <string>

namespace ddfcam::planning {
namespace {

// Bounds the mesh a hostile or mistyped project file can make us build (a 4096-segment ball
// already has 16.8 million triangles).
constexpr int kMaxSegments = 4096;

[[noreturn]] void rejectTool(const Tool& tool, const std::string& why) {
  throw InvalidInput("tool '" + tool.name + "': " + why);
}

}  // namespace

// The generators' own messages speak of rings and parameters the user never set; checking here
// lets the message name the tool and its fields.
void validateTool(const Tool& tool) {
  if (!(tool.radiusMm > 0.0))
    rejectTool(tool, "radius " + std::to_string(tool.radiusMm) + " mm is not positive");
  if (tool.kind == ToolKind::CylinderRoll) {
    if (!(tool.widthMm > 0.0))
      rejectTool(tool, "width " + std::to_string(tool.widthMm) + " mm is not positive");
    if (tool.segments < 3)
      rejectTool(tool, std::to_string(tool.segments) + " segments, a roll needs at least 3");
  } else if (tool.kind == ToolKind::Sphere) {
    if (tool.segments < 4)
      rejectTool(tool, std::to_string(tool.segments) + " segments, a ball needs at least 4");
  } else {
    rejectTool(tool, "unknown tool kind " + std::to_string(static_cast<int>(tool.kind)));
  }
  if (tool.segments > kMaxSegments)
    rejectTool(tool, std::to_string(tool.segments) + " segments, at most " +
                         std::to_string(kMaxSegments) + " are allowed");
}

ddf::TriangleMesh toolMesh(const Tool& tool) {
  validateTool(tool);
  if (tool.kind == ToolKind::Sphere)
    return makeSphereTool(tool.radiusMm, tool.segments / 2, tool.segments);
  return makeCylinderTool({tool.radiusMm, tool.widthMm, tool.segments});
}

}  // namespace ddfcam::planning
