// SPDX-License-Identifier: MIT
// Stale fields under Xvfb: after the heights change, every field computed from the earlier
// heights is marked where a person looks (the field list, the scalar bar, the error-map
// statistics), and Recompute gives what a full computation of the current heights gives.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/gui/panels/error_map_panel.h>
#include <ddfcam/gui/panels/fields_panel.h>
#include <ddfcam/gui/panels/simulation_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/analysis/segmentation.h>
#include <ddfcam/planning/model/builtin_fields.h>

#include <QAction>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QtTest/QtTest>

#include <algorithm>
#include <cstring>

using ddfcam::gui::FieldKind;
using ddfcam::planning::ScalarField;

namespace {

constexpr FieldKind kAllKinds[] = {
    FieldKind::Height,        FieldKind::HeightMm,          FieldKind::MaterialRemoved,
    FieldKind::Deviation,     FieldKind::KMax,              FieldKind::KMin,
    FieldKind::MeanCurvature, FieldKind::GaussianCurvature, FieldKind::CurvatureType,
    FieldKind::MaxToolRadius};

/// The field the planning library computes from the project's current heights, called
/// directly: the full recomputation a recomputed field must equal.
ScalarField fullComputation(const std::string& name, const ddfcam::planning::Project& p) {
  namespace planning = ddfcam::planning;
  const ddfcam::ddf::DisplacementField& part = *p.part;
  if (name == "height (h)") return planning::heightField(part);
  if (name == "height above support") return planning::heightMmField(part);
  if (name == "material removed")
    return planning::materialRemovedField(part, p.states.front().heights);
  if (name == "deviation from mesh") return planning::deviationField(part, *p.designMesh);
  const planning::CurvatureField curvature =
      planning::computeCurvature(part, planning::partCurvatureParams(p));
  using Q = planning::CurvatureQuantity;
  if (name == "k_max") return planning::curvatureScalarField(curvature, Q::KMax);
  if (name == "k_min") return planning::curvatureScalarField(curvature, Q::KMin);
  if (name == "mean curvature") return planning::curvatureScalarField(curvature, Q::Mean);
  if (name == "Gaussian curvature")
    return planning::curvatureScalarField(curvature, Q::Gaussian);
  if (name == "curvature type") return planning::curvatureTypeField(curvature);
  const auto box = ddfcam::ddf::extractSupportMesh(part).bounds();
  return planning::maxToolRadiusField(curvature, std::max((box[1] - box[0]).norm(), 1e-3));
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

class StaleFieldsTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(true)); }
  void everyFieldIsFlaggedAfterACutAndRecomputesToAFullComputation();

 private:
  template <typename T>
  T* child(const char* name) {
    return f_.window->findChild<T*>(name);
  }
  /// Texts of the field list's rows after the "(none)" row.
  QStringList fieldRows() {
    auto* list = child<QListWidget>("fieldList");
    QStringList rows;
    for (int r = 1; r < list->count(); ++r) rows << list->item(r)->text();
    return rows;
  }
};

void StaleFieldsTest::everyFieldIsFlaggedAfterACutAndRecomputesToAFullComputation() {
  auto* simulation = f_.window->findChild<ddfcam::gui::SimulationPanel*>();
  auto* fields = f_.window->findChild<ddfcam::gui::FieldsPanel*>();
  auto* errorMap = f_.window->findChild<ddfcam::gui::ErrorMapPanel*>();
  QVERIFY(simulation->simulatePath(0));
  waitOk();
  for (FieldKind kind : kAllKinds) {
    QVERIFY(fields->compute(kind));
    waitOk();
  }
  QVERIFY(errorMap->setDesiredSurface(0));
  QVERIFY(errorMap->computeErrorMap());
  waitOk();
  const std::size_t count = std::size(kAllKinds) + 1;
  QCOMPARE(project().fields.size(), count);
  for (const QString& row : fieldRows()) QVERIFY2(!row.contains("stale"), qPrintable(row));
  QVERIFY(!errorMap->isStale());
  const auto& scene = f_.window->partView().scene();
  QVERIFY(!QString::fromStdString(scene.scalarBarTitle()).contains("STALE"));

  // A cut of other heights: the stock state restored (an undoable edit of the heights).
  QVERIFY(simulation->restoreState(0));
  QApplication::processEvents();
  const QStringList rows = fieldRows();
  QCOMPARE(rows.size(), static_cast<int>(count));
  for (const QString& row : rows) QVERIFY2(row.contains("stale"), qPrintable(row));
  QVERIFY(errorMap->isStale());
  QVERIFY(child<QLabel>("errorStatisticsLabel")->text().startsWith("STALE"));
  QVERIFY2(QString::fromStdString(scene.scalarBarTitle()).contains("STALE"),
           scene.scalarBarTitle().c_str());
  QVERIFY(raisePanel("fields"));
  QTest::qWait(50);
  ddfcam::test::dumpFrame(f_.window->grab().toImage(), "stale_fields");

  // Recompute each built-in field from its row: equal, bit for bit, to a full computation.
  auto* list = child<QListWidget>("fieldList");
  auto* recompute = child<QPushButton>("recomputeFieldButton");
  for (int row = 1; row < static_cast<int>(count); ++row) {
    list->setCurrentRow(row);
    QVERIFY(recompute->isEnabled());
    recompute->click();
    waitOk();
    const ScalarField& field = project().fields[static_cast<std::size_t>(row - 1)];
    QVERIFY2(sameBits(field.values, fullComputation(field.name, project()).values),
             field.name.c_str());
    QVERIFY2(!fieldRows()[row - 1].contains("stale"), qPrintable(fieldRows()[row - 1]));
  }
  // The error map is not a Compute-menu field: it stays marked until the Error map panel
  // computes it again, and its Recompute button is off.
  list->setCurrentRow(static_cast<int>(count));
  QVERIFY(fieldRows().back().contains("stale"));
  QVERIFY(!recompute->isEnabled());
  QVERIFY(errorMap->computeErrorMap());
  waitOk();
  QVERIFY(!errorMap->isStale());
  QVERIFY(!fieldRows().back().contains("stale"));

  // Undo of the recomputations and of the restore brings back the first fields, fresh again.
  QAction* undo = f_.window->findChild<QAction*>("actionUndo");
  for (std::size_t i = 0; i < count + 1; ++i) undo->trigger();
  for (const QString& row : fieldRows()) QVERIFY2(!row.contains("stale"), qPrintable(row));
  QVERIFY(!errorMap->isStale());
}

DDFCAM_GUI_TEST_MAIN(StaleFieldsTest)
#include "stale_fields_test.moc"
