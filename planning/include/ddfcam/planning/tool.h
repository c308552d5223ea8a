// SPDX-License-Identifier: MIT
// ddfcam: a grinding tool as the workbench stores it (shape parameters) and its cutting mesh.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <string>

namespace ddfcam::planning {

/// @brief Shapes of tools the workbench knows.
enum class ToolKind {
  CylinderRoll = 0,  ///< cylindrical roll, axis along tool +x, centred at the origin
  Sphere = 1,        ///< ball (ball-end head), centred at the origin
};

/// @brief A named tool: its shape and size. The cutting mesh is derived (toolMesh()).
struct Tool {
  std::string name = "roll R5 W10";        ///< shown in lists and files (default "roll R5 W10")
  ToolKind kind = ToolKind::CylinderRoll;  ///< shape (default cylindrical roll)
  double radiusMm = 5.0;                   ///< roll or ball radius, mm (default 5)
  double widthMm = 10.0;  ///< roll width along its axis, mm; unused for a ball (default 10)
  /// Facets around the circumference (default 48: a multiple of 4 puts mesh vertices on the
  /// roll's lowest line, so the mesh cuts as deep as the round roll it stands for).
  int segments = 48;

  bool operator==(const Tool&) const = default;
};

/// @brief Checks that @p tool describes a buildable shape: radius > 0, for a roll width > 0
/// and at least 3 segments, for a ball at least 4 segments, at most 4096 segments (bounds the
/// mesh a project file can ask for), and a known kind.
/// @throws InvalidInput naming the tool and the offending field.
void validateTool(const Tool& tool);

/// @brief The closed triangle mesh of @p tool in its own frame (see ToolKind), for the depth
/// buffer and for display: makeCylinderTool / makeSphereTool (rings = segments / 2).
/// A roll has 4 segments triangles, a ball 2 segments (segments / 2 - 1).
/// @throws InvalidInput as validateTool().
ddf::TriangleMesh toolMesh(const Tool& tool);

}  // namespace ddfcam::planning
