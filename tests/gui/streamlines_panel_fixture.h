// SPDX-License-Identifier: MIT
// Test support: parts, polydata readers and the workbench set-up of the Streamlines panel tests.
#pragma once

#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/planning/model/project.h>

#include <QtTest/QtTest>

#include <vtkCell.h>
#include <vtkIdList.h>
#include <vtkPolyData.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace ddfcam::test {

inline constexpr double kRadius = 10.0;  ///< radius of cylinderProject(), mm

/// A project holding only the DDF of @p part, named @p name.
inline planning::Project projectOf(ddf::GeneratedSurface part, const char* name) {
  planning::Project project;
  project.partName = name;
  project.part = std::move(part.ddf);
  return project;
}

/// The open cylinder (radius kRadius, length 30 mm) as a project.
inline planning::Project cylinderProject() {
  return projectOf(
      ddf::cylinderPart(
          {.radiusMm = kRadius, .lengthMm = 30.0, .segments = 48, .rings = 12, .m = 9}),
      "cylinder");
}

/// Points of every cell of a polydata, in cell order, mm.
inline std::vector<std::vector<ddf::Vec3>> cellPoints(vtkPolyData* data) {
  std::vector<std::vector<ddf::Vec3>> out;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    auto* ids = data->GetCell(c)->GetPointIds();
    auto& cell = out.emplace_back();
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i) {
      double p[3];
      data->GetPoint(ids->GetId(i), p);
      cell.emplace_back(p[0], p[1], p[2]);
    }
  }
  return out;
}

/// The contact points of every pass of @p path, mm.
inline std::vector<std::vector<ddf::Vec3>> passContacts(const planning::ToolPath& path) {
  std::vector<std::vector<ddf::Vec3>> out;
  for (std::size_t s = 0; s < path.passStarts.size(); ++s) {
    const std::size_t end =
        s + 1 < path.passStarts.size() ? path.passStarts[s + 1] : path.poses.size();
    auto& line = out.emplace_back();
    for (std::size_t i = path.passStarts[s]; i < end; ++i) line.push_back(path.poses[i].contact);
  }
  return out;
}

/// A workbench without the demo part whose Streamlines panel is reset before every test.
class StreamlinesPanelTestBase : public WorkbenchTest {
  Q_OBJECT

 protected:
  gui::StreamlinesPanel& panel() { return *f_.window->findChild<gui::StreamlinesPanel*>(); }
  gui::PartScene& scene() { return f_.window->partView().scene(); }

 private slots:
  void initTestCase() {
    QVERIFY(openWorkbench(false));
    QVERIFY(f_.window->findChild<gui::StreamlinesPanel*>() != nullptr);
  }
  void init() {
    f_.script.errors.clear();
    panel().setRegion(-1);
    panel().setFieldSource(planning::FlowFieldSource::MaxCurvatureDirection);
    panel().setFieldSmoothing(false);
    panel().setSmoothingWindow(0);
  }
};

}  // namespace ddfcam::test
