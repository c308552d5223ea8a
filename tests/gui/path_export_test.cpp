// SPDX-License-Identifier: MIT
// File > Export tool paths under Xvfb: CSV, APT (both dialects, inch) and G-code (3-axis, A/C,
// B/C) written from a project with a roll path and two ball-end paths, read back and compared
// with the project's poses to the written precision; one file per region; inline validation.
#include "frame_checks.h"
#include "gui_test_registry.h"
#include "workbench_fixture.h"

#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/path_export_dialog.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/io/programs/apt_reader.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/planning/model/demo_project.h>

#include <QAction>
#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QRegularExpression>
#include <QStatusBar>
#include <QtTest/QtTest>

#include <cmath>
#include <filesystem>
#include <numbers>

using ddfcam::gui::PathExportDialect;
using ddfcam::gui::PathExportFormat;
using ddfcam::gui::PathExportGrouping;
using ddfcam::gui::PathExportOptions;
namespace io = ddfcam::io;
namespace planning = ddfcam::planning;
using ddfcam::ddf::Vec3;

namespace {

constexpr double kBallRadiusMm = 2.0;

// A ball-end path on the contacts of one demo pass: the ball touches each contact along the
// demo roll's normal (contact -> roll centre), its axis tilted by tiltDeg about x.
planning::ToolPath ballPath(const planning::ToolPath& demo, int pass, double tiltDeg,
                            const std::string& name) {
  planning::ToolPath path;
  path.name = name;
  path.tool = 1;
  path.feedMmPerMin = 600.0;
  path.passStarts = {0};
  const int begin = demo.passStarts[static_cast<std::size_t>(pass)];
  const int end = pass + 1 < static_cast<int>(demo.passStarts.size())
                      ? demo.passStarts[static_cast<std::size_t>(pass) + 1]
                      : static_cast<int>(demo.poses.size());
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(tiltDeg * std::numbers::pi / 180.0, Vec3::UnitX()).toRotationMatrix();
  for (int i = begin; i < end; ++i) {
    const auto& roll = demo.poses[static_cast<std::size_t>(i)];
    const Vec3 normal = (roll.pose.translation() - roll.contact).normalized();
    planning::PathPose pose;
    pose.contact = roll.contact;
    pose.pose.linear() = tilt;
    pose.pose.translation() =
        roll.contact + kBallRadiusMm * normal - kBallRadiusMm * (tilt * Vec3::UnitZ());
    path.poses.push_back(pose);
  }
  return path;
}

// Demo project + ball-end tool 1, path 1 vertical at x = 14, path 2 tilted 20 degrees at
// x = 26; regions "left" (faces left of x = 17) and "right".
planning::Project exportProject() {
  planning::Project project = planning::demoProject();
  project.tools.push_back(planning::Tool{.name = "ball R2",
                                         .kind = planning::ToolKind::BallEnd,
                                         .radiusMm = kBallRadiusMm,
                                         .widthMm = 8.0});
  const planning::ToolPath demo = project.paths.front();
  project.paths.push_back(ballPath(demo, 0, 0.0, "ball vertical"));
  project.paths.push_back(ballPath(demo, 2, 20.0, "ball tilted"));
  planning::Region left, right;
  left.name = "left";
  right.name = "right";
  const auto& part = *project.part;
  for (int f = 0; f < part.faceCount(); ++f) {
    Vec3 centre = Vec3::Zero();
    for (int v : part.faceVertices(f))
      centre += ddfcam::ddf::toEigen(part.support().point(OpenMesh::VertexHandle(v))) / 3.0;
    (centre.x() < 17.0 ? left : right).faces.push_back(f);
  }
  project.regions = {left, right};
  return project;
}

std::filesystem::path fsPath(const QString& file) {
  return std::filesystem::path(file.toStdU16String());
}

std::vector<planning::ClPoint> cutPoints(const planning::ClProgram& program) {
  std::vector<planning::ClPoint> cuts;
  for (const auto& p : program.points)
    if (p.move == planning::MoveKind::Cut) cuts.push_back(p);
  return cuts;
}

QString readText(const QString& file) {
  QFile f(file);
  return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// Tool positions of the G0/G1 lines of a G-code file (X Y Z modal), mm or inch as written.
std::vector<Vec3> gcodeMoves(const QString& text) {
  std::vector<Vec3> moves;
  Vec3 at = Vec3::Zero();
  const QRegularExpression word(R"(([XYZ])\s*(-?[0-9.]+))");
  for (const QString& line : text.split('\n')) {
    if (!line.contains(QRegularExpression(R"(\bG0?1\b)"))) continue;
    for (auto m = word.globalMatch(line); m.hasNext();) {
      const auto match = m.next();
      const int axis = QString("XYZ").indexOf(match.captured(1));
      at[axis] = match.captured(2).toDouble();
    }
    moves.push_back(at);
  }
  return moves;
}

}  // namespace

class PathExportTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private:
  QTemporaryDir dir_;
  ddfcam::test::ScriptedDialogs script_;
  std::unique_ptr<QSettings> settings_;
  std::optional<PathExportOptions> choice_;   // what the scripted export dialog answers
  std::optional<PathExportOptions> offered_;  // what the window offered it
  std::unique_ptr<ddfcam::gui::MainWindow> window_;

  PathExportOptions options(PathExportFormat format, const QString& name,
                            std::vector<int> paths) const {
    PathExportOptions o;
    o.format = format;
    o.paths = std::move(paths);
    o.filePath = dir_.filePath(name);
    return o;
  }
  const planning::Project& project() const { return window_->document().project(); }

 private slots:
  void initTestCase() {
    ddfcam::gui::VtkErrorMonitor::install();
    QVERIFY(dir_.isValid());
    settings_ = std::make_unique<QSettings>(dir_.filePath("settings.ini"), QSettings::IniFormat);
    ddfcam::gui::WorkbenchDialogs dialogs = script_.dialogs();
    dialogs.exportPaths = [this](const planning::Project&, const PathExportOptions& initial) {
      offered_ = initial;
      return choice_;
    };
    ddfcam::gui::WorkbenchOptions options;
    options.openDemoAtStart = false;
    options.recoveryDirectory = dir_.filePath("recovery");
    options.settings = settings_.get();
    window_ = std::make_unique<ddfcam::gui::MainWindow>(dialogs, options);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    auto* action = window_->findChild<QAction*>("actionExportPaths");
    QVERIFY(action);
    QVERIFY(!action->isEnabled());  // no paths yet
    window_->document().reset(exportProject());
    QVERIFY(window_->waitForJobs());
    QVERIFY(action->isEnabled());
  }

  void csvContactPointsToTheWrittenPrecision() {
    PathExportOptions o = options(PathExportFormat::Csv, "all.csv", {0, 1, 2});
    o.coordinateDecimals = 4;
    choice_ = o;
    window_->findChild<QAction*>("actionExportPaths")->trigger();
    QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
    // Two tools: the roll's path and the ball-end paths go to files of their own.
    const QStringList files = QDir(dir_.path()).entryList({"all*.csv"}, QDir::Files);
    QCOMPARE(files.size(), 2);
    std::size_t compared = 0;
    for (const QString& name : files) {
      const planning::ClProgram program = io::readToolPathCsv(fsPath(dir_.filePath(name)));
      QCOMPARE(program.pointKind, planning::ClPointKind::Contact);
      const auto cuts = cutPoints(program);
      const bool roll = cuts.size() == project().paths[0].poses.size();
      std::vector<planning::PathPose> poses = project().paths[roll ? 0 : 1].poses;
      if (!roll)
        poses.insert(poses.end(), project().paths[2].poses.begin(), project().paths[2].poses.end());
      QCOMPARE(cuts.size(), poses.size());
      for (std::size_t i = 0; i < poses.size(); ++i) {
        QVERIFY((cuts[i].positionMm - poses[i].contact).cwiseAbs().maxCoeff() <= 0.5e-4 + 1e-9);
        ++compared;
      }
    }
    QVERIFY(compared > 100);
  }

  void aptInInchBothDialects() {
    for (const auto dialect : {PathExportDialect::AptStandard, PathExportDialect::AptNx}) {
      PathExportOptions o = options(PathExportFormat::Apt, "balls.apt", {1, 2});
      o.dialect = dialect;
      o.unit = ddfcam::LengthUnit::Inch;
      o.coordinateDecimals = 5;
      o.vectorDecimals = 8;
      QStringList written;
      QVERIFY(ddfcam::gui::runUserAction(script_.dialogs().error, "export", [&] {
        written = ddfcam::gui::exportPaths(project(), o);
      }));
      QCOMPARE(written.size(), 1);
      const QString text = readText(written.front());
      QVERIFY(text.contains("UNITS/INCHES"));
      QVERIFY(text.contains(dialect == PathExportDialect::AptNx ? "FEDRAT/IPM," : ",IPM"));
      const planning::ClProgram program = io::readApt(fsPath(written.front()));
      // APT has no link moves: the retract between the two paths reads back as a feed move, the
      // lift's rapid as a rapid, and the approach ends on the second path's first point, which
      // is written once (no zero-length GOTO); each path is one pass.
      const auto cuts = cutPoints(program);
      std::vector<planning::PathPose> poses = project().paths[1].poses;
      poses.insert(poses.end(), project().paths[2].poses.begin(), project().paths[2].poses.end());
      QCOMPARE(cuts.size(), poses.size() + 1);
      std::size_t at = 0;
      for (const auto& pose : poses) {
        const Vec3 reference = pose.pose.translation();
        while (at < cuts.size() &&
               (cuts[at].positionMm - reference).cwiseAbs().maxCoeff() > 0.5e-5 * 25.4 + 1e-9)
          ++at;
        QVERIFY2(at < cuts.size(), "a tool reference point is missing from the APT file");
        QVERIFY(cuts[at].axis);
        const Vec3 axis = pose.pose.linear() * Vec3::UnitZ();
        QVERIFY((*cuts[at].axis - axis).cwiseAbs().maxCoeff() <= 0.5e-8 + 1e-12);
        ++at;
      }
    }
  }

  void gcodeThreeAxisTips() {
    PathExportOptions o = options(PathExportFormat::GCode, "vertical.nc", {1});
    o.dialect = PathExportDialect::GCode3Axis;
    o.coordinateDecimals = 4;
    const QStringList written = ddfcam::gui::exportPaths(project(), o);
    QCOMPARE(written.size(), 1);
    const auto moves = gcodeMoves(readText(written.front()));
    // Every tip appears among the G1 moves, in order.
    std::size_t at = 0;
    for (const auto& pose : project().paths[1].poses) {
      while (at < moves.size() &&
             (moves[at] - pose.pose.translation()).cwiseAbs().maxCoeff() > 0.5e-4 + 1e-9)
        ++at;
      QVERIFY2(at < moves.size(), "a tip is missing from the G-code");
      ++at;
    }
  }

  void gcodeFiveAxisMachines() {
    for (const auto dialect : {PathExportDialect::GCode5AxisAC, PathExportDialect::GCode5AxisBC}) {
      PathExportOptions o = options(PathExportFormat::GCode, "tilted.nc", {2});
      o.dialect = dialect;
      QVERIFY(ddfcam::gui::pathExportProblem(project(), o).isEmpty());
      const QString text = readText(ddfcam::gui::exportPaths(project(), o).front());
      const QString tilt = dialect == PathExportDialect::GCode5AxisAC ? "A" : "B";
      const QString other = dialect == PathExportDialect::GCode5AxisAC ? "B" : "A";
      QVERIFY(text.contains(QRegularExpression("G1 .*" + tilt + "-?[0-9]")));
      QVERIFY(!text.contains(QRegularExpression("G1 .*" + other + "-?[0-9]")));
      QVERIFY(text.contains(QRegularExpression("G1 .*C-?[0-9]")));
    }
  }

  void onePerRegionCountsCutPoints() {
    PathExportOptions o = options(PathExportFormat::Csv, "regions.csv", {1, 2});
    o.grouping = PathExportGrouping::FilePerRegion;
    const QStringList written = ddfcam::gui::exportPaths(project(), o);
    QCOMPARE(written.size(), 2);
    QVERIFY(written[0].endsWith("regions_left.csv"));
    QVERIFY(written[1].endsWith("regions_right.csv"));
    QCOMPARE(cutPoints(io::readToolPathCsv(fsPath(written[0]))).size(),
             project().paths[1].poses.size());
    QCOMPARE(cutPoints(io::readToolPathCsv(fsPath(written[1]))).size(),
             project().paths[2].poses.size());
  }

  void validationNamesTheProblem() {
    PathExportOptions o = options(PathExportFormat::GCode, "bad.nc", {2});
    o.dialect = PathExportDialect::GCode3Axis;
    const QString tilted = ddfcam::gui::pathExportProblem(project(), o);
    QVERIFY2(tilted.contains("3-axis") && tilted.contains("ball tilted") && tilted.contains("20.0"),
             qPrintable(tilted));
    o.paths = {0};
    QVERIFY(ddfcam::gui::pathExportProblem(project(), o).contains("cutters"));
    o.paths = {};
    QVERIFY(ddfcam::gui::pathExportProblem(project(), o).contains("at least one"));
    // Through the menu: one error, no file.
    o.paths = {2};
    choice_ = o;
    script_.errors.clear();
    window_->findChild<QAction*>("actionExportPaths")->trigger();
    QCOMPARE(script_.errors.size(), 1);
    QVERIFY(script_.errors.front().contains("3-axis"));
    QVERIFY(!QFile::exists(o.filePath));
    script_.errors.clear();
  }

  void dialogShowsProblemsInline() {
    PathExportOptions o = options(PathExportFormat::Csv, "dialog.csv", {});
    ddfcam::gui::PathExportDialog dialog(project(), o, window_.get());
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QVERIFY(dialog.problem().isEmpty());
    QCOMPARE(dialog.options().paths, (std::vector<int>{0, 1, 2}));  // all checked
    auto* format = dialog.findChild<QComboBox*>("exportFormat");
    format->setCurrentIndex(format->findData(int(PathExportFormat::GCode)));
    QVERIFY(dialog.options().filePath.endsWith("dialog.ngc"));
    QCOMPARE(dialog.options().point, planning::ClPointKind::ToolReference);
    QVERIFY(dialog.problem().contains("cutters"));  // the roll path is checked
    dialog.findChild<QListWidget*>("exportPaths")->item(0)->setCheckState(Qt::Unchecked);
    auto* dialect = dialog.findChild<QComboBox*>("exportDialect");
    dialect->setCurrentIndex(dialect->findData(int(PathExportDialect::GCode3Axis)));
    QVERIFY(dialog.problem().contains("3-axis"));
    QVERIFY(dialog.findChild<QLabel*>("exportProblem")->isVisible());
    ddfcam::test::dumpFrame(dialog.grab().toImage(), "path_export_dialog_3axis");
    dialect->setCurrentIndex(dialect->findData(int(PathExportDialect::GCode5AxisAC)));
    QVERIFY(dialog.problem().isEmpty());
    ddfcam::test::dumpFrame(dialog.grab().toImage(), "path_export_dialog_5axis");
  }

  void gcodeForAMachineFileKeepsTipsAndAxes() {
    PathExportOptions o = options(PathExportFormat::GCode, "haas.nc", {2});
    o.machineFile = QString(DDFCAM_SOURCE_DIR) + "/resources/machines/haas-umc750.json";
    QVERIFY(ddfcam::gui::pathExportProblem(project(), o).isEmpty());
    QVERIFY(ddfcam::gui::exportMachineName(o).startsWith("Haas UMC-750"));
    const QString text = readText(ddfcam::gui::exportPaths(project(), o).front());
    QVERIFY(text.contains("(machine: Haas UMC-750"));
    QVERIFY(text.contains(QRegularExpression("\\nG234 H[0-9]+\\n")));
    // TCP: X Y Z are the tips; B and C give the axis by the Haas convention
    // (sin B cos C, sin B sin C, cos B), read here from the text.
    const QRegularExpression word(R"(([XYZBC])\s*(-?[0-9.]+))");
    std::vector<std::pair<Vec3, Vec3>> moves;  // tip, axis
    double b = 0.0, c = 0.0;
    Vec3 at = Vec3::Zero();
    for (const QString& line : text.split('\n')) {
      for (auto m = word.globalMatch(line); m.hasNext();) {
        const auto match = m.next();
        const double v = match.captured(2).toDouble();
        if (match.captured(1) == "B")
          b = v;
        else if (match.captured(1) == "C")
          c = v;
        else
          at[QString("XYZ").indexOf(match.captured(1))] = v;
      }
      if (!line.startsWith("G1 ")) continue;
      const double br = b * std::numbers::pi / 180.0, cr = c * std::numbers::pi / 180.0;
      moves.push_back(
          {at, Vec3(std::sin(br) * std::cos(cr), std::sin(br) * std::sin(cr), std::cos(br))});
    }
    std::size_t found = 0;
    for (const auto& pose : project().paths[2].poses) {
      const Vec3 tip = pose.pose.translation();
      const Vec3 axis = pose.pose.linear() * Vec3::UnitZ();
      for (const auto& [t, a] : moves) {
        if ((t - tip).cwiseAbs().maxCoeff() > 0.5e-4 + 1e-9) continue;
        QVERIFY((a - axis).norm() < 1e-5);
        ++found;
        break;
      }
    }
    QCOMPARE(found, project().paths[2].poses.size());
  }

  void dialogTakesAMachineFile() {
    PathExportOptions o = options(PathExportFormat::GCode, "machine.ngc", {1, 2});
    ddfcam::gui::PathExportDialog dialog(project(), o, window_.get());
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    auto* machine = dialog.findChild<QLineEdit*>("exportMachineFile");
    auto* dialect = dialog.findChild<QComboBox*>("exportDialect");
    auto* name = dialog.findChild<QLabel*>("exportMachineName");
    QVERIFY(machine && dialect && name);
    QVERIFY(machine->isEnabled());
    QVERIFY(dialect->isEnabled());
    machine->setText(QString(DDFCAM_SOURCE_DIR) + "/resources/machines/haas-umc750.json");
    QVERIFY(!dialect->isEnabled());  // the machine replaces the dialect
    QVERIFY(name->isVisible());
    QVERIFY2(name->text().contains("B/C") && name->text().contains("TCP"),
             qPrintable(name->text()));
    QVERIFY(dialog.problem().isEmpty());
    QCOMPARE(dialog.options().machineFile, machine->text());
    ddfcam::test::dumpFrame(dialog.grab().toImage(), "path_export_dialog_machine");
    QFile bad(dir_.filePath("bad_machine.json"));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write(R"({"name": "x", "rotary_axes": "XY"})");
    bad.close();
    machine->setText(bad.fileName());
    QVERIFY2(dialog.problem().contains("machine file") && dialog.problem().contains("AC or BC"),
             qPrintable(dialog.problem()));
    // CSV has no machine.
    auto* format = dialog.findChild<QComboBox*>("exportFormat");
    format->setCurrentIndex(format->findData(int(PathExportFormat::Csv)));
    QVERIFY(!machine->isEnabled());
    QVERIFY(dialog.problem().isEmpty());
  }

  void remembersTheLastChoices() {
    PathExportOptions o = options(PathExportFormat::Apt, "remembered.apt", {1});
    o.dialect = PathExportDialect::AptNx;
    o.coordinateDecimals = 6;
    o.vectorDecimals = 9;
    choice_ = o;
    window_->findChild<QAction*>("actionExportPaths")->trigger();
    QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
    QVERIFY(QFile::exists(o.filePath));
    // Success is said in the status bar, with the file's name.
    QVERIFY2(window_->statusBar()->currentMessage().contains("remembered.apt"),
             qPrintable(window_->statusBar()->currentMessage()));
    choice_.reset();  // cancel the next one
    window_->findChild<QAction*>("actionExportPaths")->trigger();
    QVERIFY(offered_);
    QCOMPARE(offered_->format, PathExportFormat::Apt);
    QCOMPARE(offered_->dialect, PathExportDialect::AptNx);
    QCOMPARE(offered_->coordinateDecimals, 6);
    QCOMPARE(offered_->vectorDecimals, 9);
    QVERIFY(offered_->machineFile.isEmpty());
    // A machine file is remembered too.
    o = options(PathExportFormat::GCode, "remembered.ngc", {2});
    o.machineFile = QString(DDFCAM_SOURCE_DIR) + "/resources/machines/table-bc.json";
    choice_ = o;
    window_->findChild<QAction*>("actionExportPaths")->trigger();
    QVERIFY2(script_.errors.isEmpty(), qPrintable(script_.errors.join('\n')));
    choice_.reset();
    window_->findChild<QAction*>("actionExportPaths")->trigger();
    QCOMPARE(offered_->machineFile, o.machineFile);
    QVERIFY(offered_->filePath.startsWith(dir_.path()));
  }

  void suggestsTheFileAfterThePartWithoutItsSuffix() {
    const planning::Project saved = project();
    const std::vector<std::pair<std::string, QString>> cases = {
        {"blade mm.stl", "blade_mm"},     // a mesh: its suffix goes, blanks become '_'
        {"bolt_clip.STEP", "bolt_clip"},  // CAD, any case
        {"part.v2", "part.v2"},           // not a part file's suffix: part of the name
        {"", "paths"}};                   // unnamed
    for (const auto& [name, stem] : cases) {
      planning::Project renamed = saved;
      renamed.partName = name;
      window_->document().reset(std::move(renamed));
      QVERIFY(window_->waitForJobs());
      choice_.reset();  // the dialog is cancelled; what it was offered is checked
      offered_.reset();
      window_->findChild<QAction*>("actionExportPaths")->trigger();
      QVERIFY(offered_);
      const QFileInfo file(offered_->filePath);
      QCOMPARE(file.fileName(), stem + "." + ddfcam::gui::pathExportSuffix(offered_->format));
    }
    window_->document().reset(saved);
    QVERIFY(window_->waitForJobs());
  }

  void cleanup() { QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0); }
  void cleanupTestCase() { window_.reset(); }
};

DDFCAM_GUI_TEST_MAIN(PathExportTest)
#include "path_export_test.moc"
