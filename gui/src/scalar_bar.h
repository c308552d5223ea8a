// SPDX-License-Identifier: MIT
// ddfcam gui: the scalar bar of the field shown on a part (private to gui/src).
#pragma once

#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>

namespace ddfcam::gui {

/// @brief A hidden, unpickable horizontal scalar bar along the bottom of the view, with
/// out-of-range swatches, three-significant-digit labels and a font that has square brackets
/// (for titles such as "material removed [mm]").
vtkSmartPointer<vtkScalarBarActor> makeScalarBar();

}  // namespace ddfcam::gui
