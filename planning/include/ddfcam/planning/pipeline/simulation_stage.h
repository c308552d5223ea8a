// SPDX-License-Identifier: MIT
// ddfcam: the simulation stage shared by the workbench's Simulation panel and `ddfcam-cli
// simulate`: the contact normals of a placed path, penetration correction and Preston removal
// with them, so the two give the same corrected path and the same removal for the same input.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/placement/penetration_correction.h>
#include <ddfcam/planning/simulation/preston_removal.h>
#include <ddfcam/planning/tools/tool.h>

#include <vector>

namespace ddfcam::planning {

/// @brief #P unit contact normals of @p path on @p surface, each pointing from the surface to
/// the tool: the given normal where there is one (normalized), else the normal of the
/// surface's raster triangle nearest to the contact; either is turned round when it points
/// away from the tool, i.e. from the contact away from the centroid of @p toolMesh's vertices
/// at the pose. A part machined from the side its vectors point away from (a bore) and a file
/// whose vectors point into the material thus both lift and press the tool the right way.
/// @param surface the goal (or current workpiece) surface the contacts lie on, mm.
/// @param toolMesh the cutting mesh in the tool frame (toolMesh()), mm.
/// @param given #P normals, part frame, or empty; a zero or non-finite entry counts as missing.
/// @throws InvalidInput for an empty tool mesh, a given count other than 0 or #P, or a contact
/// without a given normal and with no surface face nearby.
std::vector<ddf::Vec3> contactNormals(const ddf::DisplacementField& surface,
                                      const ddf::TriangleMesh& toolMesh, const ToolPath& path,
                                      const std::vector<ddf::Vec3>& given = {});

/// @brief A path after penetration correction and what the correction did.
struct CorrectedPath {
  ToolPath path;                       ///< the input path with its poses lifted
  PenetrationCorrectionReport report;  ///< lifts and checks per pose
};

/// @brief correctPenetrations() of @p path against @p goal with the cutting mesh of @p tool and
/// the contactNormals() made from params.normals (the given normals, empty for none).
/// @throws InvalidInput as contactNormals() and correctPenetrations(), or for an invalid tool.
/// @throws Cancelled if params.progress asks to stop.
CorrectedPath correctPathPenetrations(const ddf::DisplacementField& goal, const Tool& tool,
                                      ToolPath path, PenetrationCorrectionParams params = {});

/// @brief A workpiece after Preston removal and what the removal did.
struct PrestonStageResult {
  ddf::DisplacementField workpiece;  ///< the input workpiece with the material removed
  PrestonReport report;              ///< contact, pressure and depth per pose
};

/// @brief applyPrestonRemoval() along @p path from @p workpiece with the cutting mesh of
/// @p tool and the contactNormals() on the workpiece as it is before the removal, made from
/// params.normals (the given normals, empty for none).
/// @throws InvalidInput as contactNormals() and applyPrestonRemoval(), or for an invalid tool.
/// @throws Cancelled if params.progress asks to stop.
PrestonStageResult prestonStage(ddf::DisplacementField workpiece, const Tool& tool,
                                const ToolPath& path, PrestonParams params = {});

}  // namespace ddfcam::planning
