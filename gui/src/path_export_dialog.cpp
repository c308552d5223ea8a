// SPDX-License-Identifier: MIT
// ddfcam gui: PathExportDialog, the widgets that gather PathExportOptions.
#include <ddfcam/gui/path_export_dialog.h>

#include <ddfcam/planning/model/path_regions.h>
#include <ddfcam/planning/model/project.h>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <initializer_list>
#include <utility>
#include <vector>

namespace ddfcam::gui {

namespace {

QComboBox* makeCombo(QWidget* parent, const char* name,
                     std::initializer_list<std::pair<QString, int>> items) {
  auto* box = new QComboBox(parent);
  box->setObjectName(name);
  for (const auto& [text, value] : items) box->addItem(text, value);
  return box;
}

// The region of each path as the per-region export groups them; empty when there are no
// regions (or they cannot be located: the export itself reports that).
std::vector<int> regionOfPaths(const planning::Project& project) {
  if (!project.part || project.regions.empty()) return {};
  try {
    return planning::pathRegions(*project.part, project.regions, project.paths);
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace

PathExportDialog::PathExportDialog(const planning::Project& project,
                                   const PathExportOptions& initial, QWidget* parent)
    : QDialog(parent), project_(project) {
  setWindowTitle(tr("Export tool paths"));
  setObjectName("pathExportDialog");
  buildForm(initial);
  showOptions(normalisedExportOptions(initial));
  refresh();
}

void PathExportDialog::buildForm(const PathExportOptions& initial) {
  auto* form = new QFormLayout;
  auto named = [this](auto* widget, const char* name) {
    widget->setObjectName(name);
    return widget;
  };
  format_ = makeCombo(this, "exportFormat",
                      {{tr("CSV table"), int(PathExportFormat::Csv)},
                       {tr("APT / CLDATA"), int(PathExportFormat::Apt)},
                       {tr("G-code"), int(PathExportFormat::GCode)}});
  dialect_ = makeCombo(this, "exportDialect", {});
  coordinateDecimals_ = named(new QSpinBox(this), "exportCoordinateDecimals");
  vectorDecimals_ = named(new QSpinBox(this), "exportVectorDecimals");
  unit_ = makeCombo(this, "exportUnit",
                    {{tr("mm"), int(LengthUnit::Millimetre)}, {tr("inch"), int(LengthUnit::Inch)}});
  point_ = makeCombo(this, "exportPoint",
                     {{tr("contact point"), int(planning::ClPointKind::Contact)},
                      {tr("tool reference point"), int(planning::ClPointKind::ToolReference)}});
  grouping_ = makeCombo(this, "exportGrouping",
                        {{tr("all paths in one file"), int(PathExportGrouping::OneFile)},
                         {tr("one file per region"), int(PathExportGrouping::FilePerRegion)}});
  paths_ = named(new QListWidget(this), "exportPaths");
  fillPaths(initial);
  file_ = named(new QLineEdit(this), "exportFile");
  auto* browse = named(new QPushButton(tr("Browse..."), this), "exportBrowse");
  auto* fileRow = new QHBoxLayout;
  fileRow->addWidget(file_, 1);
  fileRow->addWidget(browse);
  machineFile_ = named(new QLineEdit(this), "exportMachineFile");
  machineFile_->setPlaceholderText(tr("none: the dialect's generic table"));
  machineFile_->setToolTip(
      tr("A machine file (JSON) with the rotary axes, their directions, pivot, limits, "
         "preferred solution and TCP; samples in resources/machines"));
  machineBrowse_ = named(new QPushButton(tr("Browse..."), this), "exportMachineBrowse");
  machineName_ = named(new QLabel(this), "exportMachineName");
  auto* machineRow = new QHBoxLayout;
  machineRow->addWidget(machineFile_, 1);
  machineRow->addWidget(machineBrowse_);
  form->addRow(tr("Format:"), format_);
  form->addRow(tr("Dialect:"), dialect_);
  form->addRow(tr("Machine:"), machineRow);
  form->addRow(QString(), machineName_);
  form->addRow(tr("Coordinate decimals:"), coordinateDecimals_);
  form->addRow(tr("Vector decimals:"), vectorDecimals_);
  form->addRow(tr("Unit:"), unit_);
  form->addRow(tr("Point:"), point_);
  form->addRow(tr("Files:"), grouping_);
  form->addRow(tr("Paths:"), paths_);
  form->addRow(tr("File:"), fileRow);
  problem_ = named(new QLabel(this), "exportProblem");
  problem_->setWordWrap(true);
  problem_->setStyleSheet("color: #b00020;");
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons_->button(QDialogButtonBox::Ok)->setText(tr("Export"));
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(problem_);
  layout->addWidget(buttons_);
  connect(browse, &QPushButton::clicked, this, &PathExportDialog::browse);
  connect(machineBrowse_, &QPushButton::clicked, this, &PathExportDialog::browseMachine);
  connectSignals();
}

void PathExportDialog::fillPaths(const PathExportOptions& initial) {
  const std::vector<int> regions = regionOfPaths(project_);
  for (std::size_t i = 0; i < project_.paths.size(); ++i) {
    const auto& path = project_.paths[i];
    QString text = tr("%1 (%2 poses").arg(QString::fromStdString(path.name)).arg(path.poses.size());
    if (i < regions.size() && regions[i] >= 0)
      text += tr(", region %1")
                  .arg(QString::fromStdString(project_.regions[std::size_t(regions[i])].name));
    auto* item = new QListWidgetItem(text + ")", paths_);
    item->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
    const bool on = initial.paths.empty() || std::find(initial.paths.begin(), initial.paths.end(),
                                                       int(i)) != initial.paths.end();
    item->setCheckState(on ? Qt::Checked : Qt::Unchecked);
  }
  paths_->setMaximumHeight(120);
}

void PathExportDialog::connectSignals() {
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(format_, &QComboBox::currentIndexChanged, this, [this] {
    if (updating_) return;
    PathExportOptions o = options();
    // The file follows the format: same folder and stem, the format's suffix.
    if (!o.filePath.isEmpty()) {
      const QFileInfo file(o.filePath);
      o.filePath =
          QDir(file.path()).filePath(file.completeBaseName() + "." + pathExportSuffix(o.format));
    }
    showOptions(normalisedExportOptions(o));
    refresh();
  });
  for (QComboBox* box : {dialect_, unit_, point_, grouping_})
    connect(box, &QComboBox::currentIndexChanged, this, &PathExportDialog::refresh);
  for (QSpinBox* box : {coordinateDecimals_, vectorDecimals_})
    connect(box, &QSpinBox::valueChanged, this, &PathExportDialog::refresh);
  connect(paths_, &QListWidget::itemChanged, this, &PathExportDialog::refresh);
  connect(file_, &QLineEdit::textChanged, this, &PathExportDialog::refresh);
  connect(machineFile_, &QLineEdit::textChanged, this, &PathExportDialog::refresh);
}

void PathExportDialog::fillDialects(PathExportFormat format) {
  dialect_->clear();
  if (format == PathExportFormat::Apt) {
    dialect_->addItem(tr("standard (FEDRAT/f,MMPM)"), int(PathExportDialect::AptStandard));
    dialect_->addItem(tr("NX CLSF (FEDRAT/MMPM,f)"), int(PathExportDialect::AptNx));
  } else if (format == PathExportFormat::GCode) {
    dialect_->addItem(tr("3-axis (X Y Z)"), int(PathExportDialect::GCode3Axis));
    dialect_->addItem(tr("5-axis, A/C table"), int(PathExportDialect::GCode5AxisAC));
    dialect_->addItem(tr("5-axis, B/C table"), int(PathExportDialect::GCode5AxisBC));
  }
  dialect_->setEnabled(format != PathExportFormat::Csv);
}

void PathExportDialog::showOptions(const PathExportOptions& o) {
  updating_ = true;
  format_->setCurrentIndex(format_->findData(int(o.format)));
  fillDialects(o.format);
  dialect_->setCurrentIndex(std::max(0, dialect_->findData(int(o.dialect))));
  const auto [low, high] = coordinateDecimalsRange(o.format);
  coordinateDecimals_->setRange(low, high);
  coordinateDecimals_->setValue(o.coordinateDecimals);
  vectorDecimals_->setRange(6, 9);
  vectorDecimals_->setValue(o.vectorDecimals);
  vectorDecimals_->setEnabled(o.format == PathExportFormat::Apt);
  unit_->setCurrentIndex(unit_->findData(int(o.unit)));
  point_->setCurrentIndex(point_->findData(int(o.point)));
  point_->setEnabled(o.format == PathExportFormat::Csv);
  grouping_->setCurrentIndex(grouping_->findData(int(o.grouping)));
  file_->setText(o.filePath);
  machineFile_->setText(o.machineFile);
  updating_ = false;
}

PathExportOptions PathExportDialog::options() const {
  PathExportOptions o;
  o.format = static_cast<PathExportFormat>(format_->currentData().toInt());
  if (dialect_->count() > 0)
    o.dialect = static_cast<PathExportDialect>(dialect_->currentData().toInt());
  o.coordinateDecimals = coordinateDecimals_->value();
  o.vectorDecimals = vectorDecimals_->value();
  o.unit = static_cast<LengthUnit>(unit_->currentData().toInt());
  o.point = static_cast<planning::ClPointKind>(point_->currentData().toInt());
  o.grouping = static_cast<PathExportGrouping>(grouping_->currentData().toInt());
  for (int i = 0; i < paths_->count(); ++i)
    if (paths_->item(i)->checkState() == Qt::Checked) o.paths.push_back(i);
  o.filePath = file_->text().trimmed();
  o.machineFile = machineFile_->text().trimmed();
  return o;
}

QString PathExportDialog::problem() const {
  return problem_->text();
}

void PathExportDialog::refresh() {
  if (updating_) return;
  const PathExportOptions o = options();
  const bool gcode = o.format == PathExportFormat::GCode;
  machineFile_->setEnabled(gcode);
  machineBrowse_->setEnabled(gcode);
  // With a machine file the dialect's generic table is not used.
  dialect_->setEnabled(o.format != PathExportFormat::Csv && (!gcode || o.machineFile.isEmpty()));
  const QString machine = gcode ? exportMachineName(o) : QString();
  machineName_->setText(machine);
  machineName_->setVisible(!machine.isEmpty());
  const QString text = pathExportProblem(project_, o);
  problem_->setText(text);
  problem_->setVisible(!text.isEmpty());
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(text.isEmpty());
}

void PathExportDialog::browse() {
  const PathExportOptions o = options();
  const QString suffix = pathExportSuffix(o.format);
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export tool paths"), o.filePath,
      tr("%1 files (*.%2);;All files (*)").arg(suffix.toUpper(), suffix));
  if (!path.isEmpty()) file_->setText(path);
}

void PathExportDialog::browseMachine() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Machine file"), machineFile_->text(),
                                                    tr("Machine files (*.json);;All files (*)"));
  if (!path.isEmpty()) machineFile_->setText(path);
}

}  // namespace ddfcam::gui
