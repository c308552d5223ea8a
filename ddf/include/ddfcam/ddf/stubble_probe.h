// SPDX-License-Identifier: MIT
// ddfcam: dry-run V-shooting of a closed mesh: where each stubble enters and leaves it, without
// changing heights (V-convexity check, sec. 8.4, and collision detection, sec. 8.5).
#pragma once

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of probeStubbles().
struct StubbleProbeParams {
  /// Process candidate support faces in parallel (TBB). Default true.
  bool parallel = true;
  /// Hits of one stubble closer than this in h with the same direction (entry or exit) are one
  /// hit: a stubble through a shared mesh edge or vertex meets two or more triangles there.
  /// Default 1e-7.
  double mergeTolerance = 1e-7;
};

/// @brief How one stubble segment g + h v, h in [-1, 1], crosses the probed mesh.
struct StubbleCrossing {
  int face = 0;             ///< support face of this copy
  std::uint32_t index = 0;  ///< raster index in the face (Raster order)
  PointId point = 0;        ///< global raster point id (shared copies have the same id)
  float height = 0.0f;      ///< current height h0 of the copy
  /// Lower end of the lowest interval of the segment inside the mesh; -1 when the segment
  /// starts inside the mesh (the entry lies below the crust, as the depth buffer clamps).
  float entry = 0.0f;
  /// Upper end of that lowest interval; +1 when it leaves the crust top inside the mesh.
  float exit = 0.0f;
  /// Number of separate intervals of the segment inside the mesh (1 for a convex mesh; more
  /// means the stubble enters the mesh more than once).
  int intervals = 0;
};

/// @brief Result of probeStubbles().
struct StubbleProbe {
  /// Every stored copy whose segment [-1, 1] meets the mesh, sorted by (face, index).
  std::vector<StubbleCrossing> crossings;
  std::size_t candidateFaces = 0;  ///< support faces from localization (CrustHash)
};

/// @brief V-shoots the stubbles of @p ddf against the closed, outward-oriented mesh @p mesh
/// placed at @p pose (mesh frame -> part frame, mm) and reports where each enters and leaves
/// it (exact ray/triangle intersection in double; entry = triangle normal against v). Heights
/// are not changed. Localization as the depth buffer: CrustHash box query, then the crust box
/// of every face against the mesh bounds, then per face each triangle is projected along the
/// face's mean vector and scan-converted row by row over the face's raster (sec. 5.2), grown by
/// how far a stubble segment strays from its base point in that view, so each stubble meets
/// only the few triangles over it; of those, only triangles whose box touches the segment's box
/// count on the segment. The results equal those of testing every stubble against every
/// triangle with the same rules (tests/ddf/stubble_probe_test.cpp checks this).
/// An inward-oriented mesh (negative signed volume) is treated as flipped.
/// @param hash localization structure built for @p ddf with its current vectors.
StubbleProbe probeStubbles(const DisplacementField& ddf, const CrustHash& hash,
                           const TriangleMesh& mesh, const Eigen::Isometry3d& pose,
                           const StubbleProbeParams& params = {});

}  // namespace ddfcam::ddf
