// SPDX-License-Identifier: MIT
// ddfcam: a grinding simulation that runs on its own thread and publishes display frames of the
// cut surface (incremental adaptive triangulation) for a viewer that draws at its own pace.
#pragma once

#include <ddfcam/ddf/view_dependent_bounds.h>
#include <ddfcam/planning/simulation/cut_inspection.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/live_tolerance_map.h>

#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <vector>

namespace ddfcam::planning {

/// @brief One published state of a LiveSimulation: the cut surface as an indexed mesh and the
/// simulation's report at that pose. Frames are immutable once published.
struct LiveFrame {
  std::uint64_t serial = 0;  ///< increases with every published frame
  int posesCut = 0;          ///< poses 0..posesCut-1 are cut (GrindingSimulation::nextPose)
  int totalPoses = 0;        ///< poses of the path
  int faceCount = 0;         ///< support faces of the part
  int rasterSteps = 0;       ///< raster steps per support edge (Raster::steps())
  GrindingReport report;     ///< the report at that state
  /// Vertex slots, 3 floats each (x, y, z), mm, part frame; unused slots are stale.
  std::vector<float> positions;
  /// Unit area-weighted normals per slot, 3 floats each (zero for an unused slot).
  std::vector<float> normals;
  std::vector<std::int32_t> triangles;     ///< 3 slots per triangle, grouped by support face
  std::vector<std::int32_t> triangleFace;  ///< support face of each triangle
  /// Per triangle corner (in the order of triangles), its parameter position (i, k) on the
  /// triangle's support face in raster steps, 2 floats each (ddf::TriangleParams): where a
  /// raster-resolution colouring (toleranceClasses) is looked up.
  std::vector<float> cornerParams;
  /// Per raster point (layout of allHeights()), its LiveToleranceMap class against the design
  /// and LiveSimulationParams::toleranceBand; empty when not inspected.
  std::vector<std::uint8_t> toleranceClasses;
  /// Poses per second the simulation achieved over the last second (0 before one passed).
  double simulatedPosesPerSecond = 0.0;
  double displayUpdateSeconds = 0.0;  ///< worker time of the last display update, s
  /// Pixel error of the view-dependent level of detail in force (setView(); raised above the
  /// requested one while the triangle budget is exceeded), px; 0 without a view (uniform bound).
  double viewPixelError = 0.0;
  /// The error bound of every support face the mesh keeps with a view, mm
  /// (ddf::IncrementalTriangulation::faceEps); empty without a view (displayEpsMm everywhere).
  std::vector<float> faceEps;
  double elapsedSeconds = 0.0;        ///< playing time so far (pauses excluded), s
  bool inspected = false;  ///< a design was given: the overcut fields below are meaningful
  std::optional<Overcut> largestOvercut;  ///< deepest overcut of poses 0..posesCut-1
  int overcutPoses = 0;                   ///< poses that overcut beyond the tolerance
};

/// @brief Parameters of LiveSimulation.
struct LiveSimulationParams {
  GrindingSimulationParams simulation;  ///< what is cut and checked (recordUndo is forced on)
  /// Error bound of the displayed triangulation (ch. 7), mm (> 0). Default 0.01.
  double displayEpsMm = 0.01;
  /// Poses per second while playing; <= 0: as fast as the machine can. Default 30.
  double posesPerSecond = 30.0;
  /// Interval of the published frames while playing, s: a frame follows the first pose that
  /// ends past each multiple of it, so the display follows at this rate however fast the
  /// simulation runs (and at the pose rate when that is slower). Default 1/30.
  double frameIntervalS = 1.0 / 30.0;
  /// Heights of the design on the workpiece's support (e.g. the "design" state): every pose is
  /// inspected for overcut against it (CutInspection). Empty: no inspection.
  std::vector<float> designHeights;
  /// Overcut up to this depth is within tolerance, mm (>= 0). Default 0.01.
  double overcutToleranceMm = 0.01;
  /// Most triangles the display should hold with a view-dependent level of detail: while the
  /// mesh has more, the view's pixel error is doubled (up to 16 times). Default 2,000,000.
  std::size_t triangleBudget = 2'000'000;
  /// Coarsest bound of the view-dependent level of detail, as a multiple of displayEpsMm (>= 1).
  /// Default 128.
  double coarsestEpsFactor = 128.0;
  /// Band of the live tolerance classes (LiveFrame::toleranceClasses), mm; used with
  /// designHeights. Default [-0.01, 0.01].
  ToleranceBand toleranceBand;
};

/// @brief Plays a GrindingSimulation on a worker thread. play() starts cutting at the set rate;
/// the worker updates an incremental triangulation of the surface (only the faces a cut
/// reached) and publishes a LiveFrame once per frameIntervalS and whenever it stops;
/// latestFrame() hands the newest one to the viewer's thread. pause() stops the worker after
/// the pose it is cutting (one pose of latency); step() and seek() run on the caller's thread
/// with the worker stopped. The state at pose k is the same whether reached by playing, by
/// stepping or by seeking (GrindingSimulation::seek restores recorded heights).
/// All member functions are called from one (the viewer's) thread.
class LiveSimulation {
 public:
  /// @throws as GrindingSimulation, and InvalidInput for a non-positive displayEpsMm.
  LiveSimulation(ddf::DisplacementField workpiece, const ToolMeshes& tool, const ToolPath& path,
                 LiveSimulationParams params = {});
  /// Stops the worker.
  ~LiveSimulation();
  LiveSimulation(const LiveSimulation&) = delete;
  LiveSimulation& operator=(const LiveSimulation&) = delete;

  /// @brief Starts (or continues) cutting on the worker; false when the path is finished.
  bool play();
  /// @brief Stops the worker after its current pose and publishes the state.
  void pause();
  /// @brief Pauses, cuts the next pose and publishes; false when the path is finished.
  /// @throws ddfcam::Error from the cut.
  bool step();
  /// @brief Pauses and moves to the state after poses 0..@p pose - 1 (see
  /// GrindingSimulation::seek), then publishes. @throws InvalidInput for a pose out of range.
  void seek(int pose);
  /// @brief Poses per second for the next play (and the running one); <= 0: as fast as possible.
  void setPosesPerSecond(double posesPerSecond);
  /// @brief A view-dependent level of detail (ddf::viewDependentBounds from @p view, bounds from
  /// displayEpsMm up to coarsestEpsFactor times it): applied by the worker with its next frame
  /// while playing, else at once with a new frame. Call again when the camera moves.
  /// @throws InvalidInput for an invalid view (checked at once).
  void setView(const ddf::ViewBoundsParams& view);

  bool isPlaying() const;
  bool finished() const;
  /// @brief The newest published frame (never null after construction). Thread-safe.
  std::shared_ptr<const LiveFrame> latestFrame() const;
  /// @brief The error that stopped the worker, once (then cleared), or null.
  std::exception_ptr takeError();
  /// @brief The simulation; only while not playing (pause() first).
  /// @throws InvalidInput while playing.
  const GrindingSimulation& simulation() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ddfcam::planning
