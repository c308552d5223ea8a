// SPDX-License-Identifier: MIT
// Test support: the base of the playback test classes (the small demo loaded, the playback of
// the Simulation panel, where its tool is drawn).
#pragma once

#include "simulation_fixture.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/panels/simulation_panel.h>
#include <ddfcam/gui/panels/simulation_playback.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/tool_overlay.h>
#include <ddfcam/planning/model/simulation_states.h>

#include <QUndoStack>

#include <vtkPolyData.h>

#include <array>
#include <cmath>
#include <vector>

namespace ddfcam::test {

/// Helpers of the playback tests (listed among their sources, so AUTOMOC sees the header).
class PlaybackTestBase : public WorkbenchTest {
  Q_OBJECT

 protected:
  using Tool = planning::Tool;
  gui::SimulationPlayback& playback() {
    return f_.window->findChild<ddfcam::gui::SimulationPanel*>()->playback();
  }
  ddfcam::gui::PartScene& scene() { return f_.window->partView().scene(); }
  QUndoStack& undo() { return *f_.window->document().undoStack(); }
  void loadDemo(std::vector<double> passX = {20.0}) {
    demo_ = smallDemo(std::move(passX));
    load(demo_.project);
    f_.script.errors.clear();
    playback().setPathIndex(0);
  }
  /// Bounds of the tool's cutting mesh at @p pose (library mesh, Eigen transform).
  static std::array<double, 6> toolBounds(const Tool& tool, const Eigen::Isometry3d& pose) {
    const auto mesh = ddfcam::planning::toolMesh(tool).transformed(pose);
    Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
    for (const auto& v : mesh.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    return {lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z()};
  }
  bool toolOverlayAt(int pose) {
    if (!scene().hasOverlay(ddfcam::gui::kToolCuttingOverlay)) return false;
    double b[6];
    scene().overlayData(ddfcam::gui::kToolCuttingOverlay)->GetBounds(b);
    const auto expected = toolBounds(project().tools[0], project().paths[0].poses[pose].pose);
    for (int i = 0; i < 6; ++i)
      if (std::abs(b[i] - expected[i]) > 1e-4) return false;
    return true;
  }

  /// The small demo with its design state: the same generator without the 0.2 mm allowance
  /// gives the same support and vectors with the design's heights.
  ddf::DisplacementField loadDemoWithDesign() {
    ddfcam::ddf::DemoPartParams designParams;
    designParams.cellsX = 16;
    designParams.cellsY = 12;
    designParams.m = 9;
    designParams.allowanceMm = 0.0;
    ddfcam::ddf::DisplacementField design = ddfcam::ddf::demoPart(designParams).ddf;
    auto demo = smallDemo();
    if (design.allHeights().size() != demo.project.part->allHeights().size() ||
        design.vector(0) != demo.project.part->vector(0))
      qFatal("the design generator no longer matches the small demo");
    demo.project.states.push_back({ddfcam::planning::kDesignStateName, design.allHeights()});
    demo_ = demo;
    load(demo.project);
    playback().setPathIndex(0);
    return design;
  }

  SmallDemo demo_;
};

}  // namespace ddfcam::test
