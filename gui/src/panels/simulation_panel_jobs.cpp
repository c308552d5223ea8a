// SPDX-License-Identifier: MIT
// ddfcam gui: the jobs of the Simulation panel: simulate a path (rigid or Preston), set up the
// workpiece (stock allowance or stock mesh), correct penetrations of a path.
#include <ddfcam/error.h>
#include <ddfcam/gui/composite_command.h>
#include <ddfcam/gui/console_dock.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/panels/simulation_options.h>
#include <ddfcam/gui/panels/simulation_panel.h>
#include <ddfcam/gui/path_commands.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/inspection/coverage.h>
#include <ddfcam/planning/model/simulation_states.h>
#include <ddfcam/planning/pipeline/simulation_stage.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/simulation_estimate.h>
#include <ddfcam/planning/simulation/workpiece.h>

#include <QElapsedTimer>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QStringList>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <utility>

namespace ddfcam::gui {

namespace {

/// "a, b, c" of at most @p limit pose numbers, then "...".
template <class Hit>
QString poseList(const std::vector<Hit>& hits, std::size_t limit = 20) {
  QStringList items;
  for (std::size_t i = 0; i < std::min(limit, hits.size()); ++i)
    items << QString::number(hits[i].pose);
  if (hits.size() > limit) items << "...";
  return items.join(", ");
}

QString grindingText(const planning::ToolPath& path, const planning::GrindingSimulationParams& p,
                     const planning::GrindingReport& r) {
  QStringList lines;
  lines << QObject::tr("Simulated '%1' (%2): removed %3 mm³ in %4 passes, %5 poses, %6 s")
               .arg(QString::fromStdString(path.name))
               .arg(p.mode == planning::SweepMode::Swept ? QObject::tr("swept volume")
                                                         : QObject::tr("discrete"))
               .arg(r.removedVolumeMm3, 0, 'f', 4)
               .arg(r.passes.size())
               .arg(r.posesCut)
               .arg(r.seconds, 0, 'f', 2);
  for (std::size_t i = 0; i < r.passes.size(); ++i)
    lines << QObject::tr("  pass %1: %2 mm³ (%3 poses)")
                 .arg(i + 1)
                 .arg(r.passes[i].removedVolumeMm3, 0, 'f', 4)
                 .arg(r.passes[i].poseCount);
  if (p.checkVConvexity)
    lines << QObject::tr("V-convexity violations: %1 poses (%2 points)%3")
                 .arg(r.vConvexity.size())
                 .arg(r.vConvexityStubbles)
                 .arg(r.vConvexity.empty() ? QString() : ": poses " + poseList(r.vConvexity));
  if (p.checkCollisions)
    lines << QObject::tr("Colliding poses: %1%2")
                 .arg(r.collisions.size())
                 .arg(r.collisions.empty() ? QString() : ": " + poseList(r.collisions));
  if (r.pointsClamped > 0)
    lines << QObject::tr(
                 "Warning: %1 heights were cut below the crust bottom and clamped to it: "
                 "the true cut is deeper there")
                 .arg(r.pointsClamped);
  return lines.join('\n');
}

/// The share of the part the tool came within reach of (planning::pathCoverage), with a
/// warning when it is tiny: a path that misses the part "succeeds" otherwise.
QString coverageText(const planning::Coverage& c) {
  QString text = QObject::tr("Coverage: the tool touched %1 % of the part (%2 of %3 mm²)")
                     .arg(c.percent(), 0, 'f', 2)
                     .arg(c.coveredAreaMm2, 0, 'f', 1)
                     .arg(c.totalAreaMm2, 0, 'f', 1);
  if (c.percent() < planning::kLowPathCoveragePercent)
    text += QObject::tr(
        "\nWarning: the path touches almost none of the part; check its frame, "
        "unit and placement");
  return text;
}

/// Maps [0, 1] of a sub-task onto [from, to] of @p progress.
ProgressCallback subProgress(const ProgressCallback& progress, double from, double to) {
  if (!progress) return {};
  return [progress, from, to](double x) { return progress(from + (to - from) * x); };
}

QString prestonText(const planning::ToolPath& path, const planning::PrestonReport& r,
                    double seconds) {
  const double deepest = r.maxDepthMm.empty() ? 0.0 : *std::ranges::max_element(r.maxDepthMm);
  return QObject::tr(
             "Preston removal along '%1': removed %2 mm³, deepest %3 mm per pose, "
             "%4 poses without contact, %5 s")
      .arg(QString::fromStdString(path.name))
      .arg(r.removedVolumeMm3, 0, 'f', 4)
      .arg(deepest, 0, 'g', 4)
      .arg(r.posesWithoutContact)
      .arg(seconds, 0, 'f', 2);
}

}  // namespace

bool SimulationPanel::confirmLongPath(const planning::ToolPath& path, const planning::Tool& tool) {
  if (static_cast<int>(path.poses.size()) <= longPathPoses_ || !workbench().confirmLongJob)
    return true;
  const planning::Project& p = workbench().document.project();
  const planning::SimulationEstimate e = planning::estimateSimulation(
      *p.part, planning::toolMeshes(tool), path, options_->grindingParams());
  const int seconds = static_cast<int>(std::ceil(e.seconds));
  const QString time = seconds >= 120 ? tr("%1 min").arg((seconds + 59) / 60)
                                      : tr("%1 s").arg(std::max(seconds, 1));
  const QString message =
      tr("Path '%1' has %2 poses. Simulating it will take about %3 on this machine (%4 ms per "
         "pose, timed on %5 of its poses). Simulate now?")
          .arg(QString::fromStdString(path.name))
          .arg(path.poses.size())
          .arg(time)
          .arg(1e3 * e.secondsPerPose, 0, 'f', 1)
          .arg(e.sampled);
  return workbench().confirmLongJob(tr("Simulate path"), message);
}

bool SimulationPanel::startJob(const QString& title, JobWork work) {
  if (!workbench().jobs.start(title, std::move(work)))
    throw InvalidInput("another job is running; wait for it or cancel it first");
  return true;
}

void SimulationPanel::report(const QString& text, QLabel* label) {
  label->setText(text);
  workbench().console.appendMessage(LogLevel::Info, text);
}

bool SimulationPanel::simulatePath(int index) {
  const planning::Project& p = workbench().document.project();
  bool started = false;
  runUserAction(workbench().reportError, tr("Simulate path"), [&] {
    if (!p.part) throw InvalidInput("there is no part to grind");
    if (index < 0 || index >= static_cast<int>(p.paths.size()))
      throw InvalidInput("select a tool path to simulate");
    const planning::ToolPath& path = p.paths[static_cast<std::size_t>(index)];
    if (path.tool < 0 || path.tool >= static_cast<int>(p.tools.size()))
      throw InvalidInput("path '" + path.name + "' refers to a missing tool");
    // The job grinds a copy: a cancelled or failed run leaves the document as it was.
    auto part = std::make_shared<ddf::DisplacementField>(*p.part);
    const planning::Tool tool = p.tools[static_cast<std::size_t>(path.tool)];
    if (!confirmLongPath(path, tool)) return;
    const bool preston = options_->removalModel() == RemovalModel::Preston;
    const planning::GrindingSimulationParams grinding = options_->grindingParams();
    const planning::PrestonParams prestonParams = options_->prestonParams();
    const QString title = tr("Simulate path '%1' (%2 poses)")
                              .arg(QString::fromStdString(path.name))
                              .arg(path.poses.size());
    started = startJob(title, [=, this](const ProgressCallback& whole) {
      planning::PathCoverageParams coverage;
      coverage.progress = subProgress(whole, 0.0, 0.2);
      const QString touched =
          coverageText(planning::pathCoverage(*part, tool, path, coverage).coverage);
      const ProgressCallback progress = subProgress(whole, 0.2, 1.0);
      QString text;
      if (preston) {
        QElapsedTimer clock;
        clock.start();
        planning::PrestonParams pp = prestonParams;
        pp.feedMmPerS = path.feedMmPerMin / 60.0;  // the feed exported programs are written with
        pp.progress = progress;
        planning::PrestonStageResult r = planning::prestonStage(std::move(*part), tool, path, pp);
        *part = std::move(r.workpiece);
        text = prestonText(path, r.report, clock.elapsed() / 1000.0);
      } else {
        const auto r =
            planning::simulateGrinding(*part, planning::toolMeshes(tool), path, grinding, progress);
        text = grindingText(path, grinding, r);
      }
      text += '\n' + touched;
      return std::function<void()>([this, part, path, title, text, preston] {
        const std::string name = planning::afterPathStateName(path.name, preston);
        workbench().document.push(std::make_unique<SetHeightsCommand>(
            workbench().document, title, part->allHeights(),
            planning::SimulationState{name, part->allHeights()}));
        report(text, report_);
      });
    });
  });
  return started;
}

bool SimulationPanel::raiseByAllowance(double allowanceMm) {
  const planning::Project& p = workbench().document.project();
  bool started = false;
  runUserAction(workbench().reportError, tr("Raise by stock allowance"), [&] {
    if (!p.part) throw InvalidInput("there is no part to raise by a stock allowance");
    auto part = std::make_shared<const ddf::DisplacementField>(*p.part);
    const QString title = tr("Raise by stock allowance %1 mm").arg(allowanceMm);
    started = startJob(title, [=, this](const ProgressCallback& progress) {
      reportProgress(progress, 0.0);
      auto raised = std::make_shared<std::vector<float>>(
          planning::workpieceWithAllowance(*part, allowanceMm).allHeights());
      reportProgress(progress, 1.0);
      return std::function<void()>([this, part, raised, title, allowanceMm] {
        Document& doc = workbench().document;
        const auto& states = doc.project().states;
        const bool hasDesign = planning::designState(states) != nullptr;
        std::vector<std::unique_ptr<DocumentCommand>> parts;
        // The error map compares against "design": keep the heights before the first raise.
        if (!hasDesign)
          parts.push_back(std::make_unique<SetHeightsCommand>(
              doc, tr("Record design"), part->allHeights(),
              planning::SimulationState{planning::kDesignStateName, part->allHeights()}));
        const std::string name = planning::allowanceStateName(allowanceMm);
        parts.push_back(std::make_unique<SetHeightsCommand>(
            doc, title, *raised, planning::SimulationState{name, *raised}));
        doc.push(std::make_unique<CompositeCommand>(doc, title, std::move(parts)));
        report(tr("Raised the part by %1 mm along its normal (state '%2'%3)")
                   .arg(allowanceMm)
                   .arg(QString::fromStdString(name))
                   .arg(hasDesign ? QString() : tr(", heights before kept as 'design'")),
               workpieceLabel_);
      });
    });
  });
  return started;
}

bool SimulationPanel::stockFromMesh(const QString& file) {
  const planning::Project& p = workbench().document.project();
  bool started = false;
  runUserAction(workbench().reportError, tr("Stock from mesh"), [&] {
    if (!p.part) throw InvalidInput("there is no part to convert a stock mesh onto");
    if (file.isEmpty()) throw InvalidInput("choose a stock mesh file");
    auto part = std::make_shared<const ddf::DisplacementField>(*p.part);
    const QString shortName = QFileInfo(file).fileName();
    const QString title = tr("Stock from mesh '%1'").arg(shortName);
    started = startJob(title, [=, this](const ProgressCallback& progress) {
      const ddf::TriangleMesh mesh = io::readMesh(std::filesystem::path(file.toStdString()));
      planning::StockWorkpieceParams params;
      params.requireFullCoverage = false;
      params.fill.progress = progress;
      auto stock = std::make_shared<planning::StockWorkpiece>(
          planning::workpieceFromStockMesh(*part, mesh, params));
      return std::function<void()>([this, stock, title, shortName] {
        const std::vector<float>& heights = stock->workpiece.allHeights();
        workbench().document.push(std::make_unique<SetHeightsCommand>(
            workbench().document, title, heights,
            planning::SimulationState{"stock " + shortName.toStdString(), heights}));
        const QString text =
            tr("Stock from '%1': %2 of %3 heights missed the mesh and keep the part's height")
                .arg(shortName)
                .arg(stock->missing)
                .arg(heights.size());
        workpieceLabel_->setText(text);
        workbench().console.appendMessage(stock->missing > 0 ? LogLevel::Warning : LogLevel::Info,
                                          text);
      });
    });
  });
  return started;
}

bool SimulationPanel::correctPenetrations(int index, int gridSize, int every) {
  const planning::Project& p = workbench().document.project();
  bool started = false;
  runUserAction(workbench().reportError, tr("Correct penetrations"), [&] {
    if (!p.part) throw InvalidInput("there is no part to correct the path against");
    if (index < 0 || index >= static_cast<int>(p.paths.size()))
      throw InvalidInput("select a tool path to correct");
    const planning::ToolPath& path = p.paths[static_cast<std::size_t>(index)];
    if (path.tool < 0 || path.tool >= static_cast<int>(p.tools.size()))
      throw InvalidInput("path '" + path.name + "' refers to a missing tool");
    if (path.poses.empty()) throw InvalidInput("path '" + path.name + "' has no poses");
    auto part = std::make_shared<const ddf::DisplacementField>(*p.part);
    const planning::Tool tool = p.tools[static_cast<std::size_t>(path.tool)];
    const QString title = tr("Correct penetrations of '%1'").arg(QString::fromStdString(path.name));
    started = startJob(title, [=, this](const ProgressCallback& progress) {
      planning::PenetrationCorrectionParams params;
      params.gridSize = gridSize;
      params.every = every;
      params.progress = progress;
      QElapsedTimer clock;
      clock.start();
      planning::CorrectedPath result = planning::correctPathPenetrations(*part, tool, path, params);
      const double ms = clock.nsecsElapsed() / 1e6;
      const planning::PenetrationCorrectionReport& r = result.report;
      const auto lifted = std::ranges::count_if(r.liftMm, [](double l) { return l > 0.0; });
      const QString text = tr("%1 poses lifted, max lift %2 mm, %3 ms")
                               .arg(lifted)
                               .arg(r.maxLiftMm, 0, 'f', 4)
                               .arg(ms, 0, 'f', 1);
      return std::function<void()>([this, index, corrected = std::move(result.path), title, text] {
        workbench().document.push(
            std::make_unique<ReplacePathCommand>(workbench().document, index, corrected, title));
        report(text, correctionLabel_);
      });
    });
  });
  return started;
}

}  // namespace ddfcam::gui
