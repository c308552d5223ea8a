// SPDX-License-Identifier: MIT
// ddfcam gui: the one interaction mode in which a drag or click on a view edits instead of
// moving the camera, shown in the status bar and ended by Esc or by leaving its panel.
#pragma once

#include <QMetaObject>
#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>

class QDockWidget;
class QMainWindow;
class QWidget;

namespace ddfcam::gui {

/// @brief Which tool the mouse on the views belongs to: navigation (drags move the camera)
/// or one mode a panel started (a brush, a lasso, a pick). At most one mode is active:
/// starting one ends the one before. A mode ends when its panel ends it, when end() is called
/// (Esc in the main window when no job runs), or when the dock holding its panel is hidden or another tab of
/// its dock group is raised, so no mode acts from a panel the engineer no longer sees.
class InteractionMode : public QObject {
  Q_OBJECT

 public:
  explicit InteractionMode(QObject* parent = nullptr);
  ~InteractionMode() override;

  /// @brief Shows the mode in @p window's status bar (permanent label "interactionModeLabel",
  /// highlighted while a mode is active). Esc is the window's (Edit > Cancel running job or
  /// editing mode), which calls end() when no job runs.
  void attachTo(QMainWindow& window);

  /// @brief Starts mode @p name (e.g. "Brush") of @p owner (a panel, inside a dock or not)
  /// with @p hint (what the mouse does, e.g. "drag paints faces"); @p stop is called
  /// when the mode is ended from outside the panel (end(), the dock left, another mode), and
  /// must switch the panel's tool off. Restarting the owner's mode only updates the texts.
  void begin(QWidget* owner, const QString& name, const QString& hint, std::function<void()> stop);
  /// @brief The owner switched its mode off itself: back to navigation, @p stop not called.
  /// Nothing happens if @p owner's mode is not the active one.
  void clear(const QWidget* owner);
  /// @brief Ends the active mode (its stop callback runs). @return false when navigating.
  bool end();
  /// @brief Name of the active mode, "" when navigating.
  QString name() const { return name_; }
  /// @brief The panel whose mode is active, or null.
  const QWidget* owner() const { return owner_; }
  /// @brief What the status bar shows, e.g. "Brush (Segmentation): drag paints faces (Esc:
  /// navigate)" or "Navigate: drag rotates, middle pans, wheel zooms".
  QString statusText() const;

 signals:
  /// @brief The mode began or ended; @p text is statusText().
  void changed(const QString& text);

 private:
  void reset();

  QPointer<QWidget> owner_;
  QString name_, hint_, panel_;
  std::function<void()> stop_;
  QMetaObject::Connection dockHidden_;
};

}  // namespace ddfcam::gui
