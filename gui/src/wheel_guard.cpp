// SPDX-License-Identifier: MIT
// ddfcam gui: WheelGuard.
#include <ddfcam/gui/wheel_guard.h>

#include <QAbstractSpinBox>
#include <QApplication>
#include <QCoreApplication>
#include <QComboBox>
#include <QEvent>
#include <QScrollArea>
#include <QWidget>

namespace ddfcam::gui {

namespace {

QScrollArea* scrollAreaOf(const QWidget* widget) {
  for (QWidget* w = widget->parentWidget(); w; w = w->parentWidget())
    if (auto* area = qobject_cast<QScrollArea*>(w)) return area;
  return nullptr;
}

}  // namespace

WheelGuard::WheelGuard(QObject* parent) : QObject(parent) {
  qApp->installEventFilter(this);
}

WheelGuard::~WheelGuard() {
  qApp->removeEventFilter(this);
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::Wheel) return false;
  auto* widget = qobject_cast<QWidget*>(watched);
  if (!widget || widget->hasFocus()) return false;
  if (!qobject_cast<QComboBox*>(widget) && !qobject_cast<QAbstractSpinBox*>(widget)) return false;
  QScrollArea* area = scrollAreaOf(widget);
  if (!area) return false;
  // The panel scrolls instead (handed over explicitly: Qt does not offer a wheel event that was
  // sent, rather than spontaneous, to the parents), and nothing else sees the event.
  QCoreApplication::sendEvent(area->viewport(), event);
  event->accept();
  return true;
}

}  // namespace ddfcam::gui
