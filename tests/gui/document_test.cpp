// SPDX-License-Identifier: MIT
// Document and its commands: exact undo/redo round trips, refusals and the modified flag.
#include "gui_test_registry.h"
#include "document_fixture.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/planning/model/project.h>

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
using ddfcam::gui::RemoveFieldCommand;
using ddfcam::gui::SetHeightsCommand;
using ddfcam::test::constantField;
using ddfcam::test::planeProject;
using ddfcam::test::withFaces;
namespace planning = ddfcam::planning;

namespace {

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
};

void DocumentTest::resetValidatesFirst() {
  Document document;
  document.reset(planeProject(), "projects/plane.ddfproj");
  const planning::Project before = document.project();
  QSignalSpy changed(&document, &Document::changed);
  QSignalSpy path(&document, &Document::filePathChanged);

  planning::Project bad;
  bad.fields.push_back({"orphan", "", false, {1.0f}, {}});  // a field without a part
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
    planning::Tool ball{.name = "ball R3",
                        .kind = planning::ToolKind::Sphere,
                        .radiusMm = 3.0,
                        .widthMm = 0.0,
                        .segments = 24};
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
  planning::ScalarField shortField{"s", "", false, {1.0f}, {}};
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, AddFieldCommand(document, shortField));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, RemoveFieldCommand(document, 1));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, RemoveFieldCommand(document, -1));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, AddPathCommand(document, linePath("p", 1, 4)));
  planning::ToolPath unordered = linePath("p", 0, 4);
  unordered.passStarts = {0, 3, 2};
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, AddPathCommand(document, unordered));
  planning::Tool flat{.name = "flat",
                      .kind = planning::ToolKind::CylinderRoll,
                      .radiusMm = -1.0,
                      .widthMm = 10.0,
                      .segments = 50};
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

DDFCAM_GUI_TEST_MAIN(DocumentTest)
#include "document_test.moc"
