// SPDX-License-Identifier: MIT
// ddfcam gui: ToolsPanel.
#include <ddfcam/gui/panels/tools_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/panels/tool_editor.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/tool_commands.h>
#include <ddfcam/gui/tool_overlay.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/io/project/tool_library_file.h>

#include <QComboBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>
#include <numeric>

namespace ddfcam::gui {

namespace {

using planning::Tool;
using planning::ToolKind;

QString toolText(const Tool& t) {
  return QObject::tr("%1  (%2, R %3 mm)")
      .arg(QString::fromStdString(t.name), ToolEditor::kindName(t.kind))
      .arg(t.radiusMm);
}

QPushButton* addButton(QBoxLayout* layout, QWidget* parent, const QString& text, const char* name) {
  auto* button = new QPushButton(text, parent);
  button->setObjectName(name);
  layout->addWidget(button);
  return button;
}

/// Pose at which the tools panel draws tool @p index: the first pose of the first path using
/// it, else above the part.
Eigen::Isometry3d displayPose(const planning::Project& p, int index) {
  for (const planning::ToolPath& path : p.paths)
    if (path.tool == index && !path.poses.empty()) return path.poses.front().pose;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  if (p.part && p.part->vertexCount() > 0) {
    lo = hi = p.part->position(0);
    for (int v = 1; v < p.part->vertexCount(); ++v) {
      lo = lo.cwiseMin(p.part->position(v));
      hi = hi.cwiseMax(p.part->position(v));
    }
  }
  return toolShowcasePose(lo, hi, p.tools[static_cast<std::size_t>(index)]);
}

}  // namespace

Tool ToolsPanel::defaultTool(ToolKind kind) {
  Tool t;  // Tool{}: the roll R5 W10
  t.kind = kind;
  // Sizes of a cutter: flutes, shank and holder; of a belt wheel: arbor and flanges.
  auto sized = [&t](const char* name, double radius, double width, double edge, double shank,
                    double shankLength, double holder, double holderLength) {
    t.name = name;
    t.radiusMm = radius;
    t.widthMm = width;
    t.edgeRadiusMm = edge;
    t.shankRadiusMm = shank;
    t.shankLengthMm = shankLength;
    t.holderRadiusMm = holder;
    t.holderLengthMm = holderLength;
  };
  switch (kind) {
    case ToolKind::CylinderRoll:
      break;
    case ToolKind::Sphere:
      t.name = "ball R5";
      break;
    case ToolKind::BeltContactWheel:
      sized("belt wheel R25 W20", 25, 20, 2, 4, 15, 10, 3);
      break;
    case ToolKind::BallEnd:
      sized("ball-end R3", 3, 12, 0, 3, 20, 10, 20);
      break;
    case ToolKind::FlatEnd:
      sized("flat-end R4", 4, 12, 0, 4, 20, 10, 20);
      break;
    case ToolKind::TorusCutter:
      sized("torus R5 r1", 5, 12, 1, 5, 20, 10, 20);
      break;
  }
  return t;
}

ToolsPanel::ToolsPanel(Workbench& workbench, QWidget* parent) : Panel(workbench, parent) {
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget(this);
  list_->setObjectName("toolList");
  layout->addWidget(list_, 1);
  auto* adding = new QHBoxLayout;
  newKind_ = new QComboBox(this);
  newKind_->setObjectName("newToolKind");
  for (const ToolKind k : {ToolKind::CylinderRoll, ToolKind::BeltContactWheel, ToolKind::BallEnd,
                           ToolKind::FlatEnd, ToolKind::TorusCutter, ToolKind::Sphere})
    newKind_->addItem(ToolEditor::kindName(k), static_cast<int>(k));
  adding->addWidget(newKind_, 1);
  QPushButton* add = addButton(adding, this, tr("Add"), "addToolButton");
  layout->addLayout(adding);
  auto* editing = new QHBoxLayout;
  duplicate_ = addButton(editing, this, tr("Duplicate"), "duplicateToolButton");
  delete_ = addButton(editing, this, tr("Delete"), "deleteToolButton");
  layout->addLayout(editing);
  editor_ = new ToolEditor(this);
  editor_->setObjectName("toolEditor");
  layout->addWidget(editor_);
  auto* files = new QHBoxLayout;
  QPushButton* load = addButton(files, this, tr("Load library..."), "loadToolLibraryButton");
  save_ = addButton(files, this, tr("Save library..."), "saveToolLibraryButton");
  layout->addLayout(files);

  connect(add, &QPushButton::clicked, this,
          [this] { addTool(static_cast<ToolKind>(newKind_->currentData().toInt())); });
  connect(duplicate_, &QPushButton::clicked, this, [this] { duplicateTool(selectedTool()); });
  connect(delete_, &QPushButton::clicked, this, [this] { deleteTool(selectedTool()); });
  connect(editor_, &ToolEditor::edited, this,
          [this] { editTool(selectedTool(), editor_->tool()); });
  connect(load, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Load tool library"), {}, tr("Tool libraries (*.tools);;All files (*)"));
    if (!path.isEmpty()) loadLibrary(path);
  });
  connect(save_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save tool library"), {}, tr("Tool libraries (*.tools);;All files (*)"));
    if (!path.isEmpty()) saveLibrary(path);
  });
  connect(list_, &QListWidget::currentRowChanged, this, [this] {
    drawTool_ = true;
    showSelected();
  });
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & Change::Part) drawTool_ = false;
    if (what & (Change::Tools | Change::Paths | Change::Part)) refresh();
  });
  refresh();
}

int ToolsPanel::selectedTool() const {
  return list_->currentRow();
}

void ToolsPanel::selectTool(int index) {
  list_->setCurrentRow(index);
}

void ToolsPanel::refresh() {
  const planning::Project& p = workbench().document.project();
  const int row = list_->currentRow();
  {
    const QSignalBlocker block(list_);
    list_->clear();
    for (const Tool& t : p.tools) list_->addItem(toolText(t));
    const int count = static_cast<int>(p.tools.size());
    list_->setCurrentRow(count == 0 ? -1 : std::clamp(row, 0, count - 1));
  }
  showSelected();
}

void ToolsPanel::showSelected() {
  const planning::Project& p = workbench().document.project();
  const int row = selectedTool();
  const bool has = row >= 0 && row < static_cast<int>(p.tools.size());
  duplicate_->setEnabled(has);
  delete_->setEnabled(has);
  editor_->setEnabled(has);
  save_->setEnabled(!p.tools.empty());
  editor_->setMessage({});
  if (has) editor_->setTool(p.tools[static_cast<std::size_t>(row)]);
  if (!drawTool_) return;
  PartScene& scene = workbench().partView.scene();
  if (!has) {
    hideToolOverlay(scene);
  } else {
    try {
      showToolOverlay(scene, p.tools[static_cast<std::size_t>(row)], displayPose(p, row));
    } catch (const std::exception& e) {
      // A tool the project holds passed validateProject; a mesh failure is shown, not thrown.
      hideToolOverlay(scene);
      editor_->setMessage(QString::fromStdString(unrollMessage(e)));
    }
  }
  workbench().partView.view().requestRender();
}

void ToolsPanel::pushTools(std::vector<Tool> tools, std::vector<int> newIndexOfOld,
                           const QString& text) {
  workbench().document.push(std::make_unique<SetToolsCommand>(
      workbench().document, std::move(tools), std::move(newIndexOfOld), text));
}

bool ToolsPanel::addTool(ToolKind kind) {
  const Tool tool = defaultTool(kind);
  const bool ok = runUserAction(workbench().reportError, tr("Add tool"), [&] {
    const planning::Project& p = workbench().document.project();
    pushTools(toolsWithAppended(p, tool), {},
              tr("Add tool '%1'").arg(QString::fromStdString(tool.name)));
  });
  if (ok) selectTool(static_cast<int>(workbench().document.project().tools.size()) - 1);
  return ok;
}

bool ToolsPanel::duplicateTool(int index) {
  const bool ok = runUserAction(workbench().reportError, tr("Duplicate tool"), [&] {
    const planning::Project& p = workbench().document.project();
    if (index < 0 || index >= static_cast<int>(p.tools.size()))
      throw InvalidInput("select a tool to duplicate");
    Tool copy = p.tools[static_cast<std::size_t>(index)];
    copy.name += " copy";
    pushTools(toolsWithAppended(p, copy), {},
              tr("Duplicate tool '%1'").arg(QString::fromStdString(p.tools[index].name)));
  });
  if (ok) selectTool(static_cast<int>(workbench().document.project().tools.size()) - 1);
  return ok;
}

bool ToolsPanel::deleteTool(int index) {
  return runUserAction(workbench().reportError, tr("Delete tool"), [&] {
    const planning::Project& p = workbench().document.project();
    if (index < 0 || index >= static_cast<int>(p.tools.size()))
      throw InvalidInput("select a tool to delete");
    std::vector<Tool> tools = p.tools;
    tools.erase(tools.begin() + index);
    std::vector<int> map(p.tools.size());
    for (int i = 0; i < static_cast<int>(map.size()); ++i)
      map[i] = i < index ? i : (i == index ? -1 : i - 1);
    pushTools(std::move(tools), std::move(map),
              tr("Delete tool '%1'").arg(QString::fromStdString(p.tools[index].name)));
  });
}

bool ToolsPanel::editTool(int index, const Tool& tool) {
  const planning::Project& p = workbench().document.project();
  if (index < 0 || index >= static_cast<int>(p.tools.size())) return false;
  try {
    planning::validateTool(tool);
  } catch (const std::exception& e) {
    // Inline, not a dialog: the user is typing and fixes the field next.
    editor_->setMessage(QString::fromStdString(unrollMessage(e)));
    return false;
  }
  if (tool == p.tools[static_cast<std::size_t>(index)]) return true;
  return runUserAction(workbench().reportError, tr("Edit tool"), [&] {
    std::vector<Tool> tools = p.tools;
    tools[static_cast<std::size_t>(index)] = tool;
    pushTools(std::move(tools), {}, tr("Edit tool '%1'").arg(QString::fromStdString(tool.name)));
  });
}

bool ToolsPanel::loadLibrary(const QString& path) {
  return runUserAction(workbench().reportError, tr("Load tool library"), [&] {
    const std::vector<Tool> loaded = io::readToolLibrary(path.toStdString());
    if (loaded.empty()) throw InvalidInput("tool library '" + path.toStdString() + "' is empty");
    const planning::Project& p = workbench().document.project();
    std::vector<Tool> tools = p.tools;
    tools.insert(tools.end(), loaded.begin(), loaded.end());
    const int first = static_cast<int>(p.tools.size());
    pushTools(std::move(tools), {}, tr("Load %1 tools").arg(loaded.size()));
    selectTool(first);
  });
}

bool ToolsPanel::saveLibrary(const QString& path) {
  return runUserAction(workbench().reportError, tr("Save tool library"), [&] {
    const planning::Project& p = workbench().document.project();
    if (p.tools.empty()) throw InvalidInput("the project has no tools to save");
    io::writeToolLibrary(path.toStdString(), p.tools);
  });
}

}  // namespace ddfcam::gui
