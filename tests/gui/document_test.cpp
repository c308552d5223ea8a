// SPDX-License-Identifier: MIT
// Document and its commands: exact undo/redo round trips, the modified flag, the undo budget.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/planning/project.h>

#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

using ddfcam::gui::AddFieldCommand;
using ddfcam::gui::AddPathCommand;
using ddfcam::gui::Change;
using ddfcam::gui::Changes;
using ddfcam::gui::Document;
using ddfcam::gui::DocumentCommand;
using ddfcam::gui::DocumentParams;
using ddfcam::gui::RemoveFieldCommand;
using ddfcam::gui::SetHeightsCommand;
namespace planning = ddfcam::planning;

namespace {

/// A plane patch of @p cells x @p cells cells: every height is 0.25 (z = 0.25, vectors of 1).
planning::Project planeProject(int cells = 4, int m = 5) {
  ddfcam::ddf::PlanePatchParams params;
  params.cellsX = cells;
  params.cellsY = cells;
  params.m = m;
  planning::Project project;
  project.partName = "plane";
  project.part = ddfcam::ddf::planePatch(params).ddf;
  return project;
}

planning::ScalarField constantField(const planning::Project& project, const std::string& name,
                                    float value) {
  planning::ScalarField field;
  field.name = name;
  field.unit = "mm";
  field.values.assign(project.part->allHeights().size(), value);
  return field;
}

planning::ToolPath linePath(const std::string& name, int tool, int poses) {
  planning::ToolPath path;
  path.name = name;
  path.tool = tool;
  for (int i = 0; i < poses; ++i) {
    planning::PathPose pose;
    pose.pose.translate(Eigen::Vector3d(i, 0.5 * i, 2.0));
    pose.contact = Eigen::Vector3d(i, 0.5 * i, 0.25);
    path.poses.push_back(pose);
  }
  path.passStarts = {0, poses / 2};
  return path;
}

/// Heights with the faces in [firstFace, firstFace + faces) set to @p value, others as @p base.
std::vector<float> withFaces(std::vector<float> base, std::size_t pointsPerFace, int firstFace,
                             int faces, float value) {
  for (std::size_t i = firstFace * pointsPerFace; i < (firstFace + faces) * pointsPerFace; ++i)
    base[i] = value;
  return base;
}

/// A command whose first apply fails after touching nothing (an edit that refuses itself).
class RefusingCommand : public DocumentCommand {
 public:
  explicit RefusingCommand(Document& document) : DocumentCommand(document, "refuse") {}

 protected:
  Changes apply(planning::Project&) override {
    throw ddfcam::InvalidInput("refusing command: refused");
  }
  Changes revert(planning::Project&) override { return Change::Fields; }
};

}  // namespace

class DocumentTest : public QObject {
  Q_OBJECT

 private slots:
  void resetValidatesFirst();
  void everyCommandRoundTrips_data();
  void everyCommandRoundTrips();
  void commandsRefuseBadInput();
  void failingCommandLeavesEverythingUnchanged();
  void modifiedFlagFollowsEditUndoSaveRedo();
  void markModifiedSurvivesUndo();
  void budgetDropsOldestSteps();
  void budgetKeepsReachableSavedState();
  void budgetSmallerThanOneStep();
  void budgetRebuildDoesNotRedoAgain();
};

void DocumentTest::resetValidatesFirst() {
  Document document;
  document.reset(planeProject(), "projects/plane.ddfproj");
  const planning::Project before = document.project();
  QSignalSpy changed(&document, &Document::changed);
  QSignalSpy path(&document, &Document::filePathChanged);

  planning::Project bad;
  bad.fields.push_back({"orphan", "", false, {1.0f}});  // a field without a part
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, document.reset(bad, "projects/other.ddfproj"));
  QVERIFY(planning::projectsEqual(document.project(), before));
  QCOMPARE(document.filePath(), QString("projects/plane.ddfproj"));
  QCOMPARE(changed.count(), 0);
  QCOMPARE(path.count(), 0);
}

using Edit = std::function<std::unique_ptr<QUndoCommand>(Document&)>;
Q_DECLARE_METATYPE(Edit)

void DocumentTest::everyCommandRoundTrips_data() {
  QTest::addColumn<Edit>("edit");
  QTest::addColumn<int>("fieldsAfter");
  QTest::newRow("set heights") << Edit([](Document& d) {
    const auto& part = *d.project().part;
    auto after = withFaces(part.allHeights(), part.pointsPerFace(), 3, 4, -0.5f);
    return std::make_unique<SetHeightsCommand>(d, "cut", after);
  }) << 2;
  QTest::newRow("set heights with state") << Edit([](Document& d) {
    const auto& part = *d.project().part;
    auto after = withFaces(part.allHeights(), part.pointsPerFace(), 0, 1, std::nanf(""));
    planning::SimulationState state{"after pass", after};
    return std::make_unique<SetHeightsCommand>(d, "cut", after, state);
  }) << 2;
  QTest::newRow("add field") << Edit([](Document& d) {
    return std::make_unique<AddFieldCommand>(d, constantField(d.project(), "new", 7.0f));
  }) << 3;
  QTest::newRow("replace field") << Edit([](Document& d) {
    return std::make_unique<AddFieldCommand>(d, constantField(d.project(), "a", -3.0f));
  }) << 2;
  QTest::newRow("remove first field")
      << Edit([](Document& d) { return std::make_unique<RemoveFieldCommand>(d, 0); }) << 1;
  QTest::newRow("remove last field")
      << Edit([](Document& d) { return std::make_unique<RemoveFieldCommand>(d, 1); }) << 1;
  QTest::newRow("add path") << Edit([](Document& d) {
    return std::make_unique<AddPathCommand>(d, linePath("p", 0, 6));
  }) << 2;
  QTest::newRow("add path with tool") << Edit([](Document& d) {
    planning::Tool ball{"ball R3", planning::ToolKind::Sphere, 3.0, 0.0, 24};
    return std::make_unique<AddPathCommand>(d, linePath("q", 99, 4), ball);
  }) << 2;
}

void DocumentTest::everyCommandRoundTrips() {
  QFETCH(Edit, edit);
  QFETCH(int, fieldsAfter);
  planning::Project start = planeProject();
  start.fields.push_back(constantField(start, "a", 1.0f));
  start.fields.push_back(constantField(start, "b", 2.0f));
  start.tools.push_back(planning::Tool{});
  start.states.push_back({"stock", start.part->allHeights()});
  Document document;
  document.reset(start);
  const planning::Project before = document.project();

  document.push(edit(document));
  const planning::Project after = document.project();
  QVERIFY(!planning::projectsEqual(after, before));
  QCOMPARE(static_cast<int>(after.fields.size()), fieldsAfter);
  for (int round = 0; round < 2; ++round) {
    document.undoStack()->undo();
    QVERIFY(planning::projectsEqual(document.project(), before));
    document.undoStack()->redo();
    QVERIFY(planning::projectsEqual(document.project(), after));
  }
}

void DocumentTest::commandsRefuseBadInput() {
  Document empty;
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, SetHeightsCommand(empty, "x", {1.0f}));
  Document document;
  planning::Project start = planeProject();
  start.fields.push_back(constantField(start, "a", 1.0f));
  start.tools.push_back(planning::Tool{});
  document.reset(start);
  const std::size_t values = start.part->allHeights().size();

  std::vector<float> shortHeights(values - 1, 0.0f);
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, SetHeightsCommand(document, "x", shortHeights));
  planning::SimulationState badState{"s", {1.0f, 2.0f}};
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           SetHeightsCommand(document, "x", start.part->allHeights(), badState));
  planning::ScalarField shortField{"s", "", false, {1.0f}};
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, AddFieldCommand(document, shortField));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, RemoveFieldCommand(document, 1));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, RemoveFieldCommand(document, -1));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, AddPathCommand(document, linePath("p", 1, 4)));
  planning::ToolPath unordered = linePath("p", 0, 4);
  unordered.passStarts = {0, 3, 2};
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, AddPathCommand(document, unordered));
  planning::Tool flat{"flat", planning::ToolKind::CylinderRoll, -1.0, 10.0, 50};
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           AddPathCommand(document, linePath("p", 0, 4), flat));
  QVERIFY(planning::projectsEqual(document.project(), start));
  QCOMPARE(document.undoStack()->count(), 0);
}

void DocumentTest::failingCommandLeavesEverythingUnchanged() {
  Document document;
  document.reset(planeProject());
  const auto& part = *document.project().part;
  document.push(std::make_unique<SetHeightsCommand>(
      document, "cut", withFaces(part.allHeights(), part.pointsPerFace(), 0, 2, 0.0f)));
  document.undoStack()->undo();  // leave a redoable step, which a real push would discard
  const planning::Project before = document.project();
  const std::uint64_t revision = document.revision();
  QSignalSpy changed(&document, &Document::changed);
  QSignalSpy modified(&document, &Document::modifiedChanged);

  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           document.push(std::make_unique<RefusingCommand>(document)));
  QVERIFY(planning::projectsEqual(document.project(), before));
  QCOMPARE(document.undoStack()->count(), 1);
  QCOMPARE(document.undoStack()->index(), 0);
  QCOMPARE(document.revision(), revision);
  QCOMPARE(changed.count(), 0);
  QCOMPARE(modified.count(), 0);
  QVERIFY(!document.isModified());
}

void DocumentTest::modifiedFlagFollowsEditUndoSaveRedo() {
  Document document;
  QSignalSpy modified(&document, &Document::modifiedChanged);
  QSignalSpy path(&document, &Document::filePathChanged);
  document.reset(planeProject());
  QVERIFY(!document.isModified());
  QCOMPARE(modified.count(), 0);

  auto addField = [&](const char* name) {
    document.push(
        std::make_unique<AddFieldCommand>(document, constantField(document.project(), name, 1)));
  };
  addField("a");
  QVERIFY(document.isModified());
  QCOMPARE(modified.count(), 1);
  QCOMPARE(modified.last().at(0).toBool(), true);
  addField("b");
  QCOMPARE(modified.count(), 1);  // still modified: no signal
  document.undoStack()->undo();
  document.undoStack()->undo();
  QVERIFY(!document.isModified());  // back at the opened state
  QCOMPARE(modified.count(), 2);
  document.undoStack()->redo();
  QVERIFY(document.isModified());

  document.markSaved("projects/saved.ddfproj");
  QVERIFY(!document.isModified());
  QCOMPARE(document.filePath(), QString("projects/saved.ddfproj"));
  QCOMPARE(path.count(), 1);
  document.undoStack()->undo();
  QVERIFY(document.isModified());
  document.undoStack()->redo();
  QVERIFY(!document.isModified());  // exactly the saved state again
  document.undoStack()->redo();     // field "b"
  QVERIFY(document.isModified());
  QCOMPARE(modified.count(), 7);

  document.reset(planeProject());
  QVERIFY(!document.isModified());
  QCOMPARE(document.filePath(), QString());
  QCOMPARE(path.count(), 2);
  QCOMPARE(document.undoStack()->count(), 0);
}

void DocumentTest::markModifiedSurvivesUndo() {
  Document document;
  document.reset(planeProject(), "projects/recovered.ddfproj");
  document.markModified();  // e.g. a recovered project: differs from its file
  QVERIFY(document.isModified());
  document.push(
      std::make_unique<AddFieldCommand>(document, constantField(document.project(), "f", 1)));
  document.undoStack()->undo();
  QVERIFY(document.isModified());  // still the recovered state, not the file's
  document.markSaved("projects/recovered.ddfproj");
  QVERIFY(!document.isModified());
}

void DocumentTest::budgetDropsOldestSteps() {
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

void DocumentTest::budgetKeepsReachableSavedState() {
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

void DocumentTest::budgetSmallerThanOneStep() {
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

void DocumentTest::budgetRebuildDoesNotRedoAgain() {
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

QTEST_MAIN(DocumentTest)
#include "document_test.moc"
