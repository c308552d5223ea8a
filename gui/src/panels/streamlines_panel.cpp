// SPDX-License-Identifier: MIT
// ddfcam gui: StreamlinesPanel, its widgets and settings (actions: streamlines_panel_actions.cpp).
#include <ddfcam/gui/panels/streamlines_panel.h>

#include <ddfcam/gui/document.h>
#include <ddfcam/gui/flow_field_display.h>
#include <ddfcam/gui/interaction_mode.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/path_list.h>
#include <ddfcam/gui/vtk_view.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace ddfcam::gui {

namespace {

// Direction combo items, in order.
enum DirectionItem { AlongMax = 0, AlongMin, FixedX, FixedY, FixedZ, DrawnStrokes };

QString swatch(const std::array<double, 3>& rgb) {
  return QString("QCheckBox { color: rgb(%1, %2, %3); font-weight: bold; }")
      .arg(std::lround(255 * rgb[0]))
      .arg(std::lround(255 * rgb[1]))
      .arg(std::lround(255 * rgb[2]));
}

}  // namespace

StreamlinesPanel::StreamlinesPanel(Workbench& workbench, QWidget* parent)
    : Panel(workbench, parent),
      display_(std::make_unique<FlowFieldDisplay>(workbench.partView.scene())) {
  for (int g = 0; g < kGlyphFieldCount; ++g)
    display_->setVisible(static_cast<GlyphField>(g), false);
  display_->setSingularitiesVisible(false);
  status_ = new QLabel(tr("Pick a point on the part, then seed."), this);
  status_->setObjectName("streamlineStatus");
  status_->setWordWrap(true);
  pathList_ = new PathListWidget(this);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(buildFieldGroup());
  layout->addWidget(buildSeedGroup());
  layout->addWidget(buildSmoothingGroup());
  layout->addWidget(buildPlacementGroup());
  layout->addWidget(pathList_, 1);
  layout->addWidget(status_);
  connect(&workbench.partView, &PartView::picked, this, &StreamlinesPanel::onPicked);
  viewWidget_ = &workbench.partView.view();
  viewWidget_->installEventFilter(this);
  connect(pathList_, &PathListWidget::selectionChanged, this, [this](int index) {
    this->workbench().partView.setSelectedPath(index);  // highlighted in the view
    updatePreview();
  });
  connect(pathList_, &PathListWidget::visibilityChanged, this, [this](int index, bool on) {
    const auto& paths = this->workbench().document.project().paths;
    if (index >= 0 && index < static_cast<int>(paths.size()))
      this->workbench().partView.setPathVisible(paths[static_cast<std::size_t>(index)].name, on);
  });
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & (Change::Part | Change::Heights)) {
      ++generation_;
      fields_.reset();
      display_->clear();
    }
    if (what & Change::Part) {
      lastPick_.reset();
      strokes_.clear();  // the panel's own; region strokes went with the regions
      stroke_.reset();
    }
    if (what & (Change::Part | Change::Regions)) {
      refreshRegions();
      showStrokes();  // a region's strokes may have changed (drawn, cleared, undone)
    }
    if (what & (Change::Part | Change::Paths)) {
      refreshPathList();
      updatePreview();
    }
  });
  refreshRegions();
  refreshPathList();
}

void StreamlinesPanel::refreshPathList() {
  PartView& view = workbench().partView;
  pathList_->refresh(workbench().document.project(),
                     [&view](const std::string& name) { return view.isPathVisible(name); });
  view.setSelectedPath(pathList_->selectedPath());
}

StreamlinesPanel::~StreamlinesPanel() = default;

QLayout* StreamlinesPanel::buildDrawRow(QWidget* group) {
  draw_ = new QToolButton(group);
  draw_->setObjectName("drawDirectionButton");
  draw_->setText(tr("Draw direction"));
  draw_->setToolTip(tr("Drag on the part to draw the flow direction"));
  draw_->setCheckable(true);
  connect(draw_, &QToolButton::toggled, this, [this](bool on) {
    InteractionMode* modes = workbench().mode;
    if (!modes) return;
    if (!on) return modes->clear(this);
    modes->begin(this, tr("Draw direction"), tr("drag draws the flow direction"),
                 [this] { draw_->setChecked(false); });
  });
  auto* clear = new QToolButton(group);
  clear->setObjectName("clearStrokesButton");
  clear->setText(tr("Clear strokes"));
  connect(clear, &QToolButton::clicked, this, [this] { clearStrokes(); });
  auto* row = new QHBoxLayout;
  row->addWidget(draw_);
  row->addWidget(clear);
  row->addStretch(1);
  return row;
}

QLayout* StreamlinesPanel::buildGlyphToggles(QWidget* group) {
  auto* toggles = new QHBoxLayout;
  const QStringList names = {tr("flow"), tr("k_max"), tr("k_min"), tr("singularities")};
  for (int t = 0; t < names.size(); ++t) {
    auto* box = new QCheckBox(names[t], group);
    box->setObjectName(QString("glyphToggle%1").arg(t));
    box->setStyleSheet(swatch(t < kGlyphFieldCount
                                  ? FlowFieldDisplay::colour(static_cast<GlyphField>(t))
                                  : FlowFieldDisplay::singularityColour(true)));
    toggles->addWidget(box);
    glyphToggles_.push_back(box);
    connect(box, &QCheckBox::toggled, this, [this, t](bool on) {
      if (t < kGlyphFieldCount)
        display_->setVisible(static_cast<GlyphField>(t), on);
      else
        display_->setSingularitiesVisible(on);
      if (on && !display_->hasFields() && !workbench().jobs.isRunning()) showField();
      workbench().partView.view().requestRender();
    });
  }
  return toggles;
}

QWidget* StreamlinesPanel::buildFieldGroup() {
  auto* group = new QGroupBox(tr("Tool flow field"), this);
  region_ = new QComboBox(group);
  region_->setObjectName("streamlineRegionCombo");
  direction_ = new QComboBox(group);
  direction_->setObjectName("streamlineDirectionCombo");
  direction_->addItems({tr("along k_max (lines of max. curvature)"),
                        tr("along k_min (lines of min. curvature)"), tr("fixed direction x"),
                        tr("fixed direction y"), tr("fixed direction z"), tr("drawn strokes")});
  QLayout* drawRow = buildDrawRow(group);
  smooth_ = new QCheckBox(tr("Smooth (Ceres)"), group);
  smooth_->setObjectName("smoothFieldCheck");
  weight_ = new QDoubleSpinBox(group);
  weight_->setObjectName("smoothnessWeight");
  weight_->setDecimals(3);
  weight_->setRange(0.0, 100.0);
  weight_->setSingleStep(0.01);
  weight_->setValue(0.02);
  weight_->setToolTip(tr("Smoothness weight lambda"));
  auto* smoothRow = new QHBoxLayout;
  smoothRow->addWidget(smooth_);
  smoothRow->addWidget(new QLabel(tr("weight"), group));
  smoothRow->addWidget(weight_);
  auto* show = new QPushButton(tr("Show field"), group);
  show->setObjectName("showFieldButton");
  QLayout* toggles = buildGlyphToggles(group);
  auto* form = new QFormLayout(group);
  form->addRow(tr("Region"), region_);
  form->addRow(tr("Direction"), direction_);
  form->addRow(drawRow);
  form->addRow(smoothRow);
  form->addRow(tr("Glyphs"), toggles);
  form->addRow(show);
  connect(show, &QPushButton::clicked, this, [this] { showField(); });
  connect(region_, &QComboBox::activated, this,
          [this](int item) { setRegion(region_->itemData(item).toInt()); });
  return group;
}

QWidget* StreamlinesPanel::buildSeedGroup() {
  auto* group = new QGroupBox(tr("Seeding"), this);
  seedByClick_ = new QToolButton(group);
  seedByClick_->setObjectName("seedByClickButton");
  seedByClick_->setText(tr("Seed by click"));
  seedByClick_->setCheckable(true);
  spacing_ = new QDoubleSpinBox(group);
  spacing_->setObjectName("streamlineSpacing");
  spacing_->setRange(0.05, 100.0);
  spacing_->setValue(2.0);
  spacing_->setSuffix(" mm");
  method_ = new QComboBox(group);
  method_->setObjectName("streamlineMethodCombo");
  method_->addItem(tr("RK4 in the support faces"),
                   static_cast<int>(planning::StreamlineMethod::Rk4));
  method_->addItem(tr("raster walk (error compensation, low-pass)"),
                   static_cast<int>(planning::StreamlineMethod::RasterWalk));
  method_->addItem(tr("continuous (3D steps, V-projection)"),
                   static_cast<int>(planning::StreamlineMethod::Continuous));
  method_->setToolTip(
      tr("Tracer of click seeding and of families (sec. 8.3). "
         "\"Cover region\" always traces with RK4."));
  auto* family = new QPushButton(tr("Seed family at last pick"), group);
  family->setObjectName("seedFamilyButton");
  dSep_ = new QDoubleSpinBox(group);
  dSep_->setObjectName("coverSeparation");
  dSep_->setRange(0.05, 100.0);
  dSep_->setValue(2.0);
  dSep_->setSuffix(" mm");
  auto* cover = new QPushButton(tr("Cover region"), group);
  cover->setObjectName("coverRegionButton");
  cover->setToolTip(
      tr("Evenly spaced lines (Jobard-Lefer), traced with RK4 whatever the "
         "method; a ball tool in a scallop-tolerance plan spaces them by "
         "curvature"));
  link_ = new QCheckBox(tr("Order and link lines (zig-zag)"), group);
  link_->setObjectName("linkLinesCheck");
  link_->setChecked(true);
  auto* form = new QFormLayout(group);
  form->addRow(seedByClick_);
  form->addRow(tr("Method"), method_);
  form->addRow(tr("Spacing w"), spacing_);
  form->addRow(family);
  form->addRow(tr("d_sep"), dSep_);
  form->addRow(cover);
  form->addRow(link_);
  connect(family, &QPushButton::clicked, this, [this] { seedFamily(); });
  connect(cover, &QPushButton::clicked, this, [this] { coverRegion(dSep_->value()); });
  return group;
}

QWidget* StreamlinesPanel::buildSmoothingGroup() {
  auto* group = new QGroupBox(tr("Smoothing of the selected path"), this);
  window_ = new QSlider(Qt::Horizontal, group);
  window_->setObjectName("smoothingWindowSlider");
  window_->setRange(0, 30);
  windowLabel_ = new QLabel(group);
  windowLabel_->setMinimumWidth(70);
  auto* apply = new QPushButton(tr("Apply"), group);
  apply->setObjectName("applySmoothingButton");
  deviation_ = new QDoubleSpinBox(group);
  deviation_->setObjectName("fairingDeviation");
  deviation_->setDecimals(3);
  deviation_->setRange(0.001, 10.0);
  deviation_->setValue(0.05);
  deviation_->setSuffix(" mm");
  auto* fair = new QPushButton(tr("Fair (Ceres)"), group);
  fair->setObjectName("fairPathButton");
  auto* row = new QHBoxLayout;
  row->addWidget(window_, 1);
  row->addWidget(windowLabel_);
  row->addWidget(apply);
  auto* fairRow = new QHBoxLayout;
  fairRow->addWidget(new QLabel(tr("max. deviation"), group));
  fairRow->addWidget(deviation_);
  fairRow->addWidget(fair);
  auto* form = new QFormLayout(group);
  form->addRow(tr("Moving average"), row);
  form->addRow(fairRow);
  connect(window_, &QSlider::valueChanged, this, [this] { updatePreview(); });
  connect(apply, &QPushButton::clicked, this, [this] { applySmoothing(); });
  connect(fair, &QPushButton::clicked, this, [this] { fairSelected(deviation_->value()); });
  updatePreview();
  return group;
}

void StreamlinesPanel::refreshRegions() {
  const QSignalBlocker block(region_);
  const int previous = region_->currentData().isValid() ? region_->currentData().toInt() : -1;
  region_->clear();
  region_->addItem(tr("whole part"), -1);
  const auto& regions = workbench().document.project().regions;
  for (std::size_t r = 0; r < regions.size(); ++r)
    region_->addItem(QString::fromStdString(regions[r].name), static_cast<int>(r));
  region_->setCurrentIndex(previous + 1 < region_->count() ? previous + 1 : 0);
  region_->setEnabled(!regions.empty());
}

FieldChoice StreamlinesPanel::currentChoice() const {
  FieldChoice choice;
  using Source = planning::FlowFieldSource;
  const int item = direction_->currentIndex();
  planning::RegionPlan& plan = choice.plan;
  plan.flowSource = item == AlongMax       ? Source::MaxCurvatureDirection
                    : item == AlongMin     ? Source::MinCurvatureDirection
                    : item == DrawnStrokes ? Source::UserStrokes
                                           : Source::FixedDirection;
  if (item >= FixedX && item <= FixedZ) plan.fixedDirection = ddf::Vec3::Unit(item - FixedX);
  if (item == DrawnStrokes) plan.strokes = strokes();
  plan.smoothField = smooth_->isChecked();
  plan.smoothnessWeight = weight_->value();
  const int region = region_->currentData().isValid() ? region_->currentData().toInt() : -1;
  const planning::Project& project = workbench().document.project();
  if (region >= 0 && region < static_cast<int>(project.regions.size()) && project.part)
    choice.faceMask = planning::regionFaceMask(*project.part, project.regions[region]);
  return choice;
}

void StreamlinesPanel::setFieldSource(planning::FlowFieldSource source,
                                      const ddf::Vec3& fixedDirection) {
  using Source = planning::FlowFieldSource;
  int item = source == Source::MinCurvatureDirection ? AlongMin : AlongMax;
  if (source == Source::UserStrokes) item = DrawnStrokes;
  if (source == Source::FixedDirection) {
    int axis = 0;
    fixedDirection.cwiseAbs().maxCoeff(&axis);
    item = FixedX + axis;
  }
  direction_->setCurrentIndex(item);
}

void StreamlinesPanel::setFieldSmoothing(bool on, double weight) {
  smooth_->setChecked(on);
  weight_->setValue(weight);
}

void StreamlinesPanel::setRegion(int index) {
  const auto& regions = workbench().document.project().regions;
  if (index < 0 || index >= static_cast<int>(regions.size())) {
    region_->setCurrentIndex(0);
    showStrokes();
    return;
  }
  region_->setCurrentIndex(index + 1);
  const planning::RegionPlan& plan = regions[index].plan;
  setFieldSource(plan.flowSource, plan.fixedDirection);
  setFieldSmoothing(plan.smoothField, plan.smoothnessWeight);
  spacing_->setValue(plan.spacingMm);
  dSep_->setValue(plan.spacingMm);
  showStrokes();
}

void StreamlinesPanel::setStreamlineMethod(planning::StreamlineMethod method) {
  method_->setCurrentIndex(method_->findData(static_cast<int>(method)));
}

planning::StreamlineMethod StreamlinesPanel::streamlineMethod() const {
  return static_cast<planning::StreamlineMethod>(method_->currentData().toInt());
}

void StreamlinesPanel::setSeedByClick(bool on) {
  seedByClick_->setChecked(on);
}

void StreamlinesPanel::onPicked(const PickResult& pick) {
  if (drawing_) return;  // a point of a stroke, not a seed
  lastPick_ = pick.location;
  if (seedByClick_->isChecked()) seedAt(pick.location);
}

void StreamlinesPanel::setSmoothingWindow(int halfWindow) {
  window_->setValue(halfWindow);
}

const planning::LineField* StreamlinesPanel::flowField() const {
  return fields_ ? &fields_->field : nullptr;
}

}  // namespace ddfcam::gui
