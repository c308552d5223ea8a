// SPDX-License-Identifier: MIT
// ddfcam gui: the mouse wheel scrolls a panel instead of changing the combo box or spin box
// that happens to pass under the pointer.
#pragma once

#include <QObject>

namespace ddfcam::gui {

/// @brief An application-wide event filter: a combo box or spin box inside a scroll area (a
/// docked panel) takes the wheel only while it has keyboard focus (clicked or tabbed into);
/// otherwise the wheel event goes to the scroll area, so the panel scrolls. Removed when the
/// guard is destroyed.
class WheelGuard : public QObject {
  Q_OBJECT

 public:
  explicit WheelGuard(QObject* parent = nullptr);
  ~WheelGuard() override;

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
};

}  // namespace ddfcam::gui
