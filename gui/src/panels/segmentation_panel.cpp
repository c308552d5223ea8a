// SPDX-License-Identifier: MIT
// ddfcam gui: SegmentationPanel.
#include <ddfcam/gui/panels/segmentation_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/interaction_mode.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/panels/region_plan_editor.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/region_commands.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/analysis/region_editing.h>
#include <ddfcam/planning/analysis/segmentation.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPixmap>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>

namespace ddfcam::gui {
namespace {

QIcon swatch(const std::array<float, 3>& color) {
  QPixmap pixmap(14, 14);
  pixmap.fill(QColor::fromRgbF(color[0], color[1], color[2]));
  return QIcon(pixmap);
}

}  // namespace

SegmentationPanel::SegmentationPanel(Workbench& workbench, QWidget* parent)
    : Panel(workbench, parent) {
  tool_ = new RegionViewTool(
      workbench,
      [this] {
        const std::vector<int> selected = selectedRegions();
        return selected.empty() ? -1 : selected.front();
      },
      this);
  plan_ = new RegionPlanEditor(this);
  plan_->setObjectName("regionPlanEditor");
  status_ = new QLabel(this);
  status_->setObjectName("segmentationStatus");
  status_->setWordWrap(true);
  auto* planGroup = new QGroupBox(tr("Plan of the selected region"), this);
  (new QVBoxLayout(planGroup))->addWidget(plan_);
  // Many controls: they scroll, so the dock (tabbed with the other panels) stays small.
  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  layout->addWidget(buildAutomaticGroup());
  layout->addWidget(buildRegionGroup());
  layout->addWidget(buildPaintGroup());
  layout->addWidget(planGroup);
  layout->addWidget(status_);
  layout->addStretch(1);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(content);
  for (QComboBox* box : content->findChildren<QComboBox*>()) {
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(8);
  }
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  outer->addWidget(scroll);

  connect(plan_, &RegionPlanEditor::planEdited, this,
          [this](const planning::RegionPlan& plan) { setSelectedPlan(plan); });
  connect(tool_, &RegionViewTool::refused, this,
          [this](const QString& message) { status_->setText(message); });
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & (Change::Regions | Change::Part)) refreshList();
    if (what & Change::Part) updateMethodControls();
    if (what & (Change::Regions | Change::Part | Change::Tools)) refreshPlan();
  });
  refreshList();
  refreshPlan();
}

SegmentationPanel::~SegmentationPanel() = default;

QWidget* SegmentationPanel::buildAutomaticGroup() {
  auto* group = new QGroupBox(tr("Automatic segmentation"), this);
  method_ = new QComboBox(group);
  method_->setObjectName("segmentationMethod");
  method_->addItems({tr("by curvature type"), tr("by tool-radius classes"), tr("by CAD face")});
  flatThreshold_ = new QDoubleSpinBox(group);
  flatThreshold_->setObjectName("segmentationFlatThreshold");
  flatThreshold_->setDecimals(5);
  flatThreshold_->setRange(0.0, 10.0);
  flatThreshold_->setSingleStep(0.001);
  flatThreshold_->setValue(planning::CurvatureTypeParams{}.flatCurvaturePerMm);
  flatThreshold_->setSuffix(" 1/mm");
  toolRadii_ = new QLineEdit("2, 5, 10", group);
  toolRadii_->setObjectName("segmentationToolRadii");
  minFaces_ = new QSpinBox(group);
  minFaces_->setObjectName("segmentationMinFaces");
  minFaces_->setRange(1, 1'000'000);
  minFaces_->setValue(planning::SegmentationParams{}.minFaces);
  auto* run = new QPushButton(tr("Segment"), group);
  run->setObjectName("segmentButton");
  auto* form = new QFormLayout(group);
  form->addRow(tr("Method"), method_);
  form->addRow(tr("Flat below |k|"), flatThreshold_);
  form->addRow(tr("Tool radii [mm]"), toolRadii_);
  form->addRow(tr("Min. region faces"), minFaces_);
  form->addRow(run);
  connect(method_, &QComboBox::currentIndexChanged, this, [this] { updateMethodControls(); });
  updateMethodControls();
  connect(run, &QPushButton::clicked, this, [this] { segment(); });
  return group;
}

QWidget* SegmentationPanel::buildRegionGroup() {
  auto* group = new QGroupBox(tr("Regions"), this);
  list_ = new QTreeWidget(group);
  list_->setObjectName("regionList");
  list_->setColumnCount(2);
  list_->setHeaderLabels({tr("Region"), tr("Faces")});
  list_->setRootIsDecorated(false);
  list_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  list_->header()->setStretchLastSection(false);
  list_->header()->setSectionResizeMode(0, QHeaderView::Stretch);
  list_->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  list_->setMinimumHeight(120);
  showColours_ = new QCheckBox(tr("Colour the part by region"), group);
  showColours_->setObjectName("showRegionColours");
  showColours_->setChecked(true);
  auto* buttons = new QHBoxLayout;
  const auto button = [&](const QString& text, const char* name, auto slot) {
    auto* b = new QPushButton(text, group);
    b->setObjectName(name);
    buttons->addWidget(b);
    connect(b, &QPushButton::clicked, this, slot);
  };
  button(tr("New"), "addRegionButton", [this] { addRegion(); });
  button(tr("Merge"), "mergeRegionsButton", [this] { mergeSelected(); });
  button(tr("Split"), "splitRegionButton", [this] { splitSelected(); });
  button(tr("Delete"), "deleteRegionButton", [this] { deleteSelected(); });
  auto* layout = new QVBoxLayout(group);
  layout->addWidget(list_);
  layout->addLayout(buttons);
  layout->addWidget(showColours_);
  connect(showColours_, &QCheckBox::toggled, tool_, &RegionViewTool::setColoursVisible);
  // Region colours are drawn over the surface: a field the user picks would stay hidden.
  connect(&workbench().partView, &PartView::fieldDisplayChanged, this, [this] {
    const std::string& shown = workbench().partView.fieldDisplay().field;
    if (!shown.empty() && shown != lastShownField_) showColours_->setChecked(false);
    lastShownField_ = shown;
  });
  connect(list_, &QTreeWidget::itemSelectionChanged, this, [this] {
    if (!refreshing_) refreshPlan();
  });
  connect(list_, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
    if (refreshing_ || column != 0) return;
    renameRegion(list_->indexOfTopLevelItem(item), item->text(0));
  });
  return group;
}

QWidget* SegmentationPanel::buildPaintGroup() {
  auto* group = new QGroupBox(tr("Paint on the part"), this);
  mode_ = new QComboBox(group);
  mode_->setObjectName("regionEditMode");
  mode_->addItems({tr("off (camera)"), tr("brush"), tr("eraser"), tr("lasso")});
  radius_ = new QDoubleSpinBox(group);
  radius_->setObjectName("brushRadius");
  radius_->setRange(0.01, 1000.0);
  radius_->setDecimals(2);
  radius_->setValue(1.0);
  radius_->setSuffix(" mm");
  auto* form = new QFormLayout(group);
  form->addRow(tr("Left drag"), mode_);
  form->addRow(tr("Brush radius"), radius_);
  connect(mode_, &QComboBox::currentIndexChanged, this, [this](int index) {
    tool_->setMode(static_cast<RegionEditMode>(index));
    announceEditMode(static_cast<RegionEditMode>(index));
  });
  connect(radius_, &QDoubleSpinBox::valueChanged, this,
          [this](double r) { tool_->setBrushRadiusMm(r); });
  tool_->setBrushRadiusMm(radius_->value());
  return group;
}

void SegmentationPanel::setSegmentationOptions(SegmentationMethod method, double flatCurvaturePerMm,
                                               const std::vector<double>& toolRadiiMm,
                                               int minFaces) {
  method_->setCurrentIndex(static_cast<int>(method));
  flatThreshold_->setValue(flatCurvaturePerMm);
  QStringList radii;
  for (double r : toolRadiiMm) radii << QString::number(r);
  toolRadii_->setText(radii.join(", "));
  minFaces_->setValue(minFaces);
}

std::vector<int> SegmentationPanel::selectedRegions() const {
  std::vector<int> out;
  for (QTreeWidgetItem* item : list_->selectedItems())
    out.push_back(list_->indexOfTopLevelItem(item));
  std::sort(out.begin(), out.end());
  return out;
}

void SegmentationPanel::selectRegions(const std::vector<int>& indices) {
  refreshing_ = true;
  list_->clearSelection();
  for (int i : indices)
    if (QTreeWidgetItem* item = list_->topLevelItem(i)) item->setSelected(true);
  if (!indices.empty() && list_->topLevelItem(indices.front()))
    list_->setCurrentItem(list_->topLevelItem(indices.front()), 0, QItemSelectionModel::NoUpdate);
  refreshing_ = false;
  refreshPlan();
}

bool SegmentationPanel::pushRegions(
    const QString& text,
    const std::function<std::vector<planning::Region>(const std::vector<planning::Region>&)>&
        edit) {
  return runUserAction(workbench().reportError, text, [&] {
    Document& document = workbench().document;
    std::vector<planning::Region> after = edit(document.project().regions);
    document.push(std::make_unique<SetRegionsCommand>(document, text, std::move(after)));
  });
}

bool SegmentationPanel::addRegion() {
  const auto& project = workbench().document.project();
  if (!project.part) return false;
  const int index = static_cast<int>(project.regions.size());
  const std::string name = "region " + std::to_string(index + 1);
  const bool ok = pushRegions(tr("New region"), [&](const auto& regions) {
    return planning::assignFaces(regions, index, std::vector<int>{}, project.part->faceCount(),
                                 name);
  });
  if (ok) selectRegions({index});
  return ok;
}

bool SegmentationPanel::renameRegion(int index, const QString& name) {
  const auto& regions = workbench().document.project().regions;
  if (index >= 0 && index < static_cast<int>(regions.size()) &&
      regions[index].name == name.toStdString())
    return false;
  const bool ok = pushRegions(tr("Rename region to '%1'").arg(name), [&](const auto& r) {
    return planning::renameRegion(r, index, name.toStdString());
  });
  if (!ok) refreshList();  // show the old name again
  return ok;
}

bool SegmentationPanel::mergeSelected() {
  const std::vector<int> selected = selectedRegions();
  const bool ok = pushRegions(tr("Merge %1 regions").arg(selected.size()),
                              [&](const auto& r) { return planning::mergeRegions(r, selected); });
  if (ok) selectRegions({selected.front()});
  return ok;
}

bool SegmentationPanel::splitSelected() {
  const std::vector<int> selected = selectedRegions();
  if (selected.empty()) return false;
  const auto& part = workbench().document.project().part;
  if (!part) return false;
  std::vector<planning::Region> after = workbench().document.project().regions;
  // From the back, so the indices of the regions still to split stay valid.
  for (auto it = selected.rbegin(); it != selected.rend(); ++it)
    after = planning::splitConnectedParts(*part, after, *it);
  if (after == workbench().document.project().regions) {
    status_->setText(tr("The selected regions are connected; nothing to split."));
    return false;
  }
  return pushRegions(tr("Split regions into connected parts"), [&](const auto&) { return after; });
}

bool SegmentationPanel::deleteSelected() {
  const std::vector<int> selected = selectedRegions();
  if (selected.empty()) return false;
  return pushRegions(tr("Delete %1 regions").arg(selected.size()), [&](const auto& regions) {
    std::vector<planning::Region> out = regions;
    for (auto it = selected.rbegin(); it != selected.rend(); ++it)
      out = planning::removeRegion(out, *it);
    return out;
  });
}

bool SegmentationPanel::setSelectedPlan(const planning::RegionPlan& plan) {
  const std::vector<int> selected = selectedRegions();
  if (selected.empty()) return false;
  const auto& regions = workbench().document.project().regions;
  if (regions[selected.front()].plan == plan) return false;
  const QString name = QString::fromStdString(regions[selected.front()].name);
  return pushRegions(tr("Change plan of '%1'").arg(name), [&](const auto& r) {
    return planning::setRegionPlan(r, selected.front(), plan);
  });
}

void SegmentationPanel::announceEditMode(RegionEditMode mode) {
  InteractionMode* modes = workbench().mode;
  if (!modes) return;
  if (mode == RegionEditMode::None) return modes->clear(this);
  static const QString names[] = {QString(), tr("Brush"), tr("Eraser"), tr("Lasso")};
  static const QString hints[] = {QString(), tr("drag paints faces"),
                                  tr("drag erases faces"),
                                  tr("drag draws a lasso")};
  const int i = static_cast<int>(mode);
  modes->begin(this, names[i], hints[i], [this] { mode_->setCurrentIndex(0); });
}

void SegmentationPanel::setEditMode(RegionEditMode mode) {
  mode_->setCurrentIndex(static_cast<int>(mode));
}

void SegmentationPanel::setBrushRadiusMm(double radiusMm) {
  radius_->setValue(radiusMm);
}

void SegmentationPanel::refreshList() {
  const std::vector<int> selected = selectedRegions();
  const auto& regions = workbench().document.project().regions;
  refreshing_ = true;
  list_->clear();
  for (const planning::Region& region : regions) {
    auto* item = new QTreeWidgetItem(list_);
    item->setText(0, QString::fromStdString(region.name));
    item->setText(1, QString::number(region.faces.size()));
    item->setTextAlignment(1, Qt::AlignRight | Qt::AlignVCenter);
    item->setIcon(0, swatch(region.color));
    item->setFlags(item->flags() | Qt::ItemIsEditable);
  }
  refreshing_ = false;
  std::vector<int> keep;
  for (int i : selected)
    if (i < static_cast<int>(regions.size())) keep.push_back(i);
  if (keep.empty() && !selected.empty() && !regions.empty())
    keep.push_back(static_cast<int>(regions.size()) - 1);
  selectRegions(keep);
}

void SegmentationPanel::refreshPlan() {
  const std::vector<int> selected = selectedRegions();
  const planning::Project& project = workbench().document.project();
  plan_->setEnabled(!selected.empty());
  plan_->setPlan(selected.empty() ? planning::RegionPlan{} : project.regions[selected.front()].plan,
                 project.tools);
}

}  // namespace ddfcam::gui
