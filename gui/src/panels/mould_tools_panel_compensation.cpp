// SPDX-License-Identifier: MIT
// ddfcam gui: MouldToolsPanel: the compensation actions (start, calibrate, import, step,
// export).
#include <ddfcam/gui/panels/mould_tools_panel.h>

#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/mould_commands.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/mesh_units.h>
#include <ddfcam/planning/model/project.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>

#include <algorithm>
#include <memory>
#include <utility>

#include "unit_combo.h"

namespace ddfcam::gui {
namespace {

using planning::CompensationHistory;

// The target DDF: the comparison's mould DDF (its vectors reach the formed part) with the
// target on the support itself, or the mould mesh converted when nothing was compared yet.
ddf::DisplacementField targetDdf(const planning::MouldStudy& study) {
  if (study.result && !study.result->sequence.stages.empty()) {
    ddf::DisplacementField target = study.result->sequence.stages.front().ddf;
    std::fill(target.allHeights().begin(), target.allHeights().end(), 0.0f);
    return target;
  }
  if (study.mould.mesh.triangles.empty())
    throw InvalidInput("the mould study has no mould surface");
  ddf::ConversionParams params;
  params.resolution = study.comparison.resolution;
  params.chooseLengths = false;
  return ddf::convertMeshToDdf(study.mould.mesh, params).ddf;
}

QString modelSource(const planning::LinearSpringbackModel& model) {
  if (!model.axisAlpha) return QStringLiteral("linear model alpha=%1").arg(model.alpha);
  return QStringLiteral("linear model alpha=(%1, %2, %3)")
      .arg((*model.axisAlpha)[0])
      .arg((*model.axisAlpha)[1])
      .arg((*model.axisAlpha)[2]);
}

}  // namespace

bool MouldToolsPanel::startCompensation() {
  return runUserAction(workbench().reportError, tr("Start compensation"), [&] {
    const planning::Project& p = workbench().document.project();
    if (!p.mould) throw InvalidInput("the project has no mould study; load a mould surface first");
    CompensationHistory history = planning::startCompensation(targetDdf(*p.mould));
    workbench().document.push(std::make_unique<SetCompensationCommand>(
        workbench().document, tr("Start compensation"), std::move(history)));
  });
}

bool MouldToolsPanel::calibrateLinearModel() {
  bool started = false;
  runUserAction(workbench().reportError, tr("Calibrate springback model"), [&] {
    const planning::Project& p = workbench().document.project();
    if (!history()) throw InvalidInput("start the compensation first");
    if (!p.mould->formed) throw InvalidInput("the mould study has no formed surface");
    auto target = std::make_shared<const ddf::DisplacementField>(history()->target);
    auto formed = std::make_shared<const ddf::TriangleMesh>(p.mould->formed->mesh);
    const double alpha = alpha_->value();
    MouldToolsPanel* self = this;
    started = workbench().jobs.start(
        tr("Calibrate springback model"), [=](const ProgressCallback& progress) {
          ddf::DeformationSequenceParams params;
          params.progress = progress;
          const std::vector<float> first =
              planning::formedHeightsFromMesh(*target, *formed, params);
          planning::LinearSpringbackModel model =
              planning::calibrateSpringback(*target, first, alpha);
          return std::function<void()>([self, model = std::move(model)]() mutable {
            self->setLinearModel(std::move(model));
          });
        });
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return started;
}

bool MouldToolsPanel::importFormedSurface(const QString& path) {
  bool started = false;
  runUserAction(workbench().reportError, tr("Import formed surface"), [&] {
    if (!history()) throw InvalidInput("start the compensation first");
    auto current = std::make_shared<const CompensationHistory>(*history());
    const std::string file = path.toStdString();
    const LengthUnit unit = unitOf(importUnit_);
    const std::string name = QFileInfo(path).fileName().toStdString();
    Document* document = &workbench().document;
    const QString text = tr("Import formed surface %1").arg(QFileInfo(path).fileName());
    started = workbench().jobs.start(text, [=](const ProgressCallback& progress) {
      const ddf::TriangleMesh formed = io::readMeshInUnit(file, unit);
      ddf::DeformationSequenceParams params;
      params.progress = progress;
      auto next = std::make_shared<CompensationHistory>(*current);
      planning::recordFormedResponse(
          *next, planning::formedHeightsFromMesh(next->target, formed, params), name);
      return std::function<void()>([document, text, next] {
        document->push(std::make_unique<SetCompensationCommand>(*document, text, *next));
      });
    });
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  if (started) setResponseSource(ResponseSource::ImportedSurface);
  return started;
}

bool MouldToolsPanel::evaluateLastMould() {
  return startHistoryJob(tr("Evaluate last mould"), false);
}

bool MouldToolsPanel::step() {
  return startHistoryJob(tr("Compensation step"), true);
}

// Records the response of the last mould when it has none (from the linear model; an imported
// response must already be there), then optionally appends the next mould.
bool MouldToolsPanel::startHistoryJob(const QString& title, bool appendStep) {
  bool started = false;
  runUserAction(workbench().reportError, title, [&] {
    if (!history()) throw InvalidInput("start the compensation first");
    const bool known = !history()->iterations.back().formedHeights.empty();
    const bool useModel = responseSource() == ResponseSource::LinearModel;
    if (!known && !useModel)
      throw InvalidInput(
          "import the surface formed in the last mould first, or choose the "
          "linear model");
    if (!known && !model_) throw InvalidInput("calibrate the linear springback model first");
    if (known && !appendStep) throw InvalidInput("the last mould already has its response");
    std::optional<planning::LinearSpringbackModel> model;
    if (!known) model = modelWithPanelAlphas();
    auto current = std::make_shared<const CompensationHistory>(*history());
    const double lambda = lambda_->value();
    Document* document = &workbench().document;
    started = workbench().jobs.start(title, [=](const ProgressCallback& progress) {
      auto next = std::make_shared<CompensationHistory>(*current);
      if (model) {
        std::vector<float> formed =
            planning::linearSpringback(*model, next->target, next->iterations.back().mouldHeights);
        planning::recordFormedResponse(*next, std::move(formed), modelSource(*model).toStdString());
      }
      reportProgress(progress, 0.5);
      if (appendStep) planning::compensationStep(*next, lambda);
      return std::function<void()>([document, title, next] {
        document->push(std::make_unique<SetCompensationCommand>(*document, title, *next));
      });
    });
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return started;
}

bool MouldToolsPanel::exportMould(int iteration, const QString& path) {
  return runUserAction(workbench().reportError, tr("Export mould"), [&] {
    if (!history()) throw InvalidInput("start the compensation first");
    io::writeMesh(planning::mouldMesh(*history(), iteration), path.toStdString());
  });
}

}  // namespace ddfcam::gui
