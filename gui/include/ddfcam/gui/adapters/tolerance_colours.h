// SPDX-License-Identifier: MIT
// ddfcam gui adapters: the error-map colouring with a tolerance band (blue = material left,
// green = in tolerance, red = overcut) and its VTK lookup table.
#pragma once

#include <ddfcam/planning/inspection/error_map.h>

#include <vtkSmartPointer.h>

#include <array>

class vtkLookupTable;

namespace ddfcam::gui {

/// @brief Colour of a deviation @p valueMm on the tolerance map over [@p loMm, @p hiMm]: green
/// inside @p band (bounds included), above it blue getting darker towards hiMm (material left),
/// below it red getting darker towards loMm (overcut), RGB in [0, 1]. Values beyond the range
/// take the darkest colour of their side; NaN is green (callers skip "no value").
/// The class of the colour always equals planning::classify(valueMm, band).
std::array<double, 3> toleranceColourAt(double valueMm, double loMm, double hiMm,
                                        const planning::ToleranceBand& band);

/// @brief One colour per class, for displays that show classes only (the live tolerance band):
/// the band's green, and the middle shades of the material-left blue and the overcut red.
/// toleranceClassOfColour() of each gives its class back.
std::array<double, 3> toleranceClassColour(planning::ToleranceClass toleranceClass);

/// @brief Which class a colour of toleranceColourAt() stands for, by its dominant channel
/// (green, blue or red), for tests and pickers reading colours back from the view.
planning::ToleranceClass toleranceClassOfColour(const std::array<double, 3>& rgb);

/// @brief Lookup table of @p colours entries sampling toleranceColourAt() at the centres of
/// equal cells over [@p loMm, @p hiMm]; the special below- and above-range colours are the
/// darkest red and blue, NaN is kNoValueRgb (colour_map.h). A cell straddling a band bound
/// takes the class of its centre, so the view may misclassify values within
/// (hi - lo) / colours of a bound.
/// @throws InvalidInput if lo >= hi, either is not finite, colours < 2, or the band is invalid.
vtkSmartPointer<vtkLookupTable> makeToleranceLookupTable(double loMm, double hiMm,
                                                         const planning::ToleranceBand& band,
                                                         int colours = 1024);

}  // namespace ddfcam::gui
