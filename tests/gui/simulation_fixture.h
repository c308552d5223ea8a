// SPDX-License-Identifier: MIT
// Test support: a small demo project (coarse demo part, default roll, short passes) for the
// Tools and Simulation panel tests.
#pragma once

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/analytic_surface.h>
#include <ddfcam/planning/model/demo_project.h>
#include <ddfcam/planning/model/project.h>

#include <memory>
#include <vector>

namespace ddfcam::test {

/// The demo part on a 16 x 12 grid at m = 9 (2.5 mm cells, 24,576 raster triangles: fast to
/// draw), its design surface, the default roll and demoPasses() along @p passX (step 0.5 mm).
struct SmallDemo {
  planning::Project project;
  std::shared_ptr<const ddf::AnalyticSurface> design;
};

inline SmallDemo smallDemo(std::vector<double> passX = {20.0}) {
  ddf::DemoPartParams partParams;
  partParams.cellsX = 16;
  partParams.cellsY = 12;
  partParams.m = 9;
  ddf::GeneratedSurface part = ddf::demoPart(partParams);
  SmallDemo demo;
  demo.design = part.design;
  planning::Project& p = demo.project;
  p.partName = "small demo";
  p.tools = {planning::Tool{}};
  planning::DemoPassesParams passes;
  passes.passXMm = std::move(passX);
  passes.stepMm = 0.5;
  passes.startYMm = 6.0;
  passes.endYMm = 24.0;
  p.paths = {planning::demoPasses(*part.design, p.tools.front(), passes)};
  p.part = std::move(part.ddf);
  return demo;
}

}  // namespace ddfcam::test
