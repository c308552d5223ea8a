// SPDX-License-Identifier: MIT
// ddfcam gui: importing path files: the dialog, the options and the undoable import.
#include <ddfcam/gui/path_import.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/console_dock.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/project_actions.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/planning/placement/cutter_tool.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

namespace ddfcam::gui {

namespace {

QString unitText(LengthUnit unit) {
  const std::string_view name = unitSymbol(unit);
  return QString::fromUtf8(name.data(), static_cast<int>(name.size()));
}

void logMessages(ConsoleDock* console, const QString& file,
                 const std::vector<planning::ClMessage>& messages) {
  if (!console) return;
  const QString name = QFileInfo(file).fileName();
  for (const auto& m : messages)
    console->appendMessage(LogLevel::Warning, m.line > 0
                                                  ? QObject::tr("%1: line %2: %3")
                                                        .arg(name)
                                                        .arg(m.line)
                                                        .arg(QString::fromStdString(m.text))
                                                  : name + ": " + QString::fromStdString(m.text));
}

QString programSummary(const QString& file, const planning::ClProgram& program) {
  return QObject::tr("%1: %2 points, %3 path(s), %4, %5 points%6")
      .arg(QFileInfo(file).fileName())
      .arg(program.points.size())
      .arg(program.pathCount())
      .arg(program.multiAxis() ? QObject::tr("5-axis") : QObject::tr("3-axis"))
      .arg(program.pointKind == planning::ClPointKind::Contact ? QObject::tr("contact")
                                                               : QObject::tr("tool reference"))
      .arg(program.warnings.empty()
               ? QString()
               : QObject::tr(", %1 warnings (see the console)").arg(program.warnings.size()));
}

// Three spin boxes (x, y, z) in a row, named <name>x, <name>y, <name>z.
QHBoxLayout* spinRow(QDoubleSpinBox* (&boxes)[3], const ddf::Vec3& values, double limit,
                     const QString& suffix, const char* name, QWidget* parent) {
  auto* row = new QHBoxLayout;
  for (int i = 0; i < 3; ++i) {
    boxes[i] = new QDoubleSpinBox(parent);
    boxes[i]->setObjectName(QString("%1%2").arg(name).arg("xyz"[i]));
    boxes[i]->setRange(-limit, limit);
    boxes[i]->setDecimals(4);
    boxes[i]->setSuffix(suffix);
    boxes[i]->setValue(values[i]);
    row->addWidget(boxes[i]);
  }
  return row;
}

// The project's tools, then (if the file has a CUTTER) a new tool from it (data -1).
QComboBox* toolChoice(const PathImportRequest& request, int toolIndex, QWidget* parent) {
  auto* tool = new QComboBox(parent);
  tool->setObjectName("importTool");
  for (std::size_t i = 0; i < request.project.tools.size(); ++i)
    tool->addItem(QString::fromStdString(request.project.tools[i].name), int(i));
  if (request.program.cutter)
    tool->addItem(QObject::tr("new tool from the file's CUTTER (d %1 mm, r %2 mm)")
                      .arg(request.program.cutter->diameterMm)
                      .arg(request.program.cutter->cornerRadiusMm),
                  -1);
  tool->setCurrentIndex(std::max(0, tool->findData(toolIndex)));
  return tool;
}

// The console line of an import: poses, the meanings used and why, distances that agree.
QString importedSummary(const QString& file, const planning::ImportedPath& imported) {
  const int poses = static_cast<int>(imported.path.poses.size());
  const QString onPart =
      imported.maxOnPartContactDistanceMm
          ? QObject::tr("%1 mm").arg(*imported.maxOnPartContactDistanceMm, 0, 'g', 4)
          : QObject::tr("none on the part");
  return QObject::tr(
             "Imported path '%1' from %2: %3 poses; %4; %5 of %3 off the part, largest "
             "|contact distance| %6 mm (on the part: %7), %8 gouging")
      .arg(QString::fromStdString(imported.path.name), QFileInfo(file).fileName())
      .arg(poses)
      .arg(QString::fromStdString(imported.convention.reason))
      .arg(imported.pointsOffPart)
      .arg(imported.maxAbsContactDistanceMm, 0, 'g', 4)
      .arg(onPart)
      .arg(imported.gougingPoses);
}

// Vector (or point) meanings in a combo box named @p name, data = the enum value.
template <typename Meaning>
QComboBox* meaningChoice(const std::vector<std::pair<Meaning, QString>>& items, Meaning initial,
                         const char* name, QWidget* parent) {
  auto* box = new QComboBox(parent);
  box->setObjectName(name);
  for (const auto& [meaning, text] : items) box->addItem(text, int(meaning));
  box->setCurrentIndex(std::max(0, box->findData(int(initial))));
  return box;
}

// What the file's vectors (disabled for 3-axis programs) and points are, auto by default.
std::pair<QComboBox*, QComboBox*> meaningChoices(const PathImportRequest& request,
                                                 const PathImportOptions& initial,
                                                 QWidget* parent) {
  using V = planning::PathVectorMeaning;
  auto* vectors =
      meaningChoice<V>({{V::Auto, QObject::tr("detect from the part")},
                        {V::ToolAxis, QObject::tr("tool axis (tip to holder)")},
                        {V::ApproachDirection, QObject::tr("approach direction (into the part)")},
                        {V::SurfaceNormal, QObject::tr("surface normal (out of the part)")}},
                       initial.vectors, "importVectors", parent);
  vectors->setEnabled(request.program.multiAxis());
  using P = planning::PathPointMeaning;
  const QString declared = request.program.pointKind == planning::ClPointKind::Contact
                               ? QObject::tr("as the file says (contacts)")
                               : QObject::tr("as the file says (tool tips or centres)");
  auto* points =
      meaningChoice<P>({{P::Auto, QObject::tr("detect from the part")},
                        {P::Declared, declared},
                        {P::Contact, QObject::tr("contact points on the surface")},
                        {P::ToolReference, QObject::tr("tool tips (wheel or ball centres)")}},
                       initial.points, "importPoints", parent);
  return {vectors, points};
}

// Places the program and adds the path (and a new tool) as one undo step.
void placeAndAdd(const QString& file, const planning::ClProgram& program,
                 const PathImportOptions& options, Document& document, ConsoleDock* console) {
  const planning::Project& project = document.project();
  std::optional<planning::Tool> newTool;
  if (options.toolIndex < 0) {
    if (!program.cutter) throw InvalidInput("the file has no CUTTER record to make a tool from");
    newTool = planning::toolFromCutter(
        *program.cutter,
        program.toolName.empty() ? QFileInfo(file).baseName().toStdString() : program.toolName);
  } else if (options.toolIndex >= static_cast<int>(project.tools.size())) {
    throw InvalidInput("the project has no tool " + std::to_string(options.toolIndex + 1));
  }
  const planning::Tool& tool =
      newTool ? *newTool : project.tools[static_cast<std::size_t>(options.toolIndex)];
  planning::PlaceProgramParams params;
  params.actualUnit = options.unit;
  params.transform = importTransform(options);
  params.includeRapids = options.includeRapids;
  params.name = options.name.trimmed().toStdString();
  params.toolIndex = newTool ? static_cast<int>(project.tools.size()) : options.toolIndex;
  params.vectorMeaning = options.vectors;
  params.pointMeaning = options.points;
  planning::ImportedPath imported = planning::placeProgram(program, tool, *project.part, params);
  logMessages(console, file, imported.warnings);
  const QString summary = importedSummary(file, imported);
  document.push(std::make_unique<AddPathCommand>(document, std::move(imported.path), newTool));
  if (console) console->appendMessage(LogLevel::Info, summary);
}

}  // namespace

QStringList importSuffixes() {
  QStringList suffixes;
  for (auto format :
       {io::PathFormat::Csv, io::PathFormat::Apt, io::PathFormat::RosYaml, io::PathFormat::FanucLs})
    for (const std::string& extension : io::pathFileExtensions(format)) {
      const QString suffix = QString::fromStdString(extension).remove(0, 1);  // the dot
      if (!suffixes.contains(suffix)) suffixes << suffix;
    }
  return suffixes;
}

QString pathFileFilter() {
  QStringList patterns;
  for (const QString& suffix : importSuffixes()) patterns << "*." + suffix;
  return QObject::tr("Tool paths (%1);;All files (*)").arg(patterns.join(' '));
}

bool isPathFile(const QString& file) {
  if (!importSuffixes().contains(QFileInfo(file).suffix().toLower())) return false;
  // .txt and .csv are also notes and tables: the content decides (as readPathFile does).
  QFile f(file);
  if (!f.open(QIODevice::ReadOnly)) return false;
  const QByteArray head = f.read(4096);
  const auto format = io::detectPathFormat(std::filesystem::path(file.toStdU16String()),
                                           std::string_view(head.constData(), head.size()));
  return format && *format != io::PathFormat::GCode;
}

Eigen::Isometry3d importTransform(const PathImportOptions& o) {
  const double toRad = std::numbers::pi / 180.0;
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = (Eigen::AngleAxisd(o.rotationDeg.z() * toRad, ddf::Vec3::UnitZ()) *
                Eigen::AngleAxisd(o.rotationDeg.y() * toRad, ddf::Vec3::UnitY()) *
                Eigen::AngleAxisd(o.rotationDeg.x() * toRad, ddf::Vec3::UnitX()))
                   .toRotationMatrix();
  t.translation() = o.translationMm;
  return t;
}

PathImportOptions initialImportOptions(const PathImportRequest& request) {
  PathImportOptions o;
  o.unit = request.program.sourceUnit;
  o.toolIndex = request.project.tools.empty() && request.program.cutter ? -1 : 0;
  o.name = request.program.partName.empty() ? QFileInfo(request.file).completeBaseName()
                                            : QString::fromStdString(request.program.partName);
  return o;
}

bool importPathFile(const QString& file, Document& document, const WorkbenchDialogs& dialogs,
                    ConsoleDock* console) {
  const QString title = QObject::tr("Import %1").arg(QFileInfo(file).fileName());
  std::optional<planning::ClProgram> program;
  const bool read = runUserAction(dialogs.error, title, [&] {
    if (!document.project().part)
      throw InvalidInput("open a part first: an imported path is placed on the part's surface");
    program = io::readPathFile(std::filesystem::path(file.toStdU16String())).program;
  });
  if (!read) return false;
  logMessages(console, file, program->warnings);
  const PathImportRequest request{file, *program, document.project()};
  const PathImportOptions initial = initialImportOptions(request);
  const std::optional<PathImportOptions> options =
      dialogs.importPath ? dialogs.importPath(request, initial) : initial;
  if (!options) return false;
  return runUserAction(dialogs.error, title,
                       [&] { placeAndAdd(file, *program, *options, document, console); });
}

PathImportDialog::PathImportDialog(const PathImportRequest& request,
                                   const PathImportOptions& initial, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("Import tool path"));
  setObjectName("pathImportDialog");
  auto* form = new QFormLayout;
  auto* summary = new QLabel(programSummary(request.file, request.program), this);
  summary->setWordWrap(true);
  form->addRow(summary);
  unit_ = new QComboBox(this);
  unit_->setObjectName("importUnit");
  for (auto unit : {LengthUnit::Millimetre, LengthUnit::Inch, LengthUnit::Metre})
    unit_->addItem(unitText(unit), int(unit));
  unit_->setCurrentIndex(unit_->findData(int(initial.unit)));
  form->addRow(tr("Unit of the file (read: %1):").arg(unitText(request.program.sourceUnit)), unit_);
  form->addRow(tr("Translation x, y, z:"),
               spinRow(translation_, initial.translationMm, 1e6, " mm", "importTranslation", this));
  form->addRow(tr("Rotation about x, y, z:"),
               spinRow(rotation_, initial.rotationDeg, 360.0, QString::fromUtf8(" °"),
                       "importRotation", this));
  tool_ = toolChoice(request, initial.toolIndex, this);
  form->addRow(tr("Tool:"), tool_);
  std::tie(vectors_, points_) = meaningChoices(request, initial, this);
  form->addRow(tr("The file's vectors are:"), vectors_);
  form->addRow(tr("The file's points are:"), points_);
  rapids_ = new QCheckBox(tr("keep rapid moves as poses"), this);
  rapids_->setObjectName("importRapids");
  rapids_->setChecked(initial.includeRapids);
  form->addRow(rapids_);
  name_ = new QLineEdit(initial.name, this);
  name_->setObjectName("importName");
  form->addRow(tr("Path name:"), name_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Import"));
  buttons->button(QDialogButtonBox::Ok)->setEnabled(tool_->count() > 0);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(buttons);
}

PathImportOptions PathImportDialog::options() const {
  PathImportOptions o;
  o.unit = static_cast<LengthUnit>(unit_->currentData().toInt());
  for (int i = 0; i < 3; ++i) {
    o.translationMm[i] = translation_[i]->value();
    o.rotationDeg[i] = rotation_[i]->value();
  }
  o.toolIndex = tool_->count() > 0 ? tool_->currentData().toInt() : 0;
  o.includeRapids = rapids_->isChecked();
  o.name = name_->text();
  o.vectors = static_cast<planning::PathVectorMeaning>(vectors_->currentData().toInt());
  o.points = static_cast<planning::PathPointMeaning>(points_->currentData().toInt());
  return o;
}

}  // namespace ddfcam::gui
