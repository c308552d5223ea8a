// SPDX-License-Identifier: MIT
// ddfcam gui adapters: a planning::LiveFrame (the cut surface of a live simulation) into one
// vtkPolyData that is refilled in place, frame after frame. Conversion only.
#pragma once

#include <ddfcam/gui/adapters/raster_texture_atlas.h>
#include <ddfcam/planning/simulation/live_simulation.h>

#include <vtkPolyData.h>  // complete type: polyData() converts the smart pointer
#include <vtkSmartPointer.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

class vtkRenderer;
class vtkTexture;

namespace ddfcam::gui {

/// @brief Surface polydata of a live simulation: points and normals from the frame's vertex
/// slots (float, mm, part frame), one triangle cell per frame triangle (32-bit cell storage)
/// and cell data kFaceArrayName with the support face of each. apply() copies a frame into the
/// same polydata (arrays resized and overwritten, then marked modified), so the mapper that
/// shows it keeps its input and only the buffers change.
///
/// With a tolerance texture (the frames carry tolerance classes and corner parameters), every
/// vertex slot gets one point per support face using it, with texture coordinates into a
/// RasterTextureAtlas of the classes, so the tolerance band is drawn at raster resolution on
/// the coarse adaptive mesh.
class LiveSurfacePolyData {
 public:
  /// @param faceCount, rasterSteps the part's support faces and raster steps: when > 0 and
  /// the atlas fits (RasterTextureAtlas::fits), frames with tolerance classes are textured.
  explicit LiveSurfacePolyData(int faceCount = 0, int rasterSteps = 0);
  /// Stops feeding the renderer given to uploadBeforeRendering().
  ~LiveSurfacePolyData();
  LiveSurfacePolyData(const LiveSurfacePolyData&) = delete;
  LiveSurfacePolyData& operator=(const LiveSurfacePolyData&) = delete;
  /// @brief Sends the texture's changed blocks to the GPU whenever @p renderer starts a frame
  /// (RasterTextureAtlas::uploadChanged, with the context current); @p renderer must outlive
  /// this object.
  void uploadBeforeRendering(vtkRenderer* renderer);
  /// @brief Copies @p frame's mesh (and its tolerance classes) into the polydata.
  void apply(const planning::LiveFrame& frame);
  /// @brief The polydata (owned; shared with whatever shows it).
  vtkPolyData* polyData() const { return data_; }
  /// @brief The tolerance texture for the surface actor, or null without one.
  vtkTexture* texture() const;
  /// @brief The atlas behind texture() (null without one).
  const RasterTextureAtlas* atlas() const { return atlas_.get(); }

 private:
  void applyShared(const planning::LiveFrame& frame);
  void applyTextured(const planning::LiveFrame& frame);
  // Triangle cells of the frame with corner points @p corners (3 per triangle).
  void setCells(const planning::LiveFrame& frame, const std::vector<std::int32_t>& corners);

  vtkSmartPointer<vtkPolyData> data_;
  std::unique_ptr<RasterTextureAtlas> atlas_;
  vtkRenderer* renderer_ = nullptr;
  unsigned long observer_ = 0;
  // Textured frames, reused between frames: per slot the face and point it was last given,
  // per point the frame corner it copies, per corner its point.
  std::vector<int> slotFace_, slotPoint_;
  std::vector<std::size_t> points_;
  std::vector<std::int32_t> connectivity_;
};

}  // namespace ddfcam::gui
