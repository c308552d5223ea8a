// SPDX-License-Identifier: MIT
// ddfcam: stateful simulation of material removal along a tool path (dissertation sec. 8.4) with
// swept volumes, V-convexity check (fig. 8.15) and collision detection (sec. 8.5).
#pragma once

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/progress.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ddfcam::planning {

/// @brief What is cut at every pose.
enum class SweepMode {
  /// The cutting part at each pose only (sec. 8.4); the result depends on the sampling step.
  Discrete = 0,
  /// The convex hull of the cutting part at two consecutive poses of a pass: exactly the swept
  /// volume of a translation of a convex tool, a close outer approximation for small rotations,
  /// so the result does not depend on the sampling step. Needs a convex cutting part.
  Swept = 1,
};

/// @brief Parameters of GrindingSimulation and simulateGrinding().
struct GrindingSimulationParams {
  SweepMode mode = SweepMode::Discrete;  ///< what is cut per pose (default Discrete)
  ddf::DepthBufferParams depthBuffer;    ///< depth-buffer settings (default DepthBufferParams{})
  /// Report stubbles where the cutting part lies in the material with material above it
  /// (fig. 8.15), which the depth buffer would wrongly remove. Default true.
  bool checkVConvexity = true;
  /// Report poses where the non-cutting part touches material (sec. 8.5). Default true.
  bool checkCollisions = true;
  /// Heights differing by less than this (units of h) are not a violation or a collision, so
  /// that a tool merely touching the surface reports nothing. Default 1e-4.
  double heightTolerance = 1e-4;
  /// Keep the undo log of every pose so that GrindingSimulation::seek() can go backwards
  /// (memory: see GrindingSimulation). simulateGrinding() never seeks and turns it off.
  /// Default true.
  bool recordUndo = true;
};

/// @brief Material removed by one pass.
struct PassRemoval {
  int firstPose = 0;  ///< index of the pass's first pose in the path
  int poseCount = 0;  ///< poses of the pass cut so far
  /// Volume removed by those poses, mm^3: volumeBetween over the pass, summed pose by pose
  /// over the changed heights.
  double removedVolumeMm3 = 0.0;
};

/// @brief A pose whose cut is not V-convex: stubbles where the cutting part's lowest interval
/// starts and ends below the current height (material above the tool) or that enter it twice
/// below the surface; the depth buffer removes the material above the tool there too.
struct VConvexityViolation {
  int pose = 0;              ///< path pose index
  std::size_t stubbles = 0;  ///< distinct raster points affected
};

/// @brief A pose whose non-cutting part (shank, holder, arbor, flange) reaches below the
/// current surface of the workpiece (checked before the pose's cut).
struct CollisionHit {
  int pose = 0;              ///< path pose index
  std::size_t stubbles = 0;  ///< distinct raster points whose material it touches
};

/// @brief What the simulation did so far.
struct GrindingReport {
  int posesCut = 0;                 ///< poses cut
  std::vector<PassRemoval> passes;  ///< one entry per pass started, in path order
  double removedVolumeMm3 = 0.0;    ///< sum over passes, mm^3
  std::size_t pointsLowered = 0;    ///< heights lowered (copies counted per face)
  /// Of the lowerings, those where the tool reached below the crust bottom and the height was
  /// clamped to h = -1 (copies counted per face and pose): the true cut is deeper there than the
  /// workpiece shows (see crustClamping() for the points left at the bottom).
  std::size_t pointsClamped = 0;
  std::vector<VConvexityViolation> vConvexity;  ///< poses with violations, ascending
  std::size_t vConvexityStubbles = 0;           ///< sum of their stubble counts
  std::vector<CollisionHit> collisions;         ///< colliding poses, ascending
  double seconds = 0.0;                         ///< wall time spent in advance() and seek(), s
};

/// @brief Playback of a tool path on a workpiece DDF: advance() cuts the next poses in
/// machining order, so a GUI can cut a few poses per frame, draw, and continue.
///
/// Per pose k: (1) collision check of the non-cutting part at k against the current workpiece
/// (probe of the stubbles, ddf::probeStubbles after CrustHash localization); (2) V-convexity
/// check of the cutting part at k; (3) the cut: Discrete cuts the cutting part at k; Swept cuts
/// the convex hull of the cutting part at k-1 and k (the part at k alone at a pass start).
/// The non-cutting part never cuts. Heights only decrease and vectors never change, so one
/// CrustHash built at construction serves the whole path.
///
/// Every pose records the stored heights it changed (shared copies included) with their
/// previous values, which gives the pass volumes incrementally and lets seek() go back.
/// Memory: a fixed copy of the heights (4 bytes per stored height) plus, per recorded pose,
/// 12 bytes per stored height the pose changed and 32 bytes of counters, plus the slack of
/// vector growth (undoMemoryBytes()). Example: the demo project's 267-pose path on a part of
/// 235,008 stored heights changes 2,688 heights per pose, 21.5 kB per pose, 5.7 MB in all.
class GrindingSimulation {
 public:
  /// @param workpiece the stock (see workpiece.h); copied in and cut in place.
  /// @param tool cutting and non-cutting meshes in the tool frame (toolMeshes()).
  /// @param path poses (tool frame -> part frame) and passStarts (empty = one pass).
  /// @throws InvalidInput for an empty cutting mesh, pass starts that are not ascending within
  /// [0, poses), or in Swept mode a cutting part that is not convex (hull volume more than
  /// 0.1 % above the mesh volume).
  GrindingSimulation(ddf::DisplacementField workpiece, const ToolMeshes& tool, const ToolPath& path,
                     const GrindingSimulationParams& params = {});

  /// @brief Cuts up to @p poses further poses (all remaining if negative).
  /// @returns the number of poses cut.
  /// @throws Cancelled through @p progress (fraction of this call's poses); the poses cut so
  /// far stay cut and the report counts them.
  int advance(int poses, const ProgressCallback& progress = {});

  /// @brief Moves to the state after poses 0..@p pose - 1: backwards by restoring the recorded
  /// heights (bit-identical to cutting only those poses), forwards by advance(). The report
  /// (except seconds) then equals the report of a simulation of the path's first @p pose poses.
  /// @throws InvalidInput for @p pose outside [0, path size], or a backward seek with
  /// GrindingSimulationParams::recordUndo off.
  void seek(int pose);

  /// @brief Sorted distinct support faces whose heights advance() or seek() may have changed
  /// since the last call (or construction); clears the set. Contains the faces the tool
  /// touched (ddf::CutStats::touchedFaces) and every face with a changed stored height,
  /// including copies of shared points changed by synchronization.
  std::vector<int> takeChangedFaces();

  /// @brief Bytes held for seeking: the height copy, the undo log and the per-pose counters.
  std::size_t undoMemoryBytes() const;

  /// @brief Index of the next pose to cut (== path size when finished).
  int nextPose() const { return next_; }
  bool finished() const { return next_ >= static_cast<int>(path_.poses.size()); }
  const ddf::DisplacementField& workpiece() const { return workpiece_; }
  const GrindingReport& report() const { return report_; }
  const ToolPath& path() const { return path_; }

  /// @brief One changed stored height: flat index into workpiece().allHeights(), its value
  /// before the pose and after it.
  struct HeightChange {
    std::uint32_t index = 0;
    float before = 0.0f;
    float after = 0.0f;
  };
  /// @brief The stored heights pose @p pose changed, with their values before and after it
  /// (its undo log, shared copies included). @throws InvalidInput unless @p pose < nextPose() and
  /// GrindingSimulationParams::recordUndo is on.
  std::span<const HeightChange> poseChanges(int pose) const;

 private:
  /// The state after one pose, for truncating the report on a backward seek.
  struct PoseRecord {
    std::size_t logEnd = 0;         // end of the pose's entries in log_
    double passVolumeMm3 = 0.0;     // its pass's removed volume after the pose
    std::size_t pointsLowered = 0;  // report counters after the pose
    std::size_t pointsClamped = 0;
  };

  ddf::CutStats cutPose(int k);
  void checkPose(int k);
  void recordPose(const ddf::CutStats& stats);
  double recordChanges(const std::vector<int>& touchedFaces);
  void markChanged(int face);
  void seekBack(int pose);
  void sumPassVolumes();
  bool isPassStart(int k) const;

  ddf::DisplacementField workpiece_;
  ToolMeshes tool_;
  ToolPath path_;
  GrindingSimulationParams params_;
  ddf::CrustHash hash_;
  std::vector<float> shadow_;        // heights after the last pose (before the next cut)
  std::vector<HeightChange> log_;    // undo entries of all recorded poses, in pose order
  std::vector<PoseRecord> records_;  // one per cut pose while recordUndo
  std::vector<char> changedFlag_;    // per face: in changed_
  std::vector<int> changed_;         // faces for takeChangedFaces()
  int next_ = 0;
  GrindingReport report_;
};

/// @brief Runs a whole path: GrindingSimulation(workpiece, tool, path, params).advance(-1).
/// @param workpiece modified in place; on Cancelled it keeps the poses cut so far.
/// @throws as GrindingSimulation and advance().
GrindingReport simulateGrinding(ddf::DisplacementField& workpiece, const ToolMeshes& tool,
                                const ToolPath& path, const GrindingSimulationParams& params = {},
                                const ProgressCallback& progress = {});

}  // namespace ddfcam::planning
