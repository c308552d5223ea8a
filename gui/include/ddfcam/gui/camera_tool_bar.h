// SPDX-License-Identifier: MIT
// ddfcam gui: a tool bar of standard camera views (fit, six axis views, isometric) for a VtkView.
#pragma once

#include <ddfcam/gui/vtk_view.h>

#include <QPointer>
#include <QToolBar>

#include <array>

class QAction;

namespace ddfcam::gui {

/// @brief Tool bar with "Fit" (objectName "actionViewFit") and one action per ViewDirection:
/// "+X" ("actionViewPlusX"), "-X" ("actionViewMinusX"), "+Y", "-Y", "+Z", "-Z" (likewise
/// named) and "Iso" ("actionViewIsometric"). Each acts on the bound view; without a view the
/// actions are disabled.
class CameraToolBar : public QToolBar {
  Q_OBJECT

 public:
  /// @brief Tool bar (objectName "cameraToolBar") bound to @p view (may be null).
  explicit CameraToolBar(VtkView* view, QWidget* parent = nullptr);

  /// @brief Binds the actions to @p view (null disables them).
  void setView(VtkView* view);
  /// @brief The bound view, or null.
  VtkView* view() const;
  /// @brief The "Fit" action (VtkView::fitCamera()).
  QAction* fitAction() const;
  /// @brief The action showing the view from @p direction (VtkView::viewFrom()).
  QAction* directionAction(ViewDirection direction) const;

 private:
  QPointer<VtkView> view_;
  QAction* fit_ = nullptr;
  std::array<QAction*, 7> directions_{};
};

}  // namespace ddfcam::gui
