// SPDX-License-Identifier: MIT
// ddfcam gui: region colours on the part, and the brush and lasso of the Segmentation panel.
#pragma once

#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/analysis/region_editing.h>
#include <ddfcam/planning/model/project.h>

#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include <vtkSmartPointer.h>

class QMouseEvent;
class vtkActor;
class vtkActor2D;
class vtkPoints;

namespace ddfcam::gui {

class VtkView;

/// @brief What a left drag on the part does while the Segmentation panel edits regions.
enum class RegionEditMode {
  None = 0,  ///< the view's camera handles the mouse as usual
  Brush,     ///< paint faces within the brush radius of the dragged surface points
  Erase,     ///< as Brush, but take the faces out of every region
  Lasso,     ///< draw a polygon; faces whose centroids project inside and face the camera
};

/// @brief Shows the regions of the document as face colours over the part (an actor of its
/// own in the view's renderer, drawn slightly in front of the surface), and, while a mode is
/// active, turns left drags on the VtkView into brush strokes or lassos through an event
/// filter (other buttons and the wheel still move the camera). A stroke or a lasso is one
/// SetRegionsCommand when the button is released; during a stroke the colours show the
/// painted faces as a preview. While the brush or eraser is active, a circle of the brush
/// radius lies under the mouse (overlay kBrushCursorOverlay, in the tangent plane of the
/// surface at the point under the mouse). Escape during a stroke or lasso cancels it: the
/// regions stay as they were and no undo step is made.
class RegionViewTool : public QObject {
  Q_OBJECT

 public:
  /// @param target index of the region that receives painted faces (-1: none selected).
  RegionViewTool(Workbench& workbench, std::function<int()> target, QObject* parent = nullptr);
  ~RegionViewTool() override;

  /// Overlay showing the brush radius under the mouse (brush and eraser modes).
  static constexpr const char* kBrushCursorOverlay = "brush cursor";

  void setMode(RegionEditMode mode);
  RegionEditMode mode() const { return mode_; }
  /// @brief Brush radius, mm (> 0).
  void setBrushRadiusMm(double radiusMm);
  /// @brief Shows or hides the region colours.
  void setColoursVisible(bool visible);
  bool coloursVisible() const { return coloursVisible_; }
  /// @brief Surface triangles currently coloured (the cells of the colour actor).
  long long colouredCellCount() const;
  /// @brief Support faces whose centroid projects inside @p polygon (widget pixels) and whose
  /// normal faces the camera.
  std::vector<int> facesInLasso(const std::vector<QPointF>& polygon) const;
  /// @brief Cancels the brush stroke or lasso in progress (as Escape does): the preview is
  /// dropped, nothing is pushed. @return true if one was in progress.
  bool cancelStroke();
  /// @brief Centre (mm, part frame) of the brush circle shown, if it is shown.
  std::optional<Eigen::Vector3d> brushCursorCentre() const { return cursorCentre_; }

 signals:
  /// @brief An edit could not be made (e.g. no region selected); @p message says why.
  void refused(const QString& message);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void rebuildColours(const std::vector<planning::Region>& regions);
  void paintAt(QPointF pos);
  void finishStroke();
  void updateBrushCursor(QPointF pos);
  void hideBrushCursor();
  bool handleKey(QEvent* event);
  // Left-button press, drag and release of a stroke or lasso; true when the event is used.
  bool handlePress(const QMouseEvent& mouse);
  bool handleMove(const QMouseEvent& mouse);
  bool handleRelease(const QMouseEvent& mouse);
  void updateLassoOutline();
  void finishLasso();
  const planning::SurfacePointGrid& grid();
  const std::vector<planning::FaceFrame>& faceFrameCache() const;

  Workbench& workbench_;
  std::function<int()> target_;
  QPointer<VtkView> view_;  ///< may die before this tool when the main window closes
  RegionEditMode mode_ = RegionEditMode::None;
  double radiusMm_ = 1.0;
  bool coloursVisible_ = true;
  bool dragging_ = false;
  std::set<int> painted_;
  std::vector<QPointF> lasso_;
  std::optional<Eigen::Vector3d> cursorCentre_;  ///< where the brush circle is drawn
  QPointF cursorPos_;                            ///< widget position of the brush circle
  std::unique_ptr<planning::SurfacePointGrid> grid_;
  mutable std::optional<std::vector<planning::FaceFrame>> frames_;  ///< cache, per part state
  vtkSmartPointer<vtkPoints> lifted_;  ///< the surface's points moved off it, per geometry
  vtkSmartPointer<vtkActor> colours_;
  vtkSmartPointer<vtkActor2D> outline_;
};

}  // namespace ddfcam::gui
