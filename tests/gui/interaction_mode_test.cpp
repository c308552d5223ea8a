// SPDX-License-Identifier: MIT
// The interaction mode under Xvfb: a panel's brush, drawing or pick mode is shown in the status
// bar, Esc returns to navigation, leaving the panel ends its mode, and a drag after that turns
// the camera instead of editing (a brush chosen in one panel once painted 156 faces from
// another).
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/gui/interaction_mode.h>
#include <ddfcam/gui/panels/mould_panel.h>
#include <ddfcam/gui/panels/segmentation_panel.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/model/demo_project.h>

#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <QtTest/QtTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <array>

using ddfcam::gui::RegionEditMode;
using ddfcam::gui::SegmentationPanel;

class InteractionModeTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void init();
  void brushShowsInTheStatusBarAndEscReturnsToNavigation();
  void leavingThePanelEndsItsModeAndADragTurnsTheCamera();
  void aNewModeEndsTheOneBefore();
  void mouldPicksAreModesToo();
  void theWheelOverABoxScrollsThePanel();

 private:
  QString statusText() const {
    return f_.window->findChild<QLabel*>("interactionModeLabel")->text();
  }
  ddfcam::gui::InteractionMode& mode() const { return *f_.window->workbench().mode; }
  SegmentationPanel& segmentation() const { return *f_.window->findChild<SegmentationPanel*>(); }
  QComboBox& paintCombo() const { return *f_.window->findChild<QComboBox*>("regionEditMode"); }
  std::array<double, 3> camera() const {
    std::array<double, 3> p{};
    f_.window->view()->renderer()->GetActiveCamera()->GetPosition(p.data());
    return p;
  }
  /// Esc as the engineer presses it: to the focused widget of the active window.
  void pressEscape() {
    f_.window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(f_.window.get()));
    QWidget* target = QApplication::focusWidget() ? QApplication::focusWidget() : f_.window.get();
    QTest::keyClick(target, Qt::Key_Escape);
  }
  /// Back to navigation, as the engineer sees it: the panel's combo off, the status bar says
  /// so, and a drag turns the part and paints nothing.
  void expectNavigation() {
    QCOMPARE(paintCombo().currentIndex(), 0);
    QCOMPARE(segmentation().viewTool().mode(), RegionEditMode::None);
    QVERIFY(mode().owner() == nullptr);
    QVERIFY2(statusText().startsWith("Navigate:"), qPrintable(statusText()));
    const auto regions = project().regions;
    const auto before = camera();
    dragAcrossTheView();
    QVERIFY(project().regions == regions);
    QVERIFY(camera() != before);
  }
  /// A left drag across the middle of the part view.
  void dragAcrossTheView() {
    auto& view = *f_.window->view();
    const QPoint c = view.rect().center();
    QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, c + QPoint(-40, 0));
    for (int x = -30; x <= 40; x += 10) QTest::mouseMove(&view, c + QPoint(x, 5));
    QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, c + QPoint(40, 5));
    QApplication::processEvents();
  }
};

void InteractionModeTest::init() {
  f_.script.errors.clear();
  ddfcam::planning::Project p = ddfcam::planning::demoProject();
  p.regions.push_back({"target", {}, {0.2f, 0.6f, 0.9f}, {}});
  load(std::move(p));
  QVERIFY(raisePanel("segmentation"));
  segmentation().selectRegions({static_cast<int>(project().regions.size()) - 1});
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusZ);
}

void InteractionModeTest::brushShowsInTheStatusBarAndEscReturnsToNavigation() {
  QVERIFY2(statusText().startsWith("Navigate:"), qPrintable(statusText()));
  segmentation().setEditMode(RegionEditMode::Brush);
  QVERIFY2(statusText().contains("Brush (Segmentation)") && statusText().contains("(Esc: navigate)"),
           qPrintable(statusText()));
  QCOMPARE(mode().name(), QString("Brush"));
  QApplication::processEvents();  // the status bar lays the longer text out
  ddfcam::test::dumpFrame(f_.window->grab().toImage(), "interaction_mode_brush");
  // Esc in the window (no job runs): back to navigation, the panel's combo says so too.
  pressEscape();
  expectNavigation();
}

void InteractionModeTest::leavingThePanelEndsItsModeAndADragTurnsTheCamera() {
  segmentation().setEditMode(RegionEditMode::Brush);
  QVERIFY(mode().owner() == &segmentation());
  // The brush paints while its panel is in front (the mode is real) ...
  {
    const auto regions = project().regions;
    dragAcrossTheView();
    QVERIFY(project().regions != regions);
  }
  // ... and ends when another tab of the dock group comes to the front.
  QVERIFY(raisePanel("fields"));
  expectNavigation();
}

void InteractionModeTest::aNewModeEndsTheOneBefore() {
  segmentation().setEditMode(RegionEditMode::Lasso);
  QCOMPARE(mode().name(), QString("Lasso"));
  auto* streamlines = f_.window->findChild<ddfcam::gui::StreamlinesPanel*>();
  streamlines->setDrawDirection(true);
  QCOMPARE(paintCombo().currentIndex(), 0);  // the lasso was ended
  QVERIFY2(statusText().contains("Draw direction"), qPrintable(statusText()));
  streamlines->setDrawDirection(false);
  QVERIFY2(statusText().startsWith("Navigate:"), qPrintable(statusText()));
}

void InteractionModeTest::mouldPicksAreModesToo() {
  auto* mould = f_.window->findChild<ddfcam::gui::MouldPanel*>();
  QVERIFY(raisePanel("mouldComparison"));
  mould->setPickMode(ddfcam::gui::MouldPanel::PickMode::SectionStart);
  QVERIFY2(statusText().contains("Section"), qPrintable(statusText()));
  pressEscape();
  QCOMPARE(mould->pickMode(), ddfcam::gui::MouldPanel::PickMode::None);
  QVERIFY2(statusText().startsWith("Navigate:"), qPrintable(statusText()));
}

void InteractionModeTest::theWheelOverABoxScrollsThePanel() {
  // A panel as the workbench docks one: a scroll area over taller content with a combo box. The
  // wheel over the box, which the pointer only passes over, scrolls the panel and leaves the
  // box's value; clicked into (focused), the box takes the wheel as usual. (The workbench's
  // wheel guard filters the whole application.)
  QScrollArea area;
  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  auto* box = new QComboBox;
  box->addItems({"off (camera)", "brush", "eraser"});
  layout->addWidget(box);
  layout->addSpacing(2000);
  area.setWidget(content);
  area.setWidgetResizable(true);
  area.resize(300, 200);
  area.show();
  area.activateWindow();
  QVERIFY(QTest::qWaitForWindowActive(&area));
  QScrollBar* bar = area.verticalScrollBar();
  QTRY_VERIFY(bar->maximum() > 0);
  const auto wheelDown = [box] {
    const QPointF at(box->width() / 2.0, box->height() / 2.0);
    QWheelEvent wheel(at, box->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(box, &wheel);
  };
  area.setFocus();
  wheelDown();
  QCOMPARE(box->currentIndex(), 0);
  QVERIFY(bar->value() > 0);
  box->setFocus();
  QTRY_VERIFY(box->hasFocus());
  wheelDown();
  QCOMPARE(box->currentIndex(), 1);
}

DDFCAM_GUI_TEST_MAIN(InteractionModeTest)
#include "interaction_mode_test.moc"
