// SPDX-License-Identifier: MIT
// ddfcam gui: InteractionMode.
#include <ddfcam/gui/interaction_mode.h>

#include <QDockWidget>
#include <QFont>
#include <QFontMetrics>
#include <QLabel>
#include <QMainWindow>
#include <QStatusBar>
#include <QWidget>

#include <utility>

namespace ddfcam::gui {

namespace {

QDockWidget* dockOf(QWidget* widget) {
  for (QWidget* w = widget; w; w = w->parentWidget())
    if (auto* dock = qobject_cast<QDockWidget*>(w)) return dock;
  return nullptr;
}

}  // namespace

InteractionMode::InteractionMode(QObject* parent) : QObject(parent) {}

InteractionMode::~InteractionMode() {
  QObject::disconnect(dockHidden_);
}

void InteractionMode::attachTo(QMainWindow& window) {
  auto* label = new QLabel(statusText(), &window);
  label->setObjectName("interactionModeLabel");
  // First: while a mode is on, it matters more than the part facts beside it.
  window.statusBar()->insertPermanentWidget(0, label);
  const auto show = [label](const QString& text) {
    const bool editing = text.contains("(Esc");
    label->setText(text);
    // An editing mode stands out (the drag no longer turns the part) and is never clipped by
    // the part facts beside it.
    label->setStyleSheet(editing ? "color: #ffb347; font-weight: bold;" : QString());
    QFont font = label->font();
    font.setBold(editing);
    label->setMinimumWidth(QFontMetrics(font).horizontalAdvance(text) + 12);
  };
  show(statusText());
  connect(this, &InteractionMode::changed, label, show);
}

void InteractionMode::begin(QWidget* owner, const QString& name, const QString& hint,
                            std::function<void()> stop) {
  if (owner_ && owner_ != owner) end();
  const bool restart = owner_ == owner;
  owner_ = owner;
  name_ = name;
  hint_ = hint;
  stop_ = std::move(stop);
  QDockWidget* dock = dockOf(owner);
  panel_ = dock ? dock->windowTitle() : QString();
  if (!restart && dock) {
    // A tab raised over this panel, or the dock closed: the mode must not act unseen.
    dockHidden_ = connect(dock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
      if (!visible) end();
    });
  }
  emit changed(statusText());
}

void InteractionMode::clear(const QWidget* owner) {
  if (!owner_ || owner_ != owner) return;
  reset();
  emit changed(statusText());
}

bool InteractionMode::end() {
  if (!owner_) return false;
  std::function<void()> stop = std::move(stop_);
  reset();
  if (stop) stop();  // the panel switches its tool off (its clear() is then a no-op)
  emit changed(statusText());
  return true;
}

void InteractionMode::reset() {
  QObject::disconnect(dockHidden_);
  owner_.clear();
  name_.clear();
  hint_.clear();
  panel_.clear();
  stop_ = nullptr;
}

QString InteractionMode::statusText() const {
  if (name_.isEmpty())
    return tr("Navigate: drag rotates, middle pans, wheel zooms");
  const QString where = panel_.isEmpty() ? name_ : tr("%1 (%2)").arg(name_, panel_);
  return tr("%1: %2 (Esc: navigate)").arg(where, hint_);
}

}  // namespace ddfcam::gui
