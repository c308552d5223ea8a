// SPDX-License-Identifier: MIT
// ddfcam gui adapters: the offset surfaces h = const of a DDF's crust -> vtkPolyData.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace ddfcam::gui {

/// @brief The crust's offset surface at height @p h: vertex v at p_v + h v_v (support position
/// plus h times its vector, mm, part frame), one triangle per support face in face order. The
/// vectors interpolate linearly over a face, so this is the h-offset surface exactly (sec. 4.3),
/// e.g. h = +1 and h = -1 for the two sides of the +-1 crust.
ddf::TriangleMesh crustOffsetMesh(const ddf::DisplacementField& ddf, double h);

/// @brief Shaded polydata of crustOffsetMesh(@p ddf, @p h) (as toSurfacePolyData, with cell data
/// kFaceArrayName: the support face of each triangle).
vtkSmartPointer<vtkPolyData> toCrustPolyData(const ddf::DisplacementField& ddf, double h);

}  // namespace ddfcam::gui
