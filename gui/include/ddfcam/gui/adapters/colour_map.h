// SPDX-License-Identifier: MIT
// ddfcam gui adapters: colour maps for scalar fields and their VTK lookup tables.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <vtkSmartPointer.h>

class vtkLookupTable;

namespace ddfcam::gui {

/// @brief Colour maps offered for scalar fields. Sequential maps (Viridis, Magma, Grey) read
/// in order of lightness; Turbo is a rainbow with smooth lightness; CoolWarm is diverging
/// (blue - near-white - red) for signed values centred on zero.
enum class ColourMap {
  Viridis = 0,  ///< perceptually uniform, dark blue-violet -> yellow (default for unsigned)
  Turbo,        ///< improved rainbow, dark blue -> green -> dark red
  Grey,         ///< dark grey -> white
  CoolWarm,     ///< diverging blue -> light grey -> red (default for signed)
  Magma,        ///< perceptually uniform, black -> purple -> pale yellow
};

/// @brief Every map in combo-box order.
inline constexpr std::array<ColourMap, 5> kColourMaps = {
    ColourMap::Viridis, ColourMap::Turbo, ColourMap::Grey, ColourMap::CoolWarm, ColourMap::Magma};

/// @brief kColourMaps, for range-for loops.
constexpr const std::array<ColourMap, 5>& allColourMaps() {
  return kColourMaps;
}

/// @brief Display name of @p map for a combo box ("Viridis", "Turbo", "Grey", "Cool to warm",
/// "Magma"); also the name colourMapFromName() accepts.
std::string colourMapName(ColourMap map);

/// @brief The map named @p name (exact display name, as colourMapName() gives it).
/// @return std::nullopt for an unknown name.
std::optional<ColourMap> colourMapFromName(std::string_view name);

/// @brief Colour of @p map at @p t (clamped to [0, 1]; NaN counts as 0), RGB in [0, 1]:
/// piecewise linear between the map's control points.
std::array<double, 3> colourAt(ColourMap map, double t);

/// @brief A colour @p map never produces, for values below the lookup table's range.
std::array<double, 3> belowRangeColour(ColourMap map);

/// @brief A colour @p map never produces, for values above the lookup table's range.
std::array<double, 3> aboveRangeColour(ColourMap map);

/// @brief The map a field shows by default: CoolWarm for signed fields, Viridis otherwise.
ColourMap defaultColourMap(bool isSigned);

/// @brief A value range [lo, hi] for a colour map.
struct ValueRange {
  double lo = 0.0;  ///< value shown with the map's first colour (field units, e.g. mm)
  double hi = 1.0;  ///< value shown with the map's last colour, > lo
};

/// @brief Default display range of a field whose values span [@p min, @p max]: the span
/// itself for unsigned fields, [-a, a] with a = max(|min|, |max|) for signed fields (so zero
/// sits on the diverging map's neutral middle). A degenerate span is widened so that lo < hi:
/// by 5 % of |value| on each side, or to [v - 0.5, v + 0.5] (signed: [-1, 1]) when it is 0.
/// @throws InvalidInput if min or max is not finite or min > max.
ValueRange defaultRange(double min, double max, bool isSigned);

/// @brief printf format of the scale labels over [@p lo, @p hi]: fixed decimals for three
/// significant digits of the larger magnitude m = max(|lo|, |hi|) when 1e-3 <= m < 1e5
/// ("%.0f" for m = 1305, "%.3f" for m = 0.25), else "%.2e". Fixed notation keeps labels short
/// enough not to run into each other (exponents like "-1.31e+03" do).
std::string scaleLabelFormat(double lo, double hi);

/// @brief Colour of "no value" (NaN, e.g. a deviation where the desired surface has no point)
/// in every lookup table of the workbench: neutral grey, RGB in [0, 1]. (VTK's default is dark
/// red, which on an error map would read as overcut.)
inline constexpr std::array<double, 3> kNoValueRgb = {0.5, 0.5, 0.5};

/// @brief A lookup table of @p colours entries sampling @p map evenly, mapping [@p lo, @p hi]
/// onto it, with belowRangeColour() / aboveRangeColour() switched on for values outside and
/// kNoValueRgb for NaN. The
/// table is complete: do not call Build() on it expecting a rebuild (VTK would only refresh its
/// special colours).
/// @throws InvalidInput if lo >= hi, either is not finite, or colours < 2.
vtkSmartPointer<vtkLookupTable> makeLookupTable(ColourMap map, double lo, double hi,
                                                int colours = 256);

}  // namespace ddfcam::gui
