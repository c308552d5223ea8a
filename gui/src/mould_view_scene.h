// SPDX-License-Identifier: MIT
// ddfcam gui: MouldView's VTK scene, shared by mould_view.cpp and mould_view_layers.cpp.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/gui/mould_view.h>

#include "scalar_bar.h"

#include <vtkActor.h>
#include <vtkCellLocator.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkSmartPointer.h>

namespace ddfcam::gui::mould_view_detail {

/// @brief Points and triangles as they are (no feature splitting): point i is mesh vertex i.
vtkSmartPointer<vtkPolyData> rawPolyData(const ddf::TriangleMesh& mesh);
/// @brief Point normals that keep the point ids (no splitting).
vtkSmartPointer<vtkPolyDataNormals> smoothNormals();
/// @brief The poly-data mapper of @p actor.
vtkPolyDataMapper* mapperOf(vtkActor* actor);

}  // namespace ddfcam::gui::mould_view_detail

namespace ddfcam::gui {

/// The VTK objects of both views.
struct MouldView::Scene {
  vtkSmartPointer<vtkPolyData> primaryData;
  vtkSmartPointer<vtkPolyDataNormals> primaryNormals = mould_view_detail::smoothNormals();
  vtkSmartPointer<vtkActor> primary;
  vtkSmartPointer<vtkPolyData> secondaryData;
  vtkSmartPointer<vtkPolyDataNormals> secondaryNormals = mould_view_detail::smoothNormals();
  vtkSmartPointer<vtkActor> secondary;  // in the secondary view
  vtkSmartPointer<vtkActor> overlay;    // the same surface, translucent, in the primary view
  vtkSmartPointer<vtkActor> highlight;
  vtkSmartPointer<vtkActor> linesPrimary;
  vtkSmartPointer<vtkActor> linesSecondary;
  vtkSmartPointer<vtkScalarBarActor> primaryBar = makeScalarBar();
  vtkSmartPointer<vtkScalarBarActor> secondaryBar = makeScalarBar();
  ddf::TriangleMesh primaryMesh;
  bool coloured = false;
  mutable vtkSmartPointer<vtkCellLocator> locators[2];
};

}  // namespace ddfcam::gui
