// SPDX-License-Identifier: MIT
// Tools panel under Xvfb: add, edit, duplicate and delete tools with exact undo and redo,
// inline validation, tool library round trip, the tool drawn in the view.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "simulation_fixture.h"
#include "workbench_test.h"

#include <ddfcam/gui/panels/tool_editor.h>
#include <ddfcam/gui/panels/tools_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/tool_overlay.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/io/project/tool_library_file.h>

#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <vtkPolyData.h>

using ddfcam::gui::ToolsPanel;
using ddfcam::planning::Tool;
using ddfcam::planning::ToolKind;

class ToolsPanelTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private:
  ToolsPanel& panel() { return *f_.window->findChild<ToolsPanel*>(); }
  QUndoStack& undo() { return *f_.window->document().undoStack(); }
  template <typename W>
  W* field(const char* name) {
    auto* w = panel().editor().findChild<W*>(name);
    if (w == nullptr) qFatal("no field %s", name);
    return w;
  }
  /// Types @p value into the spin box @p name and presses Enter, as a user would.
  void typeLength(const char* name, double value) {
    auto* spin = field<QDoubleSpinBox>(name);
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, spin->textFromValue(value));
    QTest::keyClick(spin, Qt::Key_Enter);
  }

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void init() {
    load(ddfcam::test::smallDemo().project);
    f_.script.errors.clear();
  }
  void addEditUndoRedoRestoreExactValues();
  void deleteRenumbersPathsAndRefusesUsedTools();
  void invalidFieldShowsMessageAndKeepsProject();
  void libraryFileRoundTrip();
  void selectedToolIsDrawnInTwoColours();
};

void ToolsPanelTest::addEditUndoRedoRestoreExactValues() {
  const Tool roll = project().tools.at(0);
  QVERIFY(panel().addTool(ToolKind::BallEnd));
  QCOMPARE(project().tools.size(), std::size_t{2});
  QCOMPARE(panel().selectedTool(), 1);
  const Tool added = project().tools[1];
  QCOMPARE(added.kind, ToolKind::BallEnd);
  // A value with more digits than the form shows survives edits of other fields bit for bit.
  Tool precise = added;
  precise.radiusMm = 1.0 / 3.0;
  QVERIFY(panel().editTool(1, precise));
  QCOMPARE(project().tools[1], precise);
  const int before = undo().count();
  typeLength("toolShankLength", 27.5);
  QCOMPARE(undo().count(), before + 1);
  Tool expected = precise;
  expected.shankLengthMm = 27.5;
  QCOMPARE(project().tools[1], expected);
  QCOMPARE(project().tools[1].radiusMm, 1.0 / 3.0);
  auto* name = field<QLineEdit>("toolName");
  name->setFocus();
  name->selectAll();
  QTest::keyClicks(name, "fine ball");
  QTest::keyClick(name, Qt::Key_Enter);
  QCOMPARE(project().tools[1].name, std::string("fine ball"));
  undo().undo();
  QCOMPARE(project().tools[1], expected);
  undo().undo();
  QCOMPARE(project().tools[1], precise);
  QCOMPARE(field<QDoubleSpinBox>("toolShankLength")->value(), added.shankLengthMm);
  undo().redo();
  QCOMPARE(project().tools[1], expected);
  QVERIFY(panel().duplicateTool(1));
  QCOMPARE(project().tools.size(), std::size_t{3});
  QCOMPARE(project().tools[2].name, expected.name + " copy");
  QCOMPARE(project().tools[2].shankLengthMm, 27.5);
  while (undo().count() > 0 && project().tools.size() > 1) undo().undo();
  QCOMPARE(project().tools.size(), std::size_t{1});
  QCOMPARE(project().tools[0], roll);
  QVERIFY(f_.script.errors.isEmpty());
}

void ToolsPanelTest::deleteRenumbersPathsAndRefusesUsedTools() {
  // Two tools, the path uses the second: deleting the first renumbers the path.
  auto demo = ddfcam::test::smallDemo();
  Tool ball = ToolsPanel::defaultTool(ToolKind::Sphere);
  demo.project.tools.insert(demo.project.tools.begin(), ball);
  demo.project.paths[0].tool = 1;
  load(demo.project);
  const Tool roll = project().tools[1];
  QVERIFY(panel().deleteTool(0));
  QCOMPARE(project().tools.size(), std::size_t{1});
  QCOMPARE(project().tools[0], roll);
  QCOMPARE(project().paths[0].tool, 0);
  // The roll is used by the path: refused with a message naming the path.
  const int count = undo().count();
  QVERIFY(!panel().deleteTool(0));
  QCOMPARE(f_.script.errors.size(), 1);
  QVERIFY2(f_.script.errors[0].contains("demo passes"), qPrintable(f_.script.errors[0]));
  QCOMPARE(undo().count(), count);
  QCOMPARE(project().tools.size(), std::size_t{1});
  f_.script.errors.clear();
  undo().undo();
  QCOMPARE(project().tools.size(), std::size_t{2});
  QCOMPARE(project().tools[0], ball);
  QCOMPARE(project().tools[1], roll);
  QCOMPARE(project().paths[0].tool, 1);
}

void ToolsPanelTest::invalidFieldShowsMessageAndKeepsProject() {
  panel().selectTool(0);
  const Tool roll = project().tools[0];
  const int count = undo().count();
  // A crown must be at least half the width (10 mm): 2 mm is refused.
  typeLength("toolCrownRadius", 2.0);
  auto* message = panel().findChild<QLabel*>("toolMessage");
  QVERIFY(message != nullptr);
  QVERIFY(!message->isHidden());
  QVERIFY2(message->text().contains("crown", Qt::CaseInsensitive), qPrintable(message->text()));
  QCOMPARE(project().tools[0], roll);
  QCOMPARE(undo().count(), count);
  QVERIFY(f_.script.errors.isEmpty());  // inline, not a dialog
  // A zero chord tolerance likewise.
  QVERIFY(!panel().editTool(0, [&] {
    Tool t = roll;
    t.chordToleranceMm = 0.0;
    return t;
  }()));
  QVERIFY(!message->text().isEmpty());
  QCOMPARE(project().tools[0], roll);
  // Fixing the field clears the message and applies.
  typeLength("toolCrownRadius", 20.0);
  QVERIFY(message->isHidden());
  QCOMPARE(project().tools[0].crownRadiusMm, 20.0);
  QCOMPARE(undo().count(), count + 1);
}

void ToolsPanelTest::libraryFileRoundTrip() {
  for (const ToolKind kind : {ToolKind::BeltContactWheel, ToolKind::BallEnd, ToolKind::FlatEnd,
                              ToolKind::TorusCutter, ToolKind::Sphere})
    QVERIFY(panel().addTool(kind));
  Tool odd = project().tools[2];
  odd.radiusMm = 2.0 / 3.0;
  odd.chordToleranceMm = 1e-3 / 7.0;
  QVERIFY(panel().editTool(2, odd));
  const std::vector<Tool> saved = project().tools;
  const QString path = f_.dir.filePath("tools.txt");
  QVERIFY(panel().saveLibrary(path));
  QVERIFY(QFile::exists(path));
  // Independent reader: the io library parses what the panel wrote.
  QCOMPARE(ddfcam::io::readToolLibrary(path.toStdString()), saved);
  const int count = undo().count();
  QVERIFY(panel().loadLibrary(path));
  QCOMPARE(undo().count(), count + 1);
  QCOMPARE(project().tools.size(), 2 * saved.size());
  for (std::size_t i = 0; i < saved.size(); ++i)
    QCOMPARE(project().tools[saved.size() + i], saved[i]);
  undo().undo();
  QCOMPARE(project().tools, saved);
  // A missing file is reported and changes nothing.
  QVERIFY(!panel().loadLibrary(f_.dir.filePath("missing.txt")));
  QCOMPARE(f_.script.errors.size(), 1);
  QCOMPARE(project().tools, saved);
  f_.script.errors.clear();
}

void ToolsPanelTest::selectedToolIsDrawnInTwoColours() {
  QVERIFY(panel().addTool(ToolKind::BallEnd));
  const Tool ball = project().tools[1];
  auto& scene = f_.window->partView().scene();
  QVERIFY(scene.hasOverlay(ddfcam::gui::kToolCuttingOverlay));
  QVERIFY(scene.hasOverlay(ddfcam::gui::kToolNonCuttingOverlay));
  double cut[6], rest[6];
  scene.overlayData(ddfcam::gui::kToolCuttingOverlay)->GetBounds(cut);
  scene.overlayData(ddfcam::gui::kToolNonCuttingOverlay)->GetBounds(rest);
  // The flutes: 2 R wide, widthMm long from the tip; the shank and holder above them.
  QVERIFY(std::abs((cut[1] - cut[0]) - 2 * ball.radiusMm) < 0.02);
  QVERIFY(std::abs((cut[5] - cut[4]) - ball.widthMm) < 0.02);
  QVERIFY2(rest[4] > cut[5] - 0.02, qPrintable(QString("%1 %2").arg(rest[4]).arg(cut[5])));
  QVERIFY(std::abs((rest[5] - rest[4]) - (ball.shankLengthMm + ball.holderLengthMm)) < 0.02);
  // Above the part (its top is below z = 3 mm).
  QVERIFY(cut[4] > 2.0);
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "tools_panel_ball_end");
  QVERIFY(raisePanel("tools"));
  ddfcam::test::dumpFrame(panel().grab().toImage(), "tools_panel_form");
  // The path's roll is drawn at the path's first pose.
  panel().selectTool(0);
  scene.overlayData(ddfcam::gui::kToolCuttingOverlay)->GetBounds(cut);
  const auto centre = project().paths[0].poses.front().pose.translation();
  QVERIFY(std::abs(0.5 * (cut[2] + cut[3]) - centre.y()) < 0.05);
  QVERIFY(std::abs(0.5 * (cut[0] + cut[1]) - centre.x()) < 0.05);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "tools_panel_roll_on_path");
}

DDFCAM_GUI_TEST_MAIN(ToolsPanelTest)
#include "tools_panel_test.moc"
