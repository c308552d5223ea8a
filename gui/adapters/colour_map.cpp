// SPDX-License-Identifier: MIT
// ddfcam gui adapters: colour map control points, interpolation and VTK lookup tables.
#include <ddfcam/gui/adapters/colour_map.h>

#include <ddfcam/error.h>

#include <vtkLookupTable.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

namespace ddfcam::gui {

namespace {

struct ControlPoint {
  double t;
  double r, g, b;
};

// Sampled every 16 of 256 entries from the published (CC0) tables of van der Walt and Smith;
// piecewise linear between them stays within about 1/255 of the full tables.
constexpr ControlPoint kViridis[] = {
    {0 / 255.0, 0.267004, 0.004874, 0.329415},   {16 / 255.0, 0.282327, 0.094955, 0.417331},
    {32 / 255.0, 0.278826, 0.175490, 0.483397},  {48 / 255.0, 0.258965, 0.251537, 0.524736},
    {64 / 255.0, 0.229739, 0.322361, 0.545706},  {80 / 255.0, 0.199430, 0.387607, 0.554642},
    {96 / 255.0, 0.172719, 0.448791, 0.557885},  {112 / 255.0, 0.149039, 0.508051, 0.557250},
    {128 / 255.0, 0.127568, 0.566949, 0.550556}, {144 / 255.0, 0.120638, 0.625828, 0.533488},
    {160 / 255.0, 0.157851, 0.683765, 0.501686}, {176 / 255.0, 0.246070, 0.738910, 0.452024},
    {192 / 255.0, 0.369214, 0.788888, 0.382914}, {208 / 255.0, 0.515992, 0.831158, 0.294279},
    {224 / 255.0, 0.678489, 0.863742, 0.189503}, {240 / 255.0, 0.845561, 0.887322, 0.099702},
    {255 / 255.0, 0.993248, 0.906157, 0.143936}};

constexpr ControlPoint kMagma[] = {
    {0 / 255.0, 0.001462, 0.000466, 0.013866},   {16 / 255.0, 0.039608, 0.031090, 0.133515},
    {32 / 255.0, 0.113094, 0.065492, 0.276784},  {48 / 255.0, 0.211718, 0.061992, 0.418647},
    {64 / 255.0, 0.316654, 0.071690, 0.485380},  {80 / 255.0, 0.414709, 0.110431, 0.504662},
    {96 / 255.0, 0.512831, 0.148179, 0.507648},  {112 / 255.0, 0.613617, 0.181811, 0.498536},
    {128 / 255.0, 0.716387, 0.214982, 0.475290}, {144 / 255.0, 0.816914, 0.255895, 0.436461},
    {160 / 255.0, 0.904281, 0.319610, 0.388137}, {176 / 255.0, 0.960949, 0.418323, 0.359630},
    {192 / 255.0, 0.986700, 0.535582, 0.382210}, {208 / 255.0, 0.996096, 0.653659, 0.446213},
    {224 / 255.0, 0.996898, 0.769591, 0.534892}, {240 / 255.0, 0.992440, 0.884330, 0.640099},
    {255 / 255.0, 0.987053, 0.991438, 0.749504}};

// Every 16th entry of Mikhailov's published Turbo table (Google, 2019).
constexpr ControlPoint kTurbo[] = {
    {0 / 255.0, 0.18995, 0.07176, 0.23217},   {16 / 255.0, 0.25107, 0.25237, 0.63374},
    {32 / 255.0, 0.27628, 0.42118, 0.89123},  {48 / 255.0, 0.25862, 0.57958, 0.99876},
    {64 / 255.0, 0.15844, 0.73551, 0.92305},  {80 / 255.0, 0.09267, 0.86554, 0.76230},
    {96 / 255.0, 0.19659, 0.94901, 0.59466},  {112 / 255.0, 0.42778, 0.99419, 0.38575},
    {128 / 255.0, 0.64362, 0.98999, 0.23356}, {144 / 255.0, 0.80473, 0.92452, 0.20459},
    {160 / 255.0, 0.93301, 0.81236, 0.22667}, {176 / 255.0, 0.99314, 0.67408, 0.20348},
    {192 / 255.0, 0.98360, 0.49291, 0.12849}, {208 / 255.0, 0.92105, 0.31489, 0.05475},
    {224 / 255.0, 0.81608, 0.18462, 0.01809}, {240 / 255.0, 0.66449, 0.08436, 0.00424},
    {255 / 255.0, 0.47960, 0.01583, 0.01055}};

// Moreland's "cool to warm" diverging map (2009), every 1/16: its Msh interpolation keeps
// both halves equally light at equal distance from the neutral middle.
constexpr ControlPoint kCoolWarm[] = {
    {0.0000, 0.2298, 0.2987, 0.7537}, {0.0625, 0.3039, 0.4065, 0.8450},
    {0.1250, 0.3830, 0.5094, 0.9174}, {0.1875, 0.4667, 0.6046, 0.9682},
    {0.2500, 0.5530, 0.6889, 0.9954}, {0.3125, 0.6392, 0.7596, 0.9982},
    {0.3750, 0.7222, 0.8140, 0.9766}, {0.4375, 0.7987, 0.8498, 0.9317},
    {0.5000, 0.8654, 0.8654, 0.8654}, {0.5625, 0.9241, 0.8274, 0.7745},
    {0.6250, 0.9589, 0.7698, 0.6780}, {0.6875, 0.9700, 0.6943, 0.5794},
    {0.7500, 0.9580, 0.6028, 0.4818}, {0.8125, 0.9239, 0.4973, 0.3880},
    {0.8750, 0.8692, 0.3783, 0.3003}, {0.9375, 0.7956, 0.2413, 0.2205},
    {1.0000, 0.7057, 0.0156, 0.1502}};

// Not black: the darkest values must stay distinguishable from shadowed surface.
constexpr ControlPoint kGrey[] = {{0.0, 0.10, 0.10, 0.10}, {1.0, 0.95, 0.95, 0.95}};

std::span<const ControlPoint> controlPoints(ColourMap map) {
  switch (map) {
    case ColourMap::Viridis:
      return kViridis;
    case ColourMap::Turbo:
      return kTurbo;
    case ColourMap::Grey:
      return kGrey;
    case ColourMap::CoolWarm:
      return kCoolWarm;
    case ColourMap::Magma:
      return kMagma;
  }
  throw InvalidInput("colour map " + std::to_string(static_cast<int>(map)) + " does not exist");
}

struct OutOfRange {
  std::array<double, 3> below, above;
};

// Colours outside each map's gamut, so clipped values are never mistaken for the ends.
OutOfRange outOfRange(ColourMap map) {
  switch (map) {
    case ColourMap::Viridis:
      return {{0.55, 0.55, 0.55}, {0.95, 0.25, 0.65}};
    case ColourMap::Turbo:
      return {{0.55, 0.55, 0.55}, {0.97, 0.97, 0.97}};
    case ColourMap::Grey:
      return {{0.15, 0.30, 0.85}, {0.90, 0.35, 0.10}};
    case ColourMap::CoolWarm:
      return {{0.10, 0.75, 0.75}, {0.95, 0.85, 0.10}};
    case ColourMap::Magma:
      return {{0.25, 0.60, 0.25}, {0.30, 0.80, 1.00}};
  }
  throw InvalidInput("colour map " + std::to_string(static_cast<int>(map)) + " does not exist");
}

void checkRange(double lo, double hi, const char* what) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw InvalidInput(std::string(what) + ": value range [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "] must be finite with lo < hi");
}

}  // namespace

std::string colourMapName(ColourMap map) {
  switch (map) {
    case ColourMap::Viridis:
      return "Viridis";
    case ColourMap::Turbo:
      return "Turbo";
    case ColourMap::Grey:
      return "Grey";
    case ColourMap::CoolWarm:
      return "Cool to warm";
    case ColourMap::Magma:
      return "Magma";
  }
  return "unknown";
}

std::optional<ColourMap> colourMapFromName(std::string_view name) {
  for (ColourMap map : kColourMaps)
    if (colourMapName(map) == name) return map;
  return std::nullopt;
}

std::array<double, 3> colourAt(ColourMap map, double t) {
  const std::span<const ControlPoint> points = controlPoints(map);
  t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  // First control point at or beyond t; the segment before it contains t.
  const auto upper = std::lower_bound(points.begin(), points.end(), t,
                                      [](const ControlPoint& p, double v) { return p.t < v; });
  if (upper == points.begin()) return {points.front().r, points.front().g, points.front().b};
  if (upper == points.end()) return {points.back().r, points.back().g, points.back().b};
  const ControlPoint& a = *(upper - 1);
  const ControlPoint& b = *upper;
  const double s = (t - a.t) / (b.t - a.t);
  return {a.r + s * (b.r - a.r), a.g + s * (b.g - a.g), a.b + s * (b.b - a.b)};
}

std::array<double, 3> belowRangeColour(ColourMap map) {
  return outOfRange(map).below;
}

std::array<double, 3> aboveRangeColour(ColourMap map) {
  return outOfRange(map).above;
}

ColourMap defaultColourMap(bool isSigned) {
  return isSigned ? ColourMap::CoolWarm : ColourMap::Viridis;
}

ValueRange defaultRange(double min, double max, bool isSigned) {
  if (!std::isfinite(min) || !std::isfinite(max) || min > max)
    throw InvalidInput("defaultRange: field values span [" + std::to_string(min) + ", " +
                       std::to_string(max) + "], expected finite min <= max");
  if (isSigned) {
    const double a = std::max(std::abs(min), std::abs(max));
    return a > 0.0 ? ValueRange{-a, a} : ValueRange{-1.0, 1.0};
  }
  if (min < max) return {min, max};
  const double pad = min != 0.0 ? 0.05 * std::abs(min) : 0.5;
  return {min - pad, max + pad};
}

std::string scaleLabelFormat(double lo, double hi) {
  const double m = std::max(std::abs(lo), std::abs(hi));
  if (!(m >= 1e-3 && m < 1e5)) return "%.2e";
  const int decimals = std::max(0, 2 - static_cast<int>(std::floor(std::log10(m))));
  return "%." + std::to_string(decimals) + "f";
}

vtkSmartPointer<vtkLookupTable> makeLookupTable(ColourMap map, double lo, double hi, int colours) {
  checkRange(lo, hi, "makeLookupTable");
  if (colours < 2)
    throw InvalidInput("makeLookupTable: " + std::to_string(colours) +
                       " colours requested, at least 2 needed");
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  // Range and special colours before the entries: set after them, a later Build() would see
  // the table as modified since its last build and regenerate the default HSV ramp.
  table->SetTableRange(lo, hi);
  table->SetScaleToLinear();
  const auto below = belowRangeColour(map);
  const auto above = aboveRangeColour(map);
  table->SetBelowRangeColor(below[0], below[1], below[2], 1.0);
  table->SetAboveRangeColor(above[0], above[1], above[2], 1.0);
  table->UseBelowRangeColorOn();
  table->UseAboveRangeColorOn();
  table->SetNanColor(kNoValueRgb[0], kNoValueRgb[1], kNoValueRgb[2], 1.0);
  table->SetNumberOfTableValues(colours);
  for (int i = 0; i < colours; ++i) {
    const auto c = colourAt(map, static_cast<double>(i) / (colours - 1));
    table->SetTableValue(i, c[0], c[1], c[2], 1.0);
  }
  table->BuildSpecialColors();
  return table;
}

}  // namespace ddfcam::gui
