// SPDX-License-Identifier: MIT
// ddfcam gui: the look of a part scene's actors, shared by its sources (private to gui/src).
#pragma once

class vtkActor;
class vtkPolyDataMapper;
class vtkProperty;

namespace ddfcam::gui::detail {

/// @brief The polydata mapper of @p actor (every PartScene actor has one).
vtkPolyDataMapper* mapperOf(vtkActor* actor);
/// @brief Colour of the plain surface, RGB in [0, 1]: brushed brass, grinding targets are metal.
inline constexpr double kSurfaceRgb[3] = {0.80, 0.72, 0.55};

/// @brief The plain surface's material (kSurfaceRgb, Phong, both sides).
void styleSurface(vtkProperty* p);

}  // namespace ddfcam::gui::detail
