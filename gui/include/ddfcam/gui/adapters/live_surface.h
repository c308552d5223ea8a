// SPDX-License-Identifier: MIT
// ddfcam gui adapters: a planning::LiveFrame (the cut surface of a live simulation) into one
// vtkPolyData that is refilled in place, frame after frame. Conversion only.
#pragma once

#include <ddfcam/planning/simulation/live_simulation.h>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace ddfcam::gui {

/// @brief Surface polydata of a live simulation: points and normals from the frame's vertex
/// slots (float, mm, part frame), one triangle cell per frame triangle (32-bit cell storage)
/// and cell data kFaceArrayName with the support face of each. apply() copies a frame into the
/// same polydata (arrays resized and overwritten, then marked modified), so the mapper that
/// shows it keeps its input and only the buffers change.
class LiveSurfacePolyData {
 public:
  LiveSurfacePolyData();
  /// @brief Copies @p frame's mesh into the polydata.
  void apply(const planning::LiveFrame& frame);
  /// @brief The polydata (owned; shared with whatever shows it).
  vtkPolyData* polyData() const { return data_; }

 private:
  vtkSmartPointer<vtkPolyData> data_;
};

}  // namespace ddfcam::gui
