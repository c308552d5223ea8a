// SPDX-License-Identifier: MIT
// ddfcam gui: SimulationPanel.
#include <ddfcam/gui/panels/simulation_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/panels/simulation_options.h>
#include <ddfcam/gui/panels/simulation_playback.h>
#include <ddfcam/gui/panels/tool_editor.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/path_commands.h>
#include <ddfcam/gui/tool_overlay.h>
#include <ddfcam/gui/vtk_view.h>

#include <QAction>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QVBoxLayout>

#include <memory>

namespace ddfcam::gui {

namespace {

QString toolText(const planning::Tool& t) {
  return QObject::tr("%1  (%2, R %3 mm)")
      .arg(QString::fromStdString(t.name), ToolEditor::kindName(t.kind))
      .arg(t.radiusMm);
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

QPushButton* makeButton(const QString& text, const char* name, QWidget* parent) {
  auto* button = new QPushButton(text, parent);
  button->setObjectName(name);
  return button;
}

QLabel* makeLabel(const char* name, QWidget* parent) {
  auto* label = new QLabel(parent);
  label->setObjectName(name);
  label->setWordWrap(true);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  return label;
}

QSpinBox* makeIntSpin(const char* name, int lo, int hi, int value, QWidget* parent) {
  auto* spin = new QSpinBox(parent);
  spin->setObjectName(name);
  spin->setRange(lo, hi);
  spin->setValue(value);
  return spin;
}

}  // namespace

SimulationPanel::SimulationPanel(Workbench& workbench, QWidget* parent) : Panel(workbench, parent) {
  auto* run = new QAction(tr("&Simulate selected path"), this);
  run->setObjectName("actionSimulatePath");
  connect(run, &QAction::triggered, this, [this] { simulatePath(paths_->currentRow()); });
  actions_ << run;
  // The panel is taller than most docks: it scrolls rather than squashing its lists.
  auto* scroll = new QScrollArea(this);
  scroll->setObjectName("simulationScroll");
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  auto* content = new QWidget(scroll);
  auto* layout = new QVBoxLayout(content);
  tools_ = addList(layout, this, tr("Tools"), "toolList");
  paths_ = addList(layout, this, tr("Tool paths"), "pathList");
  layout->addWidget(makeWorkpieceGroup());
  auto* optionsBox = new QGroupBox(tr("Simulation options"), this);
  options_ = new SimulationOptions(optionsBox);
  options_->setObjectName("simulationOptions");
  (new QVBoxLayout(optionsBox))->addWidget(options_);
  layout->addWidget(optionsBox);
  simulate_ = new QPushButton(tr("Simulate path"), this);
  simulate_->setObjectName("simulateButton");
  layout->addWidget(simulate_);
  report_ = makeLabel("simulationReport", this);
  layout->addWidget(report_);
  layout->addWidget(makeCorrectionGroup());
  layout->addWidget(new QLabel(tr("Playback"), this));
  playback_ = new SimulationPlayback(workbench, {}, this);
  playback_->setObjectName("playback");
  layout->addWidget(playback_);
  states_ = addList(layout, this, tr("Simulation states"), "stateList");
  restore_ = new QPushButton(tr("Restore state"), this);
  restore_->setObjectName("restoreStateButton");
  layout->addWidget(restore_);
  scroll->setWidget(content);
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  outer->addWidget(scroll);
  connect(simulate_, &QPushButton::clicked, run, &QAction::trigger);
  connect(restore_, &QPushButton::clicked, this, [this] { restoreState(states_->currentRow()); });
  connect(paths_, &QListWidget::currentRowChanged, this, [this] {
    showFeedOfSelectedPath();
    playback_->setPathIndex(paths_->currentRow());
    if (!playback_->isActive()) showToolOfSelectedPath();
  });
  connect(playback_, &SimulationPlayback::ended, this, [this] { showToolOfSelectedPath(); });
  connect(options_, &SimulationOptions::changed, this, &SimulationPanel::applyOptions);
  connect(options_, &SimulationOptions::feedEdited, this,
          [this](double feed) { setPathFeed(paths_->currentRow(), feed); });
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & (Change::Tools | Change::Paths | Change::States | Change::Part)) refresh();
  });
  applyOptions();
  refresh();
}

QWidget* SimulationPanel::makeWorkpieceGroup() {
  auto* box = new QGroupBox(tr("Workpiece"), this);
  auto* grid = new QGridLayout(box);
  allowance_ = new QDoubleSpinBox(box);
  allowance_->setObjectName("allowanceSpin");
  allowance_->setRange(-10.0, 10.0);
  allowance_->setDecimals(3);
  allowance_->setSingleStep(0.05);
  allowance_->setValue(0.2);
  allowance_->setSuffix(tr(" mm"));
  raise_ = makeButton(tr("Raise by stock allowance"), "raiseAllowanceButton", box);
  raise_->setToolTip(
      tr("Raise the part along its normal by the allowance; the current heights "
         "are kept as state 'design' for the error map"));
  stockMesh_ = makeButton(tr("Stock from mesh..."), "stockMeshButton", box);
  workpieceLabel_ = makeLabel("workpieceLabel", box);
  grid->addWidget(allowance_, 0, 0);
  grid->addWidget(raise_, 0, 1);
  grid->addWidget(stockMesh_, 1, 0, 1, 2);
  grid->addWidget(workpieceLabel_, 2, 0, 1, 2);
  connect(raise_, &QPushButton::clicked, this, [this] { raiseByAllowance(allowance_->value()); });
  connect(stockMesh_, &QPushButton::clicked, this, [this] {
    const QString file = QFileDialog::getOpenFileName(
        this, tr("Stock mesh"), {}, tr("Meshes (*.stl *.obj *.ply *.off);;All files (*)"));
    if (!file.isEmpty()) stockFromMesh(file);
  });
  return box;
}

QWidget* SimulationPanel::makeCorrectionGroup() {
  auto* box = new QGroupBox(tr("Penetration correction"), this);
  auto* grid = new QGridLayout(box);
  correctionGrid_ = makeIntSpin("correctionGridSpin", 2, 1000, 50, box);
  correctionGrid_->setToolTip(tr("Tangential grid cells per axis"));
  correctionEvery_ = makeIntSpin("correctionEverySpin", 1, 1000, 1, box);
  correctionEvery_->setToolTip(
      tr("Exact lift at every k-th pose, interpolated and checked "
         "in between"));
  correct_ = makeButton(tr("Correct penetrations"), "correctPenetrationsButton", box);
  correctionLabel_ = makeLabel("correctionLabel", box);
  grid->addWidget(new QLabel(tr("Grid"), box), 0, 0);
  grid->addWidget(correctionGrid_, 0, 1);
  grid->addWidget(new QLabel(tr("Every"), box), 0, 2);
  grid->addWidget(correctionEvery_, 0, 3);
  grid->addWidget(correct_, 1, 0, 1, 4);
  grid->addWidget(correctionLabel_, 2, 0, 1, 4);
  connect(correct_, &QPushButton::clicked, this, [this] {
    correctPenetrations(paths_->currentRow(), correctionGrid_->value(), correctionEvery_->value());
  });
  return box;
}

void SimulationPanel::applyOptions() {
  playback_->setSimulationParams(options_->grindingParams());
  const bool preston = options_->removalModel() == RemovalModel::Preston;
  if (preston && playback_->isActive()) playback_->cancel();
  playback_->setEnabled(!preston);
  playback_->setToolTip(preston ? tr("Playback cuts rigidly with the depth buffer; the Preston "
                                     "model runs only with 'Simulate path'")
                                : QString());
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
  raise_->setEnabled(p.part.has_value());
  stockMesh_->setEnabled(p.part.has_value());
  correct_->setEnabled(paths > 0 && p.part.has_value());
  showFeedOfSelectedPath();
}

void SimulationPanel::showFeedOfSelectedPath() {
  const planning::Project& p = workbench().document.project();
  const int row = paths_->currentRow();
  if (row >= 0 && row < static_cast<int>(p.paths.size()))
    options_->showFeed(p.paths[static_cast<std::size_t>(row)].feedMmPerMin);
}

bool SimulationPanel::setPathFeed(int index, double feedMmPerMin) {
  Document& document = workbench().document;
  const planning::Project& p = document.project();
  if (index < 0 || index >= static_cast<int>(p.paths.size())) return false;
  planning::ToolPath path = p.paths[static_cast<std::size_t>(index)];
  if (path.feedMmPerMin == feedMmPerMin) return false;
  path.feedMmPerMin = feedMmPerMin;
  const QString text = tr("Set feed of path '%1' to %2 mm/min")
                           .arg(QString::fromStdString(path.name))
                           .arg(feedMmPerMin);
  return runUserAction(workbench().reportError, text, [&] {
    document.push(std::make_unique<ReplacePathCommand>(document, index, std::move(path), text));
  });
}

void SimulationPanel::showToolOfSelectedPath() {
  const planning::Project& p = workbench().document.project();
  const int row = paths_->currentRow();
  PartScene& scene = workbench().partView.scene();
  if (row < 0 || row >= static_cast<int>(p.paths.size()) || p.paths[row].poses.empty() ||
      p.paths[row].tool < 0 || p.paths[row].tool >= static_cast<int>(p.tools.size())) {
    hideToolOverlay(scene);
  } else {
    const planning::ToolPath& path = p.paths[static_cast<std::size_t>(row)];
    runUserAction(workbench().reportError, tr("Show tool"), [&] {
      showToolOverlay(scene, p.tools[static_cast<std::size_t>(path.tool)], path.poses.front().pose);
    });
  }
  workbench().partView.view().requestRender();
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
