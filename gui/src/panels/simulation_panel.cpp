// SPDX-License-Identifier: MIT
// ddfcam gui: SimulationPanel.
#include <ddfcam/gui/panels/simulation_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/planning/path_simulation.h>

#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <memory>

namespace ddfcam::gui {

namespace {

QString toolText(const planning::Tool& t) {
  const QString kind = t.kind == planning::ToolKind::CylinderRoll
                           ? QObject::tr("roll R%1 x W%2 mm").arg(t.radiusMm).arg(t.widthMm)
                           : QObject::tr("ball R%1 mm").arg(t.radiusMm);
  return QString::fromStdString(t.name) + "  (" + kind + ")";
}

QString pathText(const planning::ToolPath& p) {
  return QObject::tr("%1  (%2 poses, %3 passes, tool %4)")
      .arg(QString::fromStdString(p.name))
      .arg(p.poses.size())
      .arg(p.passStarts.size())
      .arg(p.tool);
}

QListWidget* addList(QVBoxLayout* layout, QWidget* parent, const QString& title, const char* name) {
  layout->addWidget(new QLabel(title, parent));
  auto* list = new QListWidget(parent);
  list->setObjectName(name);
  layout->addWidget(list, 1);
  return list;
}

}  // namespace

SimulationPanel::SimulationPanel(Workbench& workbench, QWidget* parent) : Panel(workbench, parent) {
  auto* run = new QAction(tr("&Simulate selected path"), this);
  run->setObjectName("actionSimulatePath");
  connect(run, &QAction::triggered, this, [this] { simulatePath(paths_->currentRow()); });
  actions_ << run;
  auto* layout = new QVBoxLayout(this);
  tools_ = addList(layout, this, tr("Tools"), "toolList");
  paths_ = addList(layout, this, tr("Tool paths"), "pathList");
  simulate_ = new QPushButton(tr("Simulate path"), this);
  simulate_->setObjectName("simulateButton");
  layout->addWidget(simulate_);
  states_ = addList(layout, this, tr("Simulation states"), "stateList");
  restore_ = new QPushButton(tr("Restore state"), this);
  restore_->setObjectName("restoreStateButton");
  layout->addWidget(restore_);
  connect(simulate_, &QPushButton::clicked, run, &QAction::trigger);
  connect(restore_, &QPushButton::clicked, this, [this] { restoreState(states_->currentRow()); });
  connect(paths_, &QListWidget::currentRowChanged, this, [this] { showToolOfSelectedPath(); });
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & (Change::Tools | Change::Paths | Change::States | Change::Part)) refresh();
  });
  refresh();
}

void SimulationPanel::refresh() {
  const planning::Project& p = workbench().document.project();
  const int pathRow = paths_->currentRow(), stateRow = states_->currentRow();
  tools_->clear();
  paths_->clear();
  states_->clear();
  for (const auto& t : p.tools) tools_->addItem(toolText(t));
  for (const auto& path : p.paths) paths_->addItem(pathText(path));
  for (const auto& s : p.states) states_->addItem(QString::fromStdString(s.name));
  const int paths = static_cast<int>(p.paths.size()), states = static_cast<int>(p.states.size());
  paths_->setCurrentRow(paths == 0 ? -1 : std::clamp(pathRow, 0, paths - 1));
  states_->setCurrentRow(states == 0 ? -1 : std::clamp(stateRow, 0, states - 1));
  simulate_->setEnabled(paths > 0 && p.part.has_value());
  restore_->setEnabled(states > 0 && p.part.has_value());
}

void SimulationPanel::showToolOfSelectedPath() {
  const planning::Project& p = workbench().document.project();
  const int row = paths_->currentRow();
  if (row < 0 || row >= static_cast<int>(p.paths.size()) || p.paths[row].poses.empty() ||
      p.paths[row].tool < 0 || p.paths[row].tool >= static_cast<int>(p.tools.size())) {
    workbench().partView.setToolOverlay(std::nullopt);
    return;
  }
  const planning::ToolPath& path = p.paths[static_cast<std::size_t>(row)];
  runUserAction(workbench().reportError, tr("Show tool"), [&] {
    workbench().partView.setToolOverlay(
        std::make_pair(p.tools[static_cast<std::size_t>(path.tool)], path.poses.front().pose));
  });
}

bool SimulationPanel::simulatePath(int index) {
  const planning::Project& p = workbench().document.project();
  bool started = false;
  runUserAction(workbench().reportError, tr("Simulate path"), [&] {
    if (!p.part) throw InvalidInput("there is no part to grind");
    if (index < 0 || index >= static_cast<int>(p.paths.size()))
      throw InvalidInput("select a tool path to simulate");
    const planning::ToolPath& path = p.paths[static_cast<std::size_t>(index)];
    if (path.tool < 0 || path.tool >= static_cast<int>(p.tools.size()))
      throw InvalidInput("path '" + path.name + "' refers to a missing tool");
    // The job grinds a copy: a cancelled or failed run leaves the document as it was.
    auto part = std::make_shared<ddf::DisplacementField>(*p.part);
    const planning::Tool tool = p.tools[static_cast<std::size_t>(path.tool)];
    const auto title = tr("Simulate path '%1'").arg(QString::fromStdString(path.name));
    Workbench* wb = &workbench();
    started =
        wb->jobs.start(title, [part, tool, path, title, wb](const ProgressCallback& progress) {
          planning::PathSimulationParams params;
          params.progress = progress;
          planning::simulatePath(*part, tool, path, params);
          return std::function<void()>([part, path, title, wb] {
            planning::SimulationState state{"after " + path.name, part->allHeights()};
            wb->document.push(std::make_unique<SetHeightsCommand>(
                wb->document, title, part->allHeights(), std::move(state)));
          });
        });
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return started;
}

bool SimulationPanel::restoreState(int index) {
  const planning::Project& p = workbench().document.project();
  return runUserAction(workbench().reportError, tr("Restore state"), [&] {
    if (index < 0 || index >= static_cast<int>(p.states.size()))
      throw InvalidInput("select a simulation state to restore");
    const planning::SimulationState& state = p.states[static_cast<std::size_t>(index)];
    workbench().document.push(std::make_unique<SetHeightsCommand>(
        workbench().document, tr("Restore state '%1'").arg(QString::fromStdString(state.name)),
        state.heights));
  });
}

}  // namespace ddfcam::gui
