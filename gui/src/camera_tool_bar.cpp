// SPDX-License-Identifier: MIT
// ddfcam gui: CameraToolBar, standard views for a VtkView.
#include <ddfcam/gui/camera_tool_bar.h>

#include <QAction>

namespace ddfcam::gui {

namespace {

struct DirectionAction {
  ViewDirection direction;
  const char* objectName;
  const char* text;
  const char* toolTip;
};

constexpr DirectionAction kDirections[] = {
    {ViewDirection::PlusX, "actionViewPlusX", QT_TR_NOOP("+X"),
     QT_TR_NOOP("View from +X (looking towards -X, Z up)")},
    {ViewDirection::MinusX, "actionViewMinusX", QT_TR_NOOP("-X"),
     QT_TR_NOOP("View from -X (looking towards +X, Z up)")},
    {ViewDirection::PlusY, "actionViewPlusY", QT_TR_NOOP("+Y"),
     QT_TR_NOOP("View from +Y (looking towards -Y, Z up)")},
    {ViewDirection::MinusY, "actionViewMinusY", QT_TR_NOOP("-Y"),
     QT_TR_NOOP("View from -Y (looking towards +Y, Z up)")},
    {ViewDirection::PlusZ, "actionViewPlusZ", QT_TR_NOOP("+Z"),
     QT_TR_NOOP("Top view, from +Z (Y up)")},
    {ViewDirection::MinusZ, "actionViewMinusZ", QT_TR_NOOP("-Z"),
     QT_TR_NOOP("Bottom view, from -Z (Y up)")},
    {ViewDirection::Isometric, "actionViewIsometric", QT_TR_NOOP("Iso"),
     QT_TR_NOOP("Isometric view (Z up)")},
};

}  // namespace

CameraToolBar::CameraToolBar(VtkView* view, QWidget* parent) : QToolBar(tr("Camera"), parent) {
  setObjectName("cameraToolBar");
  setToolButtonStyle(Qt::ToolButtonTextOnly);
  fit_ = addAction(tr("Fit"));
  fit_->setObjectName("actionViewFit");
  fit_->setToolTip(tr("Fit the part into the view, keeping the direction"));
  connect(fit_, &QAction::triggered, this, [this] {
    if (view_) view_->fitCamera();
  });
  for (const DirectionAction& d : kDirections) {
    QAction* action = addAction(tr(d.text));
    action->setObjectName(d.objectName);
    action->setToolTip(tr(d.toolTip));
    const ViewDirection direction = d.direction;
    connect(action, &QAction::triggered, this, [this, direction] {
      if (view_) view_->viewFrom(direction);
    });
    directions_[static_cast<int>(direction)] = action;
  }
  setView(view);
}

void CameraToolBar::setView(VtkView* view) {
  view_ = view;
  fit_->setEnabled(view != nullptr);
  for (QAction* action : directions_) action->setEnabled(view != nullptr);
}

VtkView* CameraToolBar::view() const {
  return view_;
}

QAction* CameraToolBar::fitAction() const {
  return fit_;
}

QAction* CameraToolBar::directionAction(ViewDirection direction) const {
  return directions_[static_cast<int>(direction)];
}

}  // namespace ddfcam::gui
