// SPDX-License-Identifier: MIT
// The part import dialog: sizes in each unit, the unit advice, the choices it starts with, the
// load parameters of the choices, and what the widget shows.
#include "gui_test_registry.h"
#include "frame_checks.h"

#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/part_import_dialog.h>

#include <QComboBox>
#include <QtTest/QtTest>

#include <cmath>

using ddfcam::LengthUnit;
using ddfcam::ddf::Vec3;
using ddfcam::gui::PartImportChoices;
using ddfcam::gui::PartImportRequest;

namespace {

PartImportRequest requestWithBounds(Vec3 lo, Vec3 hi) {
  PartImportRequest r;
  r.file = "blade.stl";
  r.boundsFileUnits = std::array{lo, hi};
  return r;
}

}  // namespace

class PartImportDialogTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private slots:
  void sizesInEachUnit();
  void smallPartSuggestsMetres();
  void hugePartWarnsWithoutSuggestion();
  void paramsFromChoices();
  void initialChoicesKeepSessionButNotUnit();
  void dialogShowsSizesAndPreselects();
};

void PartImportDialogTest::sizesInEachUnit() {
  const std::array bounds{Vec3(1, 2, 3), Vec3(1.3, 2.02, 3.005)};
  const auto mm = ddfcam::gui::sizeMmIn(bounds, LengthUnit::Millimetre);
  QVERIFY(std::abs(mm[0] - 0.3) < 1e-12 && std::abs(mm[1] - 0.02) < 1e-12);
  const auto m = ddfcam::gui::sizeMmIn(bounds, LengthUnit::Metre);
  QVERIFY(std::abs(m[0] - 300.0) < 1e-9 && std::abs(m[2] - 5.0) < 1e-9);
  const auto cm = ddfcam::gui::sizeMmIn(bounds, LengthUnit::Centimetre);
  QVERIFY(std::abs(cm[0] - 3.0) < 1e-12);
  const auto in = ddfcam::gui::sizeMmIn(bounds, LengthUnit::Inch);
  QVERIFY(std::abs(in[0] - 0.3 * 25.4) < 1e-12);
  QCOMPARE(ddfcam::gui::sizeText(m), QString("300 x 20 x 5 mm"));
}

void PartImportDialogTest::smallPartSuggestsMetres() {
  // A 0.3-unit blade: in mm 0.3 mm across, in m 300 mm, the likely reading.
  const PartImportRequest r = requestWithBounds(Vec3::Zero(), Vec3(0.3, 0.0, 0.0));
  const auto advice = ddfcam::gui::unitAdvice(r);
  QVERIFY(advice.suspicious);
  QCOMPARE(advice.suggestion, std::optional(LengthUnit::Metre));
  QVERIFY2(advice.message.contains("0.3 units") && advice.message.contains("300 mm"),
           qPrintable(advice.message));
  QCOMPARE(ddfcam::gui::initialImportChoices(r, {}).unit, std::optional(LengthUnit::Metre));
  // A usual size gets no advice and stays in mm.
  const PartImportRequest usual = requestWithBounds(Vec3::Zero(), Vec3(300, 20, 5));
  QVERIFY(!ddfcam::gui::unitAdvice(usual).suspicious);
  QCOMPARE(ddfcam::gui::initialImportChoices(usual, {}).unit,
           std::optional(LengthUnit::Millimetre));
  // A CAD file that states its unit is trusted: "from file", no advice.
  PartImportRequest cad = r;
  cad.cad = true;
  cad.fileUnit = LengthUnit::Millimetre;
  QVERIFY(!ddfcam::gui::unitAdvice(cad).suspicious);
  QCOMPARE(ddfcam::gui::initialImportChoices(cad, {}).unit, std::nullopt);
}

void PartImportDialogTest::hugePartWarnsWithoutSuggestion() {
  const PartImportRequest r = requestWithBounds(Vec3::Zero(), Vec3(30'000, 0, 0));
  const auto advice = ddfcam::gui::unitAdvice(r);
  QVERIFY(advice.suspicious);
  QCOMPARE(advice.suggestion, std::nullopt);
  QCOMPARE(ddfcam::gui::initialImportChoices(r, {}).unit, std::optional(LengthUnit::Millimetre));
}

void PartImportDialogTest::paramsFromChoices() {
  PartImportChoices c;
  const auto defaults = ddfcam::gui::loadParamsFor(c);
  QCOMPARE(defaults.unit, std::optional(LengthUnit::Millimetre));
  QCOMPARE(defaults.conversion.support, ddfcam::ddf::SupportChoice::Reduced);
  QCOMPARE(defaults.conversion.toleranceMm, 0.01);
  QCOMPARE(defaults.conversion.rasterSpacingMm, 0.0);
  QCOMPARE(defaults.conversion.stockMm, 0.0);
  c.unit = LengthUnit::Inch;
  c.accuracy = ddfcam::gui::ImportAccuracy::RasterSpacing;
  c.rasterSpacingMm = 0.25;
  c.support = ddfcam::ddf::SupportChoice::Input;
  c.stockMm = 0.5;
  const auto p = ddfcam::gui::loadParamsFor(c);
  QCOMPARE(p.unit, std::optional(LengthUnit::Inch));
  QCOMPARE(p.conversion.toleranceMm, 0.0);
  QCOMPARE(p.conversion.rasterSpacingMm, 0.25);
  QCOMPARE(p.conversion.support, ddfcam::ddf::SupportChoice::Input);
  QCOMPARE(p.conversion.stockMm, 0.5);
  c.unit = std::nullopt;
  QCOMPARE(ddfcam::gui::loadParamsFor(c).unit, std::nullopt);
}

void PartImportDialogTest::initialChoicesKeepSessionButNotUnit() {
  PartImportChoices recent;
  recent.unit = LengthUnit::Metre;
  recent.toleranceMm = 0.05;
  recent.stockMm = 0.3;
  recent.support = ddfcam::ddf::SupportChoice::Input;
  const auto c =
      ddfcam::gui::initialImportChoices(requestWithBounds(Vec3::Zero(), Vec3(50, 40, 3)), recent);
  QCOMPARE(c.unit, std::optional(LengthUnit::Millimetre));
  QCOMPARE(c.toleranceMm, 0.05);
  QCOMPARE(c.stockMm, 0.3);
  QCOMPARE(c.support, ddfcam::ddf::SupportChoice::Input);
}

void PartImportDialogTest::dialogShowsSizesAndPreselects() {
  const PartImportRequest r = requestWithBounds(Vec3::Zero(), Vec3(0.3, 0.02, 0.005));
  ddfcam::gui::PartImportDialog dialog(r, ddfcam::gui::initialImportChoices(r, {}));
  QCOMPARE(dialog.choices().unit, std::optional(LengthUnit::Metre));
  const QString sizes = dialog.sizeSummary();
  QVERIFY2(
      sizes.contains("in m: 300 x 20 x 5 mm") && sizes.contains("in mm: 0.3 x 0.02 x 0.005 mm"),
      qPrintable(sizes));
  QVERIFY(sizes.contains("0.301 units across"));
  dialog.show();
  ddfcam::test::dumpFrame(dialog.grab().toImage(), "part_import_dialog");
  QCOMPARE(dialog.choices().toleranceMm, 0.01);
  QCOMPARE(dialog.choices().support, ddfcam::ddf::SupportChoice::Reduced);
  // A CAD file's own unit is the first entry, marked "from file".
  PartImportRequest cad = r;
  cad.cad = true;
  cad.fileUnit = LengthUnit::Metre;
  ddfcam::gui::PartImportDialog cadDialog(cad, ddfcam::gui::initialImportChoices(cad, {}));
  auto* unit = cadDialog.findChild<QComboBox*>("importPartUnit");
  QVERIFY(unit);
  QCOMPARE(unit->currentText(), QString("m (from file)"));
  QCOMPARE(cadDialog.choices().unit, std::nullopt);
}

DDFCAM_GUI_TEST_MAIN(PartImportDialogTest)
#include "part_import_dialog_test.moc"
