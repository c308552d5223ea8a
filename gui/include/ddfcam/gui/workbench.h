// SPDX-License-Identifier: MIT
// ddfcam gui: what a workflow panel may use, and the panel interface the main window registers.
#pragma once

#include <ddfcam/gui/user_action.h>

#include <QList>
#include <functional>
#include <QString>
#include <QWidget>

class QAction;

namespace ddfcam::gui {

class ConsoleDock;
class Document;
class InteractionMode;
class JobRunner;
class MouldView;
class PartView;
class PlotDock;
class ProjectActions;

/// @brief The shell's services, handed to every panel: the document to read and edit (through
/// commands), the job runner for long work, the 3D part view (field display, overlays, picks),
/// the plot dock, the console and the error reporter of user actions.
struct Workbench {
  Document& document;              ///< the session's project and undo stack
  JobRunner& jobs;                 ///< runs long work off the UI thread
  PartView& partView;              ///< 3D view of the part: fields, overlays, picking
  PlotDock& plots;                 ///< histogram and line plots
  ConsoleDock& console;            ///< message log
  ErrorReporter reportError;       ///< shows an error of a user action (dialog + console)
  MouldView* mouldView = nullptr;  ///< the "Mould" tab's views (mould and formed surfaces)
  /// The views' interaction mode (a brush, a lasso, a pick) shown in the status bar; a panel
  /// that turns a drag or click into an edit begins its mode here (may be null in tests).
  InteractionMode* mode = nullptr;
  /// File operations; partReport() says how the document's part was imported (may be null).
  ProjectActions* projectActions = nullptr;
  /// Announces a long job with its estimate (see WorkbenchDialogs::confirmLongJob); true: go
  /// on. Null: always go on.
  std::function<bool(const QString& title, const QString& message)> confirmLongJob;
};

/// @brief A workflow panel: a widget the main window puts in a dock, plus optional actions it
/// adds to a menu. A new workflow is a Panel subclass registered with
/// MainWindow::registerPanel(); nothing else in the main window changes.
class Panel : public QWidget {
  Q_OBJECT

 public:
  explicit Panel(Workbench& workbench, QWidget* parent = nullptr)
      : QWidget(parent), workbench_(workbench) {}

  /// @brief Dock title, e.g. "Fields".
  virtual QString title() const = 0;
  /// @brief Stable identifier (dock objectName "panel_<id>", saved window state), e.g. "fields".
  virtual QString id() const = 0;
  /// @brief Dock area the panel starts in (default right).
  virtual Qt::DockWidgetArea area() const { return Qt::RightDockWidgetArea; }
  /// @brief Title of the menu the panel's actions go to (e.g. "&Simulate"); empty: none.
  virtual QString menuTitle() const { return {}; }
  /// @brief Actions for menuTitle(), owned by the panel.
  virtual QList<QAction*> menuActions() const { return {}; }

 protected:
  Workbench& workbench() const { return workbench_; }

 private:
  Workbench& workbench_;
};

}  // namespace ddfcam::gui
