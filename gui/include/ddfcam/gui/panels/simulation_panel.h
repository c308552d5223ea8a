// SPDX-License-Identifier: MIT
// ddfcam gui: the Simulation panel: tools, tool paths, grinding a path, simulation states.
#pragma once

#include <ddfcam/gui/workbench.h>

class QListWidget;
class QPushButton;

namespace ddfcam::gui {

/// @brief Lists tools, paths and simulation states. Selecting a path shows its tool at the
/// first pose; "Simulate" grinds the selected path into a copy of the part as a job
/// (planning::simulatePath) and commits the new heights as one undoable edit that also records
/// a simulation state; "Restore" sets the heights of a recorded state (undoable).
class SimulationPanel : public Panel {
  Q_OBJECT

 public:
  explicit SimulationPanel(Workbench& workbench, QWidget* parent = nullptr);
  QString title() const override { return tr("Simulation"); }
  QString id() const override { return "simulation"; }
  QString menuTitle() const override { return tr("&Simulate"); }
  QList<QAction*> menuActions() const override { return actions_; }

  /// @brief Starts grinding path @p index (the Simulate button). @return true if started.
  bool simulatePath(int index);
  /// @brief Sets the part's heights to those of state @p index (undoable).
  /// @return true if done.
  bool restoreState(int index);

 private:
  void refresh();
  void showToolOfSelectedPath();

  QList<QAction*> actions_;
  QListWidget* tools_ = nullptr;
  QListWidget* paths_ = nullptr;
  QListWidget* states_ = nullptr;
  QPushButton* simulate_ = nullptr;
  QPushButton* restore_ = nullptr;
};

}  // namespace ddfcam::gui
