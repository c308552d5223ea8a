// SPDX-License-Identifier: MIT
// Document undo budget: dropping the oldest steps, keeping the saved state reachable, rebuilds.
#include "gui_test_registry.h"
#include "document_fixture.h"

#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/planning/model/project.h>

#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <memory>
#include <vector>

using ddfcam::gui::AddFieldCommand;
using ddfcam::gui::Document;
using ddfcam::gui::DocumentParams;
using ddfcam::gui::SetHeightsCommand;
using ddfcam::test::constantField;
using ddfcam::test::planeProject;
using ddfcam::test::withFaces;
namespace planning = ddfcam::planning;

class DocumentBudgetTest : public QObject {
  Q_OBJECT

 private slots:
  void budgetDropsOldestSteps();
  void budgetKeepsReachableSavedState();
  void budgetSmallerThanOneStep();
  void budgetRebuildDoesNotRedoAgain();
};

void DocumentBudgetTest::budgetDropsOldestSteps() {
  constexpr int kSteps = 12;
  constexpr int kKept = 5;
  planning::Project start = planeProject(10, 9);  // 200 faces
  const std::size_t ppf = start.part->pointsPerFace();
  // Every step changes its own 10 faces, so every step holds the same memory.
  auto stepHeights = [&](const std::vector<float>& base, int step) {
    return withFaces(base, ppf, 10 * step, 10, -0.01f * static_cast<float>(step + 1));
  };
  std::size_t stepBytes = 0;
  {
    Document probe;
    probe.reset(start);
    stepBytes =
        SetHeightsCommand(probe, "s", stepHeights(start.part->allHeights(), 0)).memoryBytes();
  }
  QVERIFY(stepBytes > 2 * 10 * ppf * sizeof(float));  // both versions of the 10 faces
  DocumentParams params;
  params.undoBudgetBytes = kKept * stepBytes + stepBytes / 2;
  Document document(params);
  document.reset(start);

  std::vector<std::vector<float>> states{start.part->allHeights()};
  for (int step = 0; step < kSteps; ++step) {
    const std::uint64_t revision = document.revision();
    states.push_back(stepHeights(states.back(), step));
    document.push(std::make_unique<SetHeightsCommand>(document, "step", states.back()));
    QCOMPARE(document.revision(), revision + 1);
    QVERIFY(document.undoMemoryBytes() <= params.undoBudgetBytes);
    QCOMPARE(document.undoStack()->count(), std::min(step + 1, kKept));
    QVERIFY(document.project().part->allHeights() == states.back());
  }
  // Undo walks back through exactly the states that remain reachable, newest first.
  for (int i = 1; i <= kKept; ++i) {
    QVERIFY(document.undoStack()->canUndo());
    document.undoStack()->undo();
    QVERIFY(document.project().part->allHeights() == states[kSteps - i]);
  }
  QVERIFY(!document.undoStack()->canUndo());
  QVERIFY(document.project().part->allHeights() == states[kSteps - kKept]);
  QVERIFY(document.isModified());  // the opened state was dropped
  for (int i = kKept - 1; i >= 0; --i) document.undoStack()->redo();
  QVERIFY(document.project().part->allHeights() == states[kSteps]);
}

void DocumentBudgetTest::budgetKeepsReachableSavedState() {
  planning::Project start = planeProject(10, 9);
  const std::size_t ppf = start.part->pointsPerFace();
  std::size_t stepBytes = 0;
  {
    Document probe;
    probe.reset(start);
    stepBytes =
        SetHeightsCommand(probe, "s", withFaces(start.part->allHeights(), ppf, 0, 10, -0.5f))
            .memoryBytes();
  }
  DocumentParams params;
  params.undoBudgetBytes = 3 * stepBytes + stepBytes / 2;  // three steps fit
  Document document(params);
  document.reset(start);
  std::vector<std::vector<float>> states{start.part->allHeights()};
  auto step = [&](int i) {
    states.push_back(withFaces(states.back(), ppf, 10 * i, 10, -0.5f));
    document.push(std::make_unique<SetHeightsCommand>(document, "step", states.back()));
  };
  for (int i = 0; i < 4; ++i) step(i);
  document.markSaved("projects/s.ddfproj");  // saved at state 4
  for (int i = 4; i < 6; ++i) step(i);       // history holds states 3..6
  QVERIFY(document.isModified());
  document.undoStack()->undo();
  document.undoStack()->undo();
  QVERIFY(document.project().part->allHeights() == states[4]);
  QVERIFY(!document.isModified());  // the saved state survived the trims
  document.undoStack()->undo();
  QVERIFY(document.isModified());
  document.undoStack()->redo();
  QVERIFY(!document.isModified());

  // Two more steps drop state 4 (the saved one) from the history.
  document.undoStack()->redo();
  document.undoStack()->redo();
  step(6);
  step(7);  // history holds states 5..8
  while (document.undoStack()->canUndo()) {
    document.undoStack()->undo();
    QVERIFY(document.isModified());
  }
  QVERIFY(document.project().part->allHeights() == states[5]);
}

void DocumentBudgetTest::budgetSmallerThanOneStep() {
  DocumentParams params;
  params.undoBudgetBytes = 16;
  Document document(params);
  document.reset(planeProject());
  QSignalSpy modified(&document, &Document::modifiedChanged);
  const auto& part = *document.project().part;
  const auto after = withFaces(part.allHeights(), part.pointsPerFace(), 0, 3, -0.75f);
  document.push(std::make_unique<SetHeightsCommand>(document, "cut", after));
  QVERIFY(document.project().part->allHeights() == after);
  QCOMPARE(document.undoStack()->count(), 0);
  QCOMPARE(document.undoMemoryBytes(), std::size_t{0});
  QVERIFY(document.isModified());  // nothing to undo, but the change is not saved
  QCOMPARE(modified.count(), 1);
}

void DocumentBudgetTest::budgetRebuildDoesNotRedoAgain() {
  // Appending fields hold almost nothing while applied, replacing ones hold the old field. A
  // rebuild that redid a kept command would append a second (moved-from) field or swap back.
  // Fields of 36 kB make the commands' own few hundred bytes negligible against the budget.
  planning::Project start = planeProject(10, 9);
  start.fields.push_back(constantField(start, "f", 1.0f));
  const std::size_t fieldBytes = start.part->allHeights().size() * sizeof(float);
  DocumentParams params;
  params.undoBudgetBytes = 2 * fieldBytes + fieldBytes / 2;  // two replacements fit, not three
  Document document(params);
  document.reset(start);
  auto field = [&](const std::string& name, float value) {
    document.push(std::make_unique<AddFieldCommand>(
        document, constantField(document.project(), name, value)));
  };
  const auto& fields = document.project().fields;
  field("f", 10.0f);
  field("g0", 0.0f);
  field("g1", 0.0f);
  field("f", 11.0f);
  QCOMPARE(document.undoStack()->count(), 4);
  field("f", 12.0f);  // over budget: the first replacement goes, the rest are pushed again
  QCOMPARE(document.undoStack()->count(), 4);
  QVERIFY(document.undoMemoryBytes() <= params.undoBudgetBytes);
  QCOMPARE(fields.size(), std::size_t{3});
  QCOMPARE(fields[0].values.front(), 12.0f);
  QCOMPARE(QString::fromStdString(fields[2].name), QString("g1"));

  document.undoStack()->undo();
  QCOMPARE(fields[0].values.front(), 11.0f);
  document.undoStack()->undo();
  QCOMPARE(fields[0].values.front(), 10.0f);
  document.undoStack()->undo();
  QCOMPARE(fields.size(), std::size_t{2});
  document.undoStack()->undo();
  QCOMPARE(fields.size(), std::size_t{1});
  QCOMPARE(fields[0].values.front(), 10.0f);
  QVERIFY(!document.undoStack()->canUndo());
  for (int i = 0; i < 4; ++i) document.undoStack()->redo();
  QCOMPARE(fields.size(), std::size_t{3});
  QCOMPARE(fields[0].values.front(), 12.0f);
}

DDFCAM_GUI_TEST_MAIN(DocumentBudgetTest)
#include "document_budget_test.moc"
