// SPDX-License-Identifier: MIT
// File > Import tool path and dropped path files under Xvfb: a hand-written CSV (transform and
// unit override checked pose by pose), a hand-written APT with a CUTTER (new tool), the shared
// NX file by drag and drop; one undo step each, reader warnings in the console, bad files
// reported once.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_fixture.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/console_dock.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/path_import.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/io/programs/apt_reader.h>
#include <ddfcam/planning/model/demo_project.h>

#include <QAction>
#include <QComboBox>
#include <QDropEvent>
#include <QFile>
#include <QListWidget>
#include <QMimeData>
#include <QPushButton>
#include <QUndoStack>
#include <QUrl>
#include <QtTest/QtTest>

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>

using ddfcam::gui::PathImportOptions;
namespace io = ddfcam::io;
namespace planning = ddfcam::planning;
using ddfcam::ddf::Vec3;

namespace {

// Tool reference points (ball-end tips) of two paths over the demo part, mm.
const std::vector<std::vector<Vec3>> kCsvPaths = {
    {{10.0, 8.0, 4.0}, {12.0, 8.0, 4.0}, {14.0, 8.0, 4.0}, {16.0, 8.0, 4.0}},
    {{16.0, 12.0, 4.0}, {14.0, 12.0, 4.0}, {12.0, 12.0, 4.0}}};

const char* kApt =
    "PARTNO/GX TEST\n"
    "UNITS/MM\n"
    "CUTTER/4.0,2.0,0.0,2.0,0.0,0.0,10.0\n"
    "LOADTL/1\n"
    "FEDRAT/500.0,MMPM\n"
    "RAPID\n"
    "GOTO/10.0,10.0,20.0\n"
    "GOTO/10.0,10.0,3.0\n"
    "GOTO/12.0,10.0,3.0\n"
    "GOTO/14.0,10.0,3.0\n"
    "GOTO/16.0,10.0,3.0\n"
    "FINI\n";

QString sharedFile() {
  return QStringLiteral(DDFCAM_SHARED_DATA_DIR) + "/paths/mech491-nx-clsf/APT_Zig_Zag_Smoothed.txt";
}

bool writeText(const QString& file, const QByteArray& text) {
  QFile f(file);
  return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
}

QByteArray csvText() {
  QByteArray text = "path,point,tool_x_mm,tool_y_mm,tool_z_mm,axis_i,axis_j,axis_k\n";
  for (std::size_t p = 0; p < kCsvPaths.size(); ++p)
    for (std::size_t i = 0; i < kCsvPaths[p].size(); ++i)
      text += QString("%1,%2,%3,%4,%5,0,0,1\n")
                  .arg(p)
                  .arg(i)
                  .arg(kCsvPaths[p][i].x())
                  .arg(kCsvPaths[p][i].y())
                  .arg(kCsvPaths[p][i].z())
                  .toUtf8();
  return text;
}

// A robot pass over the demo part's surface as x,y,z,i,j,k rows (no header, as robot tools
// write them): points on the surface, vectors into the part (approach directions).
QByteArray robotCsv(std::vector<Vec3>& points, std::vector<Vec3>& normals) {
  const ddfcam::ddf::GeneratedSurface demo = ddfcam::ddf::demoPart();
  QByteArray text;
  for (int i = 0; i <= 10; ++i) {
    const Vec3 below(10.0 + i, 12.0, 0.0);
    const Vec3 p(below.x(), below.y(), -demo.surface->value(below));  // graph: value = z - f
    const Vec3 n = demo.surface->normal(p);
    points.push_back(p);
    normals.push_back(n);
    text += QString("%1 %2 %3 %4 %5 %6\n")
                .arg(p.x(), 0, 'f', 9)
                .arg(p.y(), 0, 'f', 9)
                .arg(p.z(), 0, 'f', 9)
                .arg(-n.x(), 0, 'f', 12)
                .arg(-n.y(), 0, 'f', 12)
                .arg(-n.z(), 0, 'f', 12)
                .toUtf8();
  }
  return text;
}

}  // namespace

class PathImportTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private:
  QTemporaryDir dir_;
  ddfcam::test::ScriptedDialogs script_;
  std::unique_ptr<QSettings> settings_;
  QString importFile_;                              // File > Import's file dialog answer
  std::function<void(PathImportOptions&)> adjust_;  // the scripted import dialog's edits
  bool cancelImport_ = false;
  std::unique_ptr<ddfcam::gui::MainWindow> window_;

  const planning::Project& project() const { return window_->document().project(); }
  QString console() const { return window_->console().text(); }

  void importByMenu(const QString& file) {
    importFile_ = file;
    window_->findChild<QAction*>("actionImportPath")->trigger();
  }

 private slots:
  void initTestCase() {
    ddfcam::gui::VtkErrorMonitor::install();
    QVERIFY(dir_.isValid());
    settings_ = std::make_unique<QSettings>(dir_.filePath("settings.ini"), QSettings::IniFormat);
    ddfcam::gui::WorkbenchDialogs dialogs = script_.dialogs();
    dialogs.importPathFile = [this] { return importFile_; };
    dialogs.importPath = [this](
                             const ddfcam::gui::PathImportRequest&,
                             const PathImportOptions& initial) -> std::optional<PathImportOptions> {
      if (cancelImport_) return std::nullopt;
      PathImportOptions o = initial;
      if (adjust_) adjust_(o);
      return o;
    };
    ddfcam::gui::WorkbenchOptions options;
    options.openDemoAtStart = false;
    options.recoveryDirectory = dir_.filePath("recovery");
    options.settings = settings_.get();
    window_ = std::make_unique<ddfcam::gui::MainWindow>(dialogs, options);
    window_->resize(1000, 700);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    planning::Project project = planning::demoProject();
    project.tools.push_back(planning::Tool{
        .name = "ball R2", .kind = planning::ToolKind::BallEnd, .radiusMm = 2.0, .widthMm = 8.0});
    window_->document().reset(std::move(project));
    QVERIFY(window_->waitForJobs());
  }

  void csvWithTransformIsOneUndoStep() {
    const QString file = dir_.filePath("hand.csv");
    QVERIFY(writeText(file, csvText()));
    const std::size_t before = project().paths.size();
    PathImportOptions chosen;
    adjust_ = [&](PathImportOptions& o) {
      QCOMPARE(o.unit, ddfcam::LengthUnit::Millimetre);  // as read
      o.toolIndex = 1;
      o.translationMm = Vec3(1.0, 2.0, 3.0);
      o.rotationDeg = Vec3(0.0, 0.0, 90.0);
      o.name = "hand csv";
      chosen = o;
    };
    importByMenu(file);
    QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
    QCOMPARE(project().paths.size(), before + 1);
    const planning::ToolPath& path = project().paths.back();
    QCOMPARE(path.name, std::string("hand csv"));
    QCOMPARE(path.tool, 1);
    QCOMPARE(path.poses.size(), std::size_t{7});
    QCOMPARE(path.passStarts, (std::vector<int>{0, 4}));
    // Rz(90) then + t: (x, y, z) -> (-y + 1, x + 2, z + 3); the axis stays +z.
    std::size_t k = 0;
    for (const auto& points : kCsvPaths)
      for (const Vec3& p : points) {
        const Vec3 expected(-p.y() + 1.0, p.x() + 2.0, p.z() + 3.0);
        const auto& pose = path.poses[k++].pose;
        QVERIFY((pose.translation() - expected).norm() < 1e-9);
        QVERIFY((pose.linear() * Vec3::UnitZ() - Vec3::UnitZ()).norm() < 1e-9);
      }
    window_->document().undoStack()->undo();
    QCOMPARE(project().paths.size(), before);
    adjust_ = {};
  }

  void unitOverrideScalesPositions() {
    const QString file = dir_.filePath("hand_small.csv");
    QVERIFY(writeText(file, csvText()));
    adjust_ = [](PathImportOptions& o) {
      o.toolIndex = 1;
      o.unit = ddfcam::LengthUnit::Inch;
    };
    importByMenu(file);
    QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
    const auto& pose = project().paths.back().poses.front().pose;
    QVERIFY((pose.translation() - 25.4 * kCsvPaths[0][0]).norm() < 1e-9);
    window_->document().undoStack()->undo();
    adjust_ = {};
  }

  void aptWithCutterAddsATool() {
    const QString file = dir_.filePath("hand.apt");
    QVERIFY(writeText(file, kApt));
    const std::size_t tools = project().tools.size();
    const std::size_t paths = project().paths.size();
    const long long drawn = window_->partView().scene().overlayCellCount("paths");
    adjust_ = [](PathImportOptions& o) {
      QCOMPARE(o.toolIndex, 0);
      o.toolIndex = -1;
    };
    importByMenu(file);
    QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
    QCOMPARE(project().tools.size(), tools + 1);
    QCOMPARE(project().tools.back().kind, planning::ToolKind::BallEnd);
    QCOMPARE(project().tools.back().radiusMm, 2.0);
    const planning::ToolPath& path = project().paths.back();
    QCOMPARE(path.tool, static_cast<int>(tools));
    QCOMPARE(path.poses.size(), std::size_t{4});  // the rapid is left out
    QCOMPARE(path.name, std::string("GX TEST"));
    QVERIFY((path.poses.back().pose.translation() - Vec3(16.0, 10.0, 3.0)).norm() < 1e-9);
    // Drawn like any path, listed and simulated by the Simulation panel (one more undo step).
    QVERIFY(window_->partView().scene().overlayCellCount("paths") > drawn);
    auto* list = window_->findChild<QListWidget*>("pathList");
    QVERIFY(list);
    QCOMPARE(list->count(), static_cast<int>(project().paths.size()));
    list->setCurrentRow(list->count() - 1);
    const int steps = window_->document().undoStack()->count();
    window_->findChild<QPushButton*>("simulateButton")->click();
    QVERIFY(window_->waitForJobs(60'000));
    QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
    QCOMPARE(window_->document().undoStack()->count(), steps + 1);
    window_->document().undoStack()->undo();
    window_->document().undoStack()->undo();
    QCOMPARE(project().tools.size(), tools);
    QCOMPARE(project().paths.size(), paths);
    adjust_ = {};
  }

  void dragEnterAcceptsPathFilesAndParts() {
    QVERIFY(writeText(dir_.filePath("a.apt"), kApt));
    QVERIFY(writeText(dir_.filePath("b.csv"), csvText()));
    QVERIFY(writeText(dir_.filePath("notes.txt"), "Remember to buy milk.\n"));
    for (const QString& name : {QString("a.apt"), QString("b.csv"), QString("part.stl")}) {
      QMimeData mime;
      mime.setUrls({QUrl::fromLocalFile(dir_.filePath(name))});
      QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
      enter.setAccepted(false);
      QApplication::sendEvent(window_.get(), &enter);
      QVERIFY2(enter.isAccepted(), qPrintable(name));
    }
    QMimeData mime;
    for (const QString& name : {QString("notes.xyz123"), QString("notes.txt")}) {
      mime.setUrls({QUrl::fromLocalFile(dir_.filePath(name))});
      QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
      enter.setAccepted(false);
      QApplication::sendEvent(window_.get(), &enter);
      QVERIFY2(!enter.isAccepted(), qPrintable(name));
    }
  }

  void droppedSharedNxFile() {
    const QString file = sharedFile();
    QVERIFY2(QFile::exists(file), qPrintable(file));
    // Independent count: the reader's non-rapid points (arcs interpolated).
    const planning::ClProgram program = io::readApt(std::filesystem::path(file.toStdString()));
    std::size_t expected = 0;
    for (const auto& p : program.points)
      if (p.move != planning::MoveKind::Rapid) ++expected;
    QVERIFY(expected >= 72);  // 75 GOTO records, 3 of them rapid
    const std::size_t paths = project().paths.size();
    adjust_ = [](PathImportOptions& o) {
      o.toolIndex = 1;
      o.translationMm = Vec3(-110.0, -135.0, -24.0);  // the zig-zag's corner onto the part
    };
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(file)});
    QDropEvent drop(QPointF(200, 200), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &drop);
    QTRY_COMPARE(project().paths.size(), paths + 1);
    QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
    QCOMPARE(project().paths.back().poses.size(), expected);
    QVERIFY(console().contains("APT_Zig_Zag_Smoothed.txt: line"));
    QVERIFY(console().contains("Imported path"));
    QApplication::processEvents();
    const QString out = qEnvironmentVariable("DDFCAM_GUI_TEST_OUTPUT");
    if (!out.isEmpty() && QDir(out).exists())
      QVERIFY(window_->saveScreenshot(QDir(out).filePath("path_import_nx_zigzag.png"),
                                      QSize(900, 600)));
    window_->document().undoStack()->undo();
    QCOMPARE(project().paths.size(), paths);
    adjust_ = {};
  }

  void robotVectorsAreReadAsTheDialogSays() {
    const QString file = dir_.filePath("robot.csv");
    std::vector<Vec3> points, normals;
    QVERIFY(writeText(file, robotCsv(points, normals)));
    const std::size_t paths = project().paths.size();
    // Default (detect from the part): approach directions, the ball's axis out of the part.
    for (const auto vectors :
         {planning::PathVectorMeaning::Auto, planning::PathVectorMeaning::ToolAxis}) {
      adjust_ = [&](PathImportOptions& o) {
        QCOMPARE(o.vectors, planning::PathVectorMeaning::Auto);
        QCOMPARE(o.points, planning::PathPointMeaning::Auto);
        o.toolIndex = 1;  // ball R2
        o.vectors = vectors;
      };
      importByMenu(file);
      QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
      const planning::ToolPath& path = project().paths.back();
      QCOMPARE(path.poses.size(), points.size());
      const double sign = vectors == planning::PathVectorMeaning::Auto ? 1.0 : -1.0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        QVERIFY((path.poses[i].pose.translation() - points[i]).norm() < 1e-6);
        QVERIFY(sign * (path.poses[i].pose.linear() * Vec3::UnitZ()).dot(normals[i]) > 0.999);
      }
    }
    QVERIFY2(console().contains("approach directions (detected"), qPrintable(console()));
    QVERIFY2(console().contains("11 of 11 poses gouge the part"), qPrintable(console()));
    QCOMPARE(project().paths.size(), paths + 2);
    window_->document().undoStack()->undo();
    window_->document().undoStack()->undo();
    QCOMPARE(project().paths.size(), paths);
    adjust_ = {};
  }

  void dialogShowsTheFile() {
    const QString file = dir_.filePath("dialog.apt");
    QVERIFY(writeText(file, kApt));
    const planning::ClProgram program = io::readApt(std::filesystem::path(file.toStdString()));
    const ddfcam::gui::PathImportRequest request{file, program, project()};
    const PathImportOptions initial = ddfcam::gui::initialImportOptions(request);
    ddfcam::gui::PathImportDialog dialog(request, initial, window_.get());
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    const PathImportOptions shown = dialog.options();
    QCOMPARE(shown.unit, ddfcam::LengthUnit::Millimetre);
    QCOMPARE(shown.toolIndex, 0);
    QCOMPARE(shown.name, QString("GX TEST"));
    QCOMPARE(shown.vectors, planning::PathVectorMeaning::Auto);
    QCOMPARE(shown.points, planning::PathPointMeaning::Auto);
    auto* vectors = dialog.findChild<QComboBox*>("importVectors");
    auto* points = dialog.findChild<QComboBox*>("importPoints");
    QVERIFY(vectors && points);
    vectors->setCurrentIndex(
        vectors->findData(int(planning::PathVectorMeaning::ApproachDirection)));
    points->setCurrentIndex(points->findData(int(planning::PathPointMeaning::Contact)));
    QCOMPARE(dialog.options().vectors, planning::PathVectorMeaning::ApproachDirection);
    QCOMPARE(dialog.options().points, planning::PathPointMeaning::Contact);
    ddfcam::test::dumpFrame(dialog.grab().toImage(), "path_import_dialog");
  }

  void badFileIsReportedOnce() {
    const QString file = dir_.filePath("bad.apt");
    QVERIFY(writeText(file, "PARTNO/BAD\nGOTO/1.0,2.0\nFINI\n"));
    const std::size_t paths = project().paths.size();
    const int undo = window_->document().undoStack()->count();
    QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
    importByMenu(file);
    QCOMPARE(script_.errors.size(), 1);
    QVERIFY2(script_.errors.front().contains("bad.apt"), qPrintable(script_.errors.front()));
    QCOMPARE(project().paths.size(), paths);
    QCOMPARE(window_->document().undoStack()->count(), undo);
    script_.errors.clear();
    importByMenu(dir_.filePath("missing.csv"));
    QCOMPARE(script_.errors.size(), 1);
    script_.errors.clear();
  }

  void cancelledImportChangesNothing() {
    const QString file = dir_.filePath("cancel.csv");
    QVERIFY(writeText(file, csvText()));
    const std::size_t paths = project().paths.size();
    cancelImport_ = true;
    importByMenu(file);
    cancelImport_ = false;
    QCOMPARE(project().paths.size(), paths);
    QVERIFY(script_.errors.isEmpty());
  }

  void cleanup() { QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0); }
  void cleanupTestCase() { window_.reset(); }
};

DDFCAM_GUI_TEST_MAIN(PathImportTest)
#include "path_import_test.moc"
