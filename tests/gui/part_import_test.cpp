// SPDX-License-Identifier: MIT
// Importing real parts in the workbench: a part in metres, a cancelled import, the Part panel's
// facts, the stock offer, the crust overlays, mould surfaces in a unit and CAD faces.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_fixture.h"

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/gui/adapters/crust_surface.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/panels/mould_panel.h>
#include <ddfcam/gui/panels/mould_tools_panel.h>
#include <ddfcam/gui/panels/part_panel.h>
#include <ddfcam/gui/panels/segmentation_panel.h>
#include <ddfcam/gui/panels/simulation_panel.h>
#include <ddfcam/gui/part_import_dialog.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/project_actions.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/io/cad/cad_model.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/model/project.h>

#include <QComboBox>
#include <QDockWidget>
#include <QFileInfo>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <vtkPolyData.h>

#include <cmath>
#include <set>

using ddfcam::LengthUnit;
using ddfcam::ddf::Vec3;
using ddfcam::gui::PartImportChoices;
using ddfcam::gui::PartImportRequest;

namespace {

/// A hill z = 2 exp(-((u - 8)^2 + (v - 6)^2) / 20) over 16 x 12 on a grid of nx x ny quads,
/// every coordinate times @p scale: 16 x 12 x 1.99 units at scale 1.
ddfcam::ddf::TriangleMesh hill(int nx, int ny, double scale) {
  ddfcam::ddf::TriangleMesh mesh;
  for (int y = 0; y <= ny; ++y)
    for (int x = 0; x <= nx; ++x) {
      const double u = 16.0 * x / nx, v = 12.0 * y / ny;
      const double z = 2.0 * std::exp(-((u - 8.0) * (u - 8.0) + (v - 6.0) * (v - 6.0)) / 20.0);
      mesh.vertices.push_back(Vec3(u, v, z) * scale);
    }
  auto at = [nx](int x, int y) { return y * (nx + 1) + x; };
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      mesh.triangles.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      mesh.triangles.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  return mesh;
}

std::array<Vec3, 2> supportBounds(const ddfcam::ddf::DisplacementField& ddf) {
  return ddfcam::ddf::extractSupportMesh(ddf).bounds();
}

}  // namespace

class PartImportTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private slots:
  void initTestCase() { QVERIFY(f_.open(true)); }
  void cleanupTestCase() { f_.window.reset(); }
  void init() { f_.script.errors.clear(); }
  void cleanup() { QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0); }

  void partInMetresIsThousandTimesLarger();
  void cancelledImportKeepsDocument();
  void partPanelShowsSizeUnitAndReach();
  void crustOverlayIsTheOffsetSurface();
  void mouldSurfacesLoadInTheirUnit();
  void unheldStockOffersLargestAllowance();
  void defaultChoicesReduceAndMeasure();
  void cadPartSegmentsByCadFace();
  void bladeHoldsHalfAMillimetreOfStockAndRaises();

 private:
  const ddfcam::planning::Project& project() { return f_.window->document().project(); }
  QString writeHill(const QString& name, double step, int nx = 16, int ny = 12) {
    const QString path = f_.dir.filePath(name);
    ddfcam::io::writeMesh(hill(nx, ny, step), path.toStdString());
    return path;
  }
  bool import(const QString& path, const PartImportChoices& choices) {
    f_.script.importChoices = choices;
    const bool started = f_.window->openPath(path);
    return started && f_.window->waitForJobs(120'000);
  }

  ddfcam::test::WorkbenchFixture f_;
};

void PartImportTest::partInMetresIsThousandTimesLarger() {
  // The same numbers read in mm and in m: the oracle is the factor 1000 of the bounds.
  const QString path = writeHill("hill_m.stl", 0.001);
  PartImportChoices c = ddfcam::test::ScriptedDialogs::legacyImport();
  QVERIFY(import(path, c));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  // The request the dialog got had the file's bounds and advised metres.
  QVERIFY(f_.script.importRequests.back().boundsFileUnits.has_value());
  QCOMPARE(f_.script.importInitialChoices.back().unit, std::optional(LengthUnit::Metre));
  const auto inMm = supportBounds(*project().part);
  c.unit = LengthUnit::Metre;
  QVERIFY(import(path, c));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(project().sourceUnit, LengthUnit::Metre);
  const auto inM = supportBounds(*project().part);
  for (int corner = 0; corner < 2; ++corner)
    QVERIFY2((inM[corner] - 1000.0 * inMm[corner]).norm() <= 1e-9 * 1000.0 * 16.0,
             qPrintable(QString("corner %1").arg(corner)));
  // Binary STL holds floats: 16 mm within their rounding.
  QVERIFY(std::abs((inM[1] - inM[0]).x() - 16.0) < 1e-4);
  QVERIFY2(f_.window->statusText().contains("16 x 12 x 1.99 mm"),
           qPrintable(f_.window->statusText()));
}

void PartImportTest::cancelledImportKeepsDocument() {
  const QString path = writeHill("big_hill.stl", 1.0, 160, 120);
  const ddfcam::planning::Project before = project();
  f_.script.importChoices = ddfcam::test::ScriptedDialogs::legacyImport();
  QVERIFY(f_.window->openPath(path));
  f_.window->jobs().cancel();
  QVERIFY(f_.window->waitForJobs(120'000));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QVERIFY(ddfcam::planning::projectsEqual(project(), before));
  // The dialog's own cancel starts nothing.
  f_.script.importChoices = std::nullopt;
  QVERIFY(!f_.window->openPath(path));
  QVERIFY(!f_.window->jobs().isRunning());
  QVERIFY(ddfcam::planning::projectsEqual(project(), before));
}

void PartImportTest::partPanelShowsSizeUnitAndReach() {
  PartImportChoices c = ddfcam::test::ScriptedDialogs::legacyImport();
  c.unit = LengthUnit::Centimetre;
  QVERIFY(import(writeHill("hill_cm.off", 0.1), c));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  auto* panel = f_.window->findChild<ddfcam::gui::PartPanel*>();
  QVERIFY(panel);
  const QString text = panel->text();
  QVERIFY2(text.contains("16 x 12 x 1.99 mm"), qPrintable(text));
  QVERIFY2(text.contains("Came in</b></td><td>cm"), qPrintable(text));
  QVERIFY2(text.contains("Crust above") && text.contains("Crust below"), qPrintable(text));
  // The reach shown is the core's: compare with crustReach of the document's part.
  const auto reach = ddfcam::ddf::crustReach(*project().part);
  QVERIFY(reach.minAboveMm > 0.0 && reach.medianBelowMm > 0.0);
  QVERIFY2(text.contains(QString::fromStdString(ddfcam::gui::reachLine(reach, true))),
           qPrintable(text));
  QVERIFY(text.contains("spacing"));
}

void PartImportTest::crustOverlayIsTheOffsetSurface() {
  auto& view = f_.window->partView();
  const auto& ddf = *project().part;
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  const QImage plain = f_.window->view()->renderImage();
  view.setCrustVisible(+1, true);
  view.setCrustVisible(-1, true);
  const QImage both = f_.window->view()->renderImage();
  ddfcam::test::dumpFrame(both, "part_import_crust_both");
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusX);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "part_import_crust_side");
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  QVERIFY(ddfcam::test::changedFraction(plain, both) > 0.002);
  // Oracle: the DDF's own point at h = +-1 at every support vertex (bary corners).
  for (int side : {+1, -1}) {
    vtkPolyData* data = view.scene().overlayData(ddfcam::gui::PartView::crustOverlayName(side));
    QVERIFY(data);
    QCOMPARE(data->GetNumberOfCells(), static_cast<vtkIdType>(ddf.faceCount()));
    const auto mesh = ddfcam::gui::crustOffsetMesh(ddf, side);
    for (int f = 0; f < ddf.faceCount(); f += 7)
      for (int c = 0; c < 3; ++c) {
        Vec3 bary = Vec3::Zero();
        bary[c] = 1.0;
        const Vec3 expected = ddf.pointAt(f, bary, side);
        QVERIFY((mesh.vertices[mesh.triangles[f][c]] - expected).norm() < 1e-12);
      }
  }
  view.setCrustVisible(+1, false);
  view.setCrustVisible(-1, false);
  QVERIFY(!view.scene().hasOverlay("crust+1"));
  // The side view framed the crusts too; frame the part alone again.
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  QVERIFY(ddfcam::test::changedFraction(plain, f_.window->view()->renderImage()) < 0.001);
}

void PartImportTest::mouldSurfacesLoadInTheirUnit() {
  const QString path = writeHill("mould_m.obj", 0.001);
  auto* panel = f_.window->findChild<ddfcam::gui::MouldPanel*>();
  QVERIFY(panel);
  QCOMPARE(panel->findChild<QComboBox*>("mouldUnitCombo")->currentText(), QString("mm"));
  panel->setSurfaceUnits(LengthUnit::Metre, LengthUnit::Millimetre);
  QVERIFY(panel->loadMould(path));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  // Oracle: the file as read, times 1000 (OBJ keeps the numbers exactly).
  const auto file = ddfcam::io::readMesh(path.toStdString());
  const auto& mould = project().mould->mould.mesh;
  QCOMPARE(mould.vertices.size(), file.vertices.size());
  for (std::size_t v = 0; v < file.vertices.size(); v += 17)
    QVERIFY((mould.vertices[v] - 1000.0 * file.vertices[v]).norm() < 1e-9);
  auto* tools = f_.window->findChild<ddfcam::gui::MouldToolsPanel*>();
  QVERIFY(tools);
  auto* unit = tools->findChild<QComboBox*>("importFormedUnitCombo");
  QVERIFY(unit);
  tools->setFormedUnit(LengthUnit::Inch);
  QCOMPARE(unit->currentText(), QString("in"));
}

void PartImportTest::cadPartSegmentsByCadFace() {
  const QString path = QStringLiteral(DDFCAM_SHARED_DATA_DIR) + "/cad/bolt_clip.step";
  if (!QFileInfo::exists(path)) QSKIP("shared data not found");
  PartImportChoices c = ddfcam::test::ScriptedDialogs::legacyImport();
  c.unit = std::nullopt;  // from the file
  QVERIFY(import(path, c));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  // The dialog was told the file's unit and size before the conversion.
  const PartImportRequest& request = f_.script.importRequests.back();
  QVERIFY(request.cad && request.boundsFileUnits);
  QCOMPARE(request.fileUnit, std::optional(LengthUnit::Metre));
  QCOMPARE(f_.script.importInitialChoices.back().unit, std::nullopt);
  // About 11.7 x 5.1 x 3.2 mm (SOURCES.md), written in metres.
  const auto sizeMm = ddfcam::gui::sizeMmIn(*request.boundsFileUnits, LengthUnit::Metre);
  QVERIFY2(std::abs(sizeMm[0] - 11.7) < 0.1 || std::abs(sizeMm[1] - 11.7) < 0.1 ||
               std::abs(sizeMm[2] - 11.7) < 0.1,
           qPrintable(ddfcam::gui::sizeText(sizeMm)));
  // Oracle: the CAD model read independently.
  const ddfcam::io::CadModel model = ddfcam::io::readCadModel(path.toStdString());
  const auto& p = project();
  QCOMPARE(static_cast<int>(p.cadFaceNames.size()), model.faceCount());
  QCOMPARE(static_cast<int>(p.cadFaceOfSupportFace.size()), p.part->faceCount());
  const std::set<int> used(p.cadFaceOfSupportFace.begin(), p.cadFaceOfSupportFace.end());
  auto* panel = f_.window->findChild<ddfcam::gui::PartPanel*>();
  QVERIFY2(panel->text().contains(QString("CAD faces</b></td><td>%1").arg(model.faceCount())),
           qPrintable(panel->text()));

  auto* segmentation = f_.window->findChild<ddfcam::gui::SegmentationPanel*>();
  QVERIFY(segmentation);
  segmentation->setSegmentationOptions(ddfcam::gui::SegmentationMethod::CadFace, 0.0, {}, 1);
  const auto regionsBefore = p.regions;
  QVERIFY(segmentation->segment());
  QVERIFY(f_.window->waitForJobs(120'000));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  // One region per CAD face (each face of this part is connected), each within one face.
  QCOMPARE(p.regions.size(), used.size());
  std::set<int> covered;
  for (const auto& region : p.regions) {
    QVERIFY(!region.faces.empty());
    const int cad = p.cadFaceOfSupportFace[region.faces.front()];
    for (int f : region.faces) QCOMPARE(p.cadFaceOfSupportFace[f], cad);
    QVERIFY(covered.insert(cad).second);
  }
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "part_import_bolt_clip_cad_faces");
  qInfo("bolt_clip.step: %d CAD faces, %d support faces, %zu regions", model.faceCount(),
        p.part->faceCount(), p.regions.size());
  f_.window->document().undoStack()->undo();
  QVERIFY(p.regions == regionsBefore);
  // A mesh part has no CAD faces: the method falls back to curvature type.
  QVERIFY(import(writeHill("plain.off", 1.0), ddfcam::test::ScriptedDialogs::legacyImport()));
  segmentation->setSegmentationOptions(ddfcam::gui::SegmentationMethod::CadFace, 0.0, {}, 1);
  auto* method = segmentation->findChild<QComboBox*>("segmentationMethod");
  QCOMPARE(method->currentIndex(),
           static_cast<int>(ddfcam::gui::SegmentationMethod::CurvatureType));
}

void PartImportTest::unheldStockOffersLargestAllowance() {
  // 20 mm of stock over a 16 mm hill whose foot is concave: no crust reaches that far.
  PartImportChoices c = ddfcam::test::ScriptedDialogs::legacyImport();
  c.stockMm = 20.0;
  f_.script.stockOffers.clear();
  f_.script.acceptLargestStock = true;
  QVERIFY(import(writeHill("stock_hill.off", 1.0), c));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  const auto& report = f_.window->projectActions().partReport();
  QVERIFY(report.has_value());
  if (!report->stock) QSKIP("the conversion does not fit the crust to a stock yet");
  QVERIFY(!report->stock->holds);
  QVERIFY(report->stock->limit.has_value());
  const double largest = report->stock->limit->largestAllowanceMm;
  const std::string message = report->stock->limit->message;  // the report is replaced below
  // Said, never silent: the limit's message and the largest allowance are offered...
  QTRY_COMPARE_WITH_TIMEOUT(f_.script.stockOffers.size(), 1, 5000);
  QVERIFY(f_.script.stockOffers.front().startsWith(
      QString::fromStdString(report->stock->limit->message)));
  QVERIFY(f_.window->findChild<ddfcam::gui::PartPanel*>()->text().contains("NOT held"));
  // ...and accepting imports again with it.
  QTRY_VERIFY_WITH_TIMEOUT(f_.window->jobs().isRunning(), 5000);
  QVERIFY(f_.window->waitForJobs(120'000));
  const auto& again = f_.window->projectActions().partReport();
  QVERIFY(again && again->stock);
  QCOMPARE(again->stock->requestedMm, largest);
  qInfo("stock 20 mm refused: %s; again with %.3g mm: %s", message.c_str(), largest,
        again->stock->holds ? "held" : "NOT held");
  f_.script.acceptLargestStock = false;
}

void PartImportTest::defaultChoicesReduceAndMeasure() {
  // What the dialog proposes in a new session: reduced support, 0.01 mm both ways.
  f_.script.importChoices = PartImportChoices{};
  QElapsedTimer timer;
  timer.start();
  QVERIFY(f_.window->openPath(writeHill("default_hill.off", 1.0, 32, 24)));
  QVERIFY(f_.window->waitForJobs(300'000));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  const auto& report = f_.window->projectActions().partReport();
  QVERIFY(report.has_value());
  QCOMPARE(report->reduction.inputFaces, 2 * 32 * 24);
  QCOMPARE(report->reduction.supportFaces, project().part->faceCount());
  QVERIFY(report->accuracy.measured);
  auto* panel = f_.window->findChild<ddfcam::gui::PartPanel*>();
  const QString text = panel->text();
  QVERIFY2(text.contains("Reduction") && text.contains("Distances"), qPrintable(text));
  QVERIFY2(f_.window->statusText().contains(
               QString("support %1 faces, m = ").arg(project().part->faceCount())),
           qPrintable(f_.window->statusText()));
  f_.window->findChild<QDockWidget*>("panel_part")->raise();
  f_.window->partView().setCrustVisible(+1, true);
  f_.window->partView().setCrustVisible(-1, true);
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusY);
  QApplication::processEvents();
  ddfcam::test::dumpFrame(f_.window->grab().toImage(), "part_import_default_window");
  qInfo(
      "default import of 1536 triangles in %lld ms: support %d -> %d faces, m = %d, input->DDF "
      "%.3g mm, DDF->input %.3g mm",
      static_cast<long long>(timer.elapsed()), report->reduction.inputFaces,
      report->reduction.supportFaces, project().part->resolution(), report->accuracy.inputToDdfMm,
      report->accuracy.ddfToInputMm);
}

void PartImportTest::bladeHoldsHalfAMillimetreOfStockAndRaises() {
  // The turbine blade (metres in the file) as a new user brings it in for grinding from stock:
  // reduced support, 0.5 mm of stock asked for in the import dialog, then Raise by allowance.
  const QString path = QString(DDFCAM_SHARED_DATA_DIR) + "/meshes/turbine-blade-jigsaw.stl";
  if (!QFileInfo::exists(path)) QSKIP("shared data not found");
  PartImportChoices c;
  c.unit = LengthUnit::Metre;
  c.toleranceMm = 0.0;  // the default resolution: a quick import
  c.stockMm = 0.5;
  f_.script.stockOffers.clear();
  QVERIFY(import(path, c));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  const auto& report = f_.window->projectActions().partReport();
  QVERIFY(report && report->stock);
  QVERIFY2(report->stock->holds, report->stock->limit ? report->stock->limit->message.c_str() : "");
  QVERIFY(report->stock->reach.minAboveMm >= 0.5);
  QVERIFY(f_.script.stockOffers.isEmpty());
  const std::vector<float> design = project().part->allHeights();
  auto* simulation = f_.window->findChild<ddfcam::gui::SimulationPanel*>();
  QVERIFY(simulation->raiseByAllowance(0.5));
  QVERIFY(f_.window->waitForJobs(120'000));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  // Oracle: the raise moves the surface 0.5 mm along the design's normals, so every raster
  // point moves along its stubble by at least that (0.5 mm / cos of the stubble's lean).
  const auto& part = *project().part;
  double least = 1e9, most = 0.0;
  for (int f = 0; f < part.faceCount(); f += 3)
    for (int k = 0; k <= part.raster().steps(); ++k)
      for (int i = 0; i < part.raster().rowLength(k); ++i) {
        const std::size_t at = f * part.pointsPerFace() + part.raster().index(i, k);
        const Vec3 v = part.vectorAt(f, part.rasterBary(i, k));
        const double along = (part.allHeights()[at] - design[at]) * v.norm();
        least = std::min(least, along), most = std::max(most, along);
      }
  qInfo(
      "blade: %d support faces, crust reach above %.3g mm (min); raised 0.5 mm: the raster "
      "points moved %.3g..%.3g mm along their stubbles",
      part.faceCount(), report->stock->reach.minAboveMm, least, most);
  QVERIFY(least >= 0.5 * (1.0 - 1e-3));
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "part_import_blade_stock");
}

DDFCAM_GUI_TEST_MAIN(PartImportTest)
#include "part_import_test.moc"
