// SPDX-License-Identifier: MIT
// ddfcam gui: MouldToolsPanel: the warps and demos of sec. 9 (cube/sphere morph, engraved
// plate scaled and bent) and the export of the shown surface.
#include <ddfcam/gui/panels/mould_tools_panel.h>

#include "mould_tools_widgets.h"

#include <ddfcam/ddf/ddf_warp.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/mould_view.h>
#include <ddfcam/io/mesh/mesh_io.h>

#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <memory>

namespace ddfcam::gui {
namespace {

constexpr int kSliderSteps = 100;

}  // namespace

QGroupBox* MouldToolsPanel::buildWarps() {
  auto* group = new QGroupBox(tr("Warps and demos"), this);
  group->setObjectName("warpsGroup");
  auto* box = new QVBoxLayout(group);
  auto* cube = new QPushButton(tr("Cube/sphere morph demo"), group);
  cube->setObjectName("cubeSphereButton");
  morphSlider_ = new QSlider(Qt::Horizontal, group);
  morphSlider_->setObjectName("cubeSphereSlider");
  morphSlider_->setRange(0, kSliderSteps);
  morphSlider_->setEnabled(false);
  auto* plate = new QPushButton(tr("Engraved plate demo"), group);
  plate->setObjectName("engravedPlateButton");
  scaleFactor_ = mould_tools::decimalSpin(group, "scaleFactorSpin", -10.0, 10.0, 3.0);
  cylinderRadius_ =
      mould_tools::decimalSpin(group, "cylinderRadiusSpin", -10000.0, 10000.0, 80.0, " mm");
  auto* scale = new QPushButton(tr("Scale vectors"), group);
  scale->setObjectName("scaleVectorsButton");
  auto* bend = new QPushButton(tr("Bend onto cylinder"), group);
  bend->setObjectName("bendCylinderButton");
  auto* exportShown = new QPushButton(tr("Export shown surface..."), group);
  exportShown->setObjectName("exportShownButton");
  auto* form = new QFormLayout;
  form->addRow(cube);
  form->addRow(tr("t (cube -> sphere)"), morphSlider_);
  form->addRow(plate);
  form->addRow(scale, scaleFactor_);
  form->addRow(bend, cylinderRadius_);
  box->addLayout(form);
  box->addWidget(exportShown);
  connect(cube, &QPushButton::clicked, this, [this] { showCubeSphereDemo(); });
  connect(morphSlider_, &QSlider::valueChanged, this, [this] { showMorph(); });
  connect(plate, &QPushButton::clicked, this, [this] { showEngravedPlate(); });
  connect(scale, &QPushButton::clicked, this, [this] { scalePlateVectors(scaleFactor_->value()); });
  connect(bend, &QPushButton::clicked, this,
          [this] { bendPlateOntoCylinder(cylinderRadius_->value()); });
  connect(exportShown, &QPushButton::clicked, this, [this] {
    const QString path =
        askSavePath(tr("Export shown surface"), tr("STL (*.stl);;OBJ (*.obj);;PLY (*.ply)"));
    if (!path.isEmpty()) exportShownSurface(path);
  });
  return group;
}

// Demos replace the mould in the primary view; a blended surface is an intermediate formed
// shape and goes where the formed surface is shown, next to the coloured mould.
void MouldToolsPanel::showSurface(ddf::TriangleMesh mesh, bool secondary, bool fitCamera) {
  shown_ = std::move(mesh);
  MouldView* view = workbench().mouldView;
  if (view == nullptr) return;
  if (secondary) {
    view->showSecondary(shown_);
  } else {
    // A demo is no formed part: the formed side would show a stale surface next to it.
    view->showSecondary({});
    view->showPrimaryPlain(shown_);
  }
  if (fitCamera) view->fitCameras();
}

bool MouldToolsPanel::showCubeSphereDemo() {
  bool started = false;
  runUserAction(workbench().reportError, tr("Cube/sphere morph demo"), [&] {
    const ddf::CubeSphereParams params = cubeSphereParams_;
    MouldToolsPanel* self = this;
    started = workbench().jobs.start(
        tr("Cube/sphere morph demo"), [params, self](const ProgressCallback& progress) {
          reportProgress(progress, 0.0);
          auto morph = std::make_shared<ddf::CubeSphereMorph>(ddf::cubeSphereMorph(params));
          reportProgress(progress, 1.0);
          return std::function<void()>([self, morph] {
            self->cubeSphere_ = std::move(*morph);
            self->morphSlider_->setEnabled(true);
            self->showMorph();
            if (self->workbench().mouldView) self->workbench().mouldView->fitCameras();
          });
        });
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return started;
}

void MouldToolsPanel::setMorphTime(double t) {
  const int value = static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSliderSteps));
  if (value == morphSlider_->value())
    showMorph();
  else
    morphSlider_->setValue(value);
}

void MouldToolsPanel::showMorph() {
  if (!cubeSphere_) return;
  runUserAction(workbench().reportError, tr("Cube/sphere morph"), [&] {
    const double t = static_cast<double>(morphSlider_->value()) / kSliderSteps;
    const std::vector<float> heights =
        ddf::morphHeights(cubeSphere_->cubeHeights, cubeSphere_->sphereHeights, t);
    const ddf::DisplacementField& layout = cubeSphere_->ddf;
    showSurface(ddf::morphMesh(layout, ddf::heightPositions(layout, heights)), false, false);
  });
}

bool MouldToolsPanel::showEngravedPlate() {
  return runUserAction(workbench().reportError, tr("Engraved plate demo"), [&] {
    plate_ = ddf::engravedPlate(plateParams_);
    showSurface(ddf::extractRasterMesh(*plate_).mesh, false, true);
  });
}

bool MouldToolsPanel::scalePlateVectors(double factor) {
  return runUserAction(workbench().reportError, tr("Scale vectors"), [&] {
    if (!plate_) plate_ = ddf::engravedPlate(plateParams_);
    ddf::DisplacementField warped = *plate_;
    ddf::scaleVectors(warped, factor);
    showSurface(ddf::extractRasterMesh(warped).mesh, false, true);
    plate_ = std::move(warped);
  });
}

bool MouldToolsPanel::bendPlateOntoCylinder(double radiusMm) {
  return runUserAction(workbench().reportError, tr("Bend onto cylinder"), [&] {
    if (!plate_) plate_ = ddf::engravedPlate(plateParams_);
    ddf::DisplacementField warped = *plate_;
    ddf::CylinderWarpParams params;
    params.radiusMm = radiusMm;
    ddf::mapSupportOntoCylinder(warped, params);
    showSurface(ddf::extractRasterMesh(warped).mesh, false, true);
    plate_ = std::move(warped);
  });
}

bool MouldToolsPanel::exportShownSurface(const QString& path) {
  return runUserAction(workbench().reportError, tr("Export shown surface"), [&] {
    if (shown_.triangles.empty())
      throw InvalidInput("nothing to export: show a blended surface or a demo first");
    io::writeMesh(shown_, path.toStdString());
  });
}

}  // namespace ddfcam::gui
