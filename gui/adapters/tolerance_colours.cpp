// SPDX-License-Identifier: MIT
// ddfcam gui adapters: tolerance-band colours of error maps.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/colour_map.h>
#include <ddfcam/gui/adapters/tolerance_colours.h>

#include <vtkLookupTable.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace ddfcam::gui {
namespace {

using Rgb = std::array<double, 3>;

// Light shades next to the band keep a just-out-of-tolerance spot distinguishable from the
// band's green; the dark ends mark the worst places.
constexpr Rgb kInBand = {0.18, 0.68, 0.28};
constexpr Rgb kLeftLight = {0.60, 0.76, 0.96};
constexpr Rgb kLeftDark = {0.04, 0.12, 0.52};
constexpr Rgb kOvercutLight = {0.98, 0.62, 0.55};
constexpr Rgb kOvercutDark = {0.55, 0.02, 0.05};

Rgb mix(const Rgb& a, const Rgb& b, double s) {
  s = std::clamp(s, 0.0, 1.0);
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}

void checkToleranceRange(double lo, double hi, const planning::ToleranceBand& band) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw InvalidInput("tolerance colours: range [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "] mm is not a finite interval");
  planning::validateToleranceBand(band);
}

}  // namespace

std::array<double, 3> toleranceColourAt(double valueMm, double loMm, double hiMm,
                                        const planning::ToleranceBand& band) {
  switch (planning::classify(valueMm, band)) {
    case planning::ToleranceClass::MaterialLeft: {
      const double span = hiMm - band.upperMm;
      return mix(kLeftLight, kLeftDark, span > 0.0 ? (valueMm - band.upperMm) / span : 1.0);
    }
    case planning::ToleranceClass::Overcut: {
      const double span = band.lowerMm - loMm;
      return mix(kOvercutLight, kOvercutDark, span > 0.0 ? (band.lowerMm - valueMm) / span : 1.0);
    }
    case planning::ToleranceClass::InTolerance:
      break;
  }
  return kInBand;
}

std::array<double, 3> toleranceClassColour(planning::ToleranceClass toleranceClass) {
  switch (toleranceClass) {
    case planning::ToleranceClass::MaterialLeft:
      return mix(kLeftLight, kLeftDark, 0.5);
    case planning::ToleranceClass::Overcut:
      return mix(kOvercutLight, kOvercutDark, 0.5);
    case planning::ToleranceClass::InTolerance:
      break;
  }
  return kInBand;
}

planning::ToleranceClass toleranceClassOfColour(const std::array<double, 3>& rgb) {
  if (rgb[1] > rgb[0] && rgb[1] > rgb[2]) return planning::ToleranceClass::InTolerance;
  return rgb[2] > rgb[0] ? planning::ToleranceClass::MaterialLeft
                         : planning::ToleranceClass::Overcut;
}

vtkSmartPointer<vtkLookupTable> makeToleranceLookupTable(double loMm, double hiMm,
                                                         const planning::ToleranceBand& band,
                                                         int colours) {
  checkToleranceRange(loMm, hiMm, band);
  if (colours < 2)
    throw InvalidInput("tolerance colours: " + std::to_string(colours) +
                       " colours requested, at least 2 needed");
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  // Range and special colours first, as in makeLookupTable: a later Build() must not see the
  // table as modified and regenerate its default ramp.
  table->SetTableRange(loMm, hiMm);
  table->SetScaleToLinear();
  table->SetBelowRangeColor(kOvercutDark[0], kOvercutDark[1], kOvercutDark[2], 1.0);
  table->SetAboveRangeColor(kLeftDark[0], kLeftDark[1], kLeftDark[2], 1.0);
  table->UseBelowRangeColorOn();
  table->UseAboveRangeColorOn();
  table->SetNanColor(kNoValueRgb[0], kNoValueRgb[1], kNoValueRgb[2], 1.0);
  table->SetNumberOfTableValues(colours);
  const double cell = (hiMm - loMm) / colours;
  for (int i = 0; i < colours; ++i) {
    const Rgb c = toleranceColourAt(loMm + (i + 0.5) * cell, loMm, hiMm, band);
    table->SetTableValue(i, c[0], c[1], c[2], 1.0);
  }
  table->BuildSpecialColors();
  return table;
}

}  // namespace ddfcam::gui
