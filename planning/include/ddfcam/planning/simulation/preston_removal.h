// SPDX-License-Identifier: MIT
// ddfcam: Preston-type material removal of a compliant grinding tool on a DDF workpiece.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/progress.h>

#include <vector>

namespace ddfcam::planning {

/// @brief Parameters of the Preston removal model. Units: mm, N, s; the removal depth per pose
/// is dh = K_p p v_s dt (mm) with p in N/mm^2, v_s in mm/s and dt = step / v_f in s, so the
/// removed cross-section of one long pass is K_p F v_s / v_f (mm^2) whatever the contact shape.
struct PrestonParams {
  double prestonCoefficientMm2PerN = 1e-7;  ///< K_p, mm^2/N (default 1e-7 = 1e-13 m^2/N)
  double forceN = 10.0;                     ///< normal force F pressing the tool, N (default 10)
  double surfaceSpeedMmPerS = 30000.0;      ///< wheel surface speed v_s, mm/s (default 30 m/s)
  double feedMmPerS = 10.0;                 ///< feed v_f, mm/s (default 10)
  /// Nominal infeed of the undeformed tool below its path pose along the contact normal, mm:
  /// sets the contact patch of the Winkler (elastic foundation) model (default 0.1).
  double infeedMm = 0.1;
  int gridSize = 50;  ///< tangential grid cells per axis over the contact patch (default 50)
  /// #P unit contact normals (material -> tool), part frame; empty (default) = the normal of
  /// the workpiece's raster triangle nearest to each contact.
  std::vector<ddf::Vec3> normals;
  ProgressCallback progress;  ///< fraction done; false cancels (default none)
};

/// @brief What applyPrestonRemoval() did.
struct PrestonReport {
  std::vector<double> contactAreaMm2;  ///< #P contact patch area (interference > 0), mm^2
  std::vector<double> maxPressure;     ///< #P largest contact pressure, N/mm^2
  std::vector<double> maxDepthMm;      ///< #P largest removal depth at one pose, mm
  double removedVolumeMm3 = 0.0;       ///< sum of depth x cell area over all poses, mm^3
  int posesWithoutContact = 0;         ///< poses whose tool did not reach the surface
};

/// @brief Removes material from @p workpiece along @p path, pose after pose: the tool
/// @p toolMesh (tool frame, mm) at its pose lowered by infeedMm along the contact normal
/// interferes with the current surface by i = max(0, h_W - h_T) on a tangential grid over the
/// contact patch; the pressure p = c i with c chosen so that sum p dA = F (Winkler
/// foundation); every raster point under the patch is lowered by K_p p v_s dt along the normal
/// (dt = half the distances to the neighbouring poses of the same pass, over v_f; a pass of
/// one pose removes nothing), converted to height units by dividing by v . n. The depth is
/// interpolated bilinearly from the grid cells (zero outside), which keeps the removed volume
/// equal to sum depth x cell area. Shared copies are finally synchronized by their minimum.
/// Removal should stay small against the crust (heights are clamped to the crust at -1).
/// @throws InvalidInput for an empty tool mesh, non-positive K_p, F, v_s, v_f or infeed,
/// gridSize < 2, a normals count other than 0 or #P, or a contact with no face nearby.
/// @throws Cancelled if the progress callback asks to stop (removal done so far is kept).
PrestonReport applyPrestonRemoval(ddf::DisplacementField& workpiece,
                                  const ddf::TriangleMesh& toolMesh, const ToolPath& path,
                                  const PrestonParams& params = {});

}  // namespace ddfcam::planning
