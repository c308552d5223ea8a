// SPDX-License-Identifier: MIT
// ddfcam gui: PartImportDialog and the logic behind it.
#include <ddfcam/gui/part_import_dialog.h>

#include <ddfcam/error.h>
#include <ddfcam/io/cad/cad_model.h>
#include <ddfcam/io/mesh/mesh_io.h>

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

#include <algorithm>

namespace ddfcam::gui {
namespace {

constexpr std::array kUnits = {LengthUnit::Millimetre, LengthUnit::Centimetre, LengthUnit::Metre,
                               LengthUnit::Inch};
/// Combo data of the "from file" entry (the unit indices are 0..3).
constexpr int kFromFile = -1;

QString symbol(LengthUnit unit) {
  return QString::fromLatin1(unitSymbol(unit).data(), static_cast<int>(unitSymbol(unit).size()));
}

QString number(double value) {
  return QString::number(value, 'g', 3);
}

bool hasSuffix(const QString& file, std::initializer_list<const char*> suffixes) {
  const QString suffix = QFileInfo(file).suffix().toLower();
  return std::any_of(suffixes.begin(), suffixes.end(),
                     [&](const char* s) { return suffix == QLatin1String(s); });
}

QDoubleSpinBox* mmSpin(QWidget* parent, const char* name, double lo, double hi, double value,
                       int decimals) {
  auto* spin = new QDoubleSpinBox(parent);
  spin->setObjectName(name);
  spin->setDecimals(decimals);
  spin->setRange(lo, hi);
  spin->setValue(value);
  spin->setSuffix(" mm");
  return spin;
}

// The file's own unit first (CAD), then mm, cm, m, in; data: kFromFile or the index in kUnits.
QComboBox* unitCombo(const PartImportRequest& request, const PartImportChoices& initial,
                     QWidget* parent) {
  auto* combo = new QComboBox(parent);
  combo->setObjectName("importPartUnit");
  if (request.cad)
    combo->addItem(request.fileUnit ? QObject::tr("%1 (from file)").arg(symbol(*request.fileUnit))
                                    : QObject::tr("as the file states (from file)"),
                   kFromFile);
  for (std::size_t i = 0; i < kUnits.size(); ++i) combo->addItem(symbol(kUnits[i]), int(i));
  const auto at = std::find(kUnits.begin(), kUnits.end(), initial.unit.value_or(kUnits[0]));
  combo->setCurrentIndex(initial.unit ? combo->findData(int(at - kUnits.begin())) : 0);
  return combo;
}

// The advice in bold, then the size the part has in mm for each reading of its numbers.
QString sizeLines(const PartImportRequest& request) {
  QStringList lines;
  const UnitAdvice advice = unitAdvice(request);
  if (advice.suspicious) lines << "<b>" + advice.message.toHtmlEscaped() + "</b>";
  if (request.boundsFileUnits) {
    for (LengthUnit unit : kUnits)
      lines << QObject::tr("in %1: %2")
                   .arg(symbol(unit), sizeText(sizeMmIn(*request.boundsFileUnits, unit)));
  } else if (!request.boundsError.isEmpty()) {
    lines << QObject::tr("size unknown: %1").arg(request.boundsError.toHtmlEscaped());
  } else {
    lines << QObject::tr("size shown after the import");
  }
  return lines.join("<br>");
}

}  // namespace

bool isCadFile(const QString& file) {
  return hasSuffix(file, {"step", "stp", "iges", "igs"});
}

bool isImportablePart(const QString& file) {
  return isCadFile(file) || hasSuffix(file, {"stl", "obj", "ply", "off"});
}

PartImportRequest readImportRequest(const QString& file) {
  PartImportRequest request;
  request.file = file;
  request.cad = isCadFile(file);
  try {
    if (request.cad) {
      // Unhealed: the bounds and the unit do not need the sewing the import does.
      io::CadReadParams params;
      params.heal = false;
      const io::CadModel model = io::readCadModel(file.toStdU16String(), params);
      request.fileUnit = model.fileUnit();
      std::array<ddf::Vec3, 2> bounds = model.boundsMm();
      for (ddf::Vec3& corner : bounds) corner /= millimetresPer(model.unit());
      request.boundsFileUnits = bounds;
    } else {
      request.boundsFileUnits = io::readMesh(file.toStdU16String()).bounds();
    }
  } catch (const std::exception& e) {
    request.boundsError = QString::fromStdString(e.what());
  }
  return request;
}

std::array<double, 3> sizeMmIn(const std::array<ddf::Vec3, 2>& bounds, LengthUnit unit) {
  const ddf::Vec3 size = (bounds[1] - bounds[0]) * millimetresPer(unit);
  return {size.x(), size.y(), size.z()};
}

double diagonalOf(const std::array<ddf::Vec3, 2>& bounds) {
  return (bounds[1] - bounds[0]).norm();
}

QString sizeText(const std::array<double, 3>& sizeMm) {
  return QStringLiteral("%1 x %2 x %3 mm")
      .arg(number(sizeMm[0]), number(sizeMm[1]), number(sizeMm[2]));
}

UnitAdvice unitAdvice(const PartImportRequest& request) {
  UnitAdvice advice;
  // A unit the CAD file states is trusted; only numbers of unknown unit are questioned.
  if ((request.cad && request.fileUnit) || !request.boundsFileUnits) return advice;
  const double diagonal = diagonalOf(*request.boundsFileUnits);
  if (!sizeSuggestsOtherUnit(diagonal)) return advice;
  advice.suspicious = true;
  advice.suggestion = likelyUnit(diagonal);
  advice.message = QObject::tr(
                       "The part is %1 units across: in mm it would be %2 mm, which is "
                       "unusual for grinding.")
                       .arg(number(diagonal), number(diagonal));
  if (advice.suggestion)
    advice.message +=
        QObject::tr(" Preselected %1 (%2 mm across); check the sizes below.")
            .arg(symbol(*advice.suggestion), number(diagonal * millimetresPer(*advice.suggestion)));
  else
    advice.message += QObject::tr(" No offered unit makes it usual; check the sizes below.");
  return advice;
}

PartImportChoices initialImportChoices(const PartImportRequest& request,
                                       const PartImportChoices& recent) {
  PartImportChoices choices = recent;
  // A unit belongs to a file: carrying it over would scale the next file wrongly.
  choices.unit = request.cad ? std::nullopt : std::optional(LengthUnit::Millimetre);
  if (const UnitAdvice advice = unitAdvice(request); advice.suggestion)
    choices.unit = advice.suggestion;
  return choices;
}

io::LoadPartParams loadParamsFor(const PartImportChoices& choices) {
  io::LoadPartParams params;
  params.unit = choices.unit;
  ddf::ConversionParams& c = params.conversion;
  c.support = choices.support;
  if (choices.accuracy == ImportAccuracy::Tolerance)
    c.toleranceMm = choices.toleranceMm;
  else
    c.rasterSpacingMm = choices.rasterSpacingMm;
  c.stockMm = choices.stockMm;
  return params;
}

PartImportDialog::PartImportDialog(const PartImportRequest& request,
                                   const PartImportChoices& initial, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("Import %1").arg(QFileInfo(request.file).fileName()));
  setObjectName("partImportDialog");
  auto* form = new QFormLayout;
  unit_ = unitCombo(request, initial, this);
  form->addRow(tr("Unit of the file:"), unit_);
  sizes_ = new QLabel(sizeLines(request), this);
  sizes_->setObjectName("importPartSizes");
  sizes_->setTextFormat(Qt::RichText);
  sizes_->setWordWrap(true);
  form->addRow(tr("Size:"), sizes_);

  byTolerance_ = new QRadioButton(tr("tolerance"), this);
  byTolerance_->setObjectName("importByTolerance");
  bySpacing_ = new QRadioButton(tr("raster spacing"), this);
  bySpacing_->setObjectName("importBySpacing");
  (initial.accuracy == ImportAccuracy::Tolerance ? byTolerance_ : bySpacing_)->setChecked(true);
  tolerance_ = mmSpin(this, "importTolerance", 1e-5, 100.0, initial.toleranceMm, 5);
  spacing_ = mmSpin(this, "importSpacing", 1e-4, 1000.0, initial.rasterSpacingMm, 4);
  form->addRow(byTolerance_, tolerance_);
  form->addRow(bySpacing_, spacing_);
  const auto enableAccuracy = [this] {
    tolerance_->setEnabled(byTolerance_->isChecked());
    spacing_->setEnabled(bySpacing_->isChecked());
  };
  connect(byTolerance_, &QRadioButton::toggled, this, enableAccuracy);
  enableAccuracy();

  support_ = new QComboBox(this);
  support_->setObjectName("importSupport");
  support_->addItem(tr("reduced (recommended)"), int(ddf::SupportChoice::Reduced));
  support_->addItem(tr("input mesh"), int(ddf::SupportChoice::Input));
  support_->setCurrentIndex(support_->findData(int(initial.support)));
  form->addRow(tr("Support:"), support_);
  stock_ = mmSpin(this, "importStock", 0.0, 100.0, initial.stockMm, 3);
  stock_->setSpecialValueText(tr("none"));
  stock_->setToolTip(tr("Allowance the crust must reach above the surface (0 = none)"));
  form->addRow(tr("Stock reach:"), stock_);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Import"));
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(buttons);
}

PartImportChoices PartImportDialog::choices() const {
  PartImportChoices c;
  const int unit = unit_->currentData().toInt();
  c.unit = unit == kFromFile ? std::nullopt : std::optional(kUnits[std::size_t(unit)]);
  c.accuracy =
      byTolerance_->isChecked() ? ImportAccuracy::Tolerance : ImportAccuracy::RasterSpacing;
  c.toleranceMm = tolerance_->value();
  c.rasterSpacingMm = spacing_->value();
  c.support = static_cast<ddf::SupportChoice>(support_->currentData().toInt());
  c.stockMm = stock_->value();
  return c;
}

QString PartImportDialog::sizeSummary() const {
  return sizes_->text();
}

}  // namespace ddfcam::gui
