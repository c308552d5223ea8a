// SPDX-License-Identifier: MIT
// ddfcam: length units and their factors to millimetres.
#include <ddfcam/length_unit.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

namespace ddfcam {
namespace {

std::string lowered(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

double millimetresPer(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Millimetre:
      return 1.0;
    case LengthUnit::Centimetre:
      return 10.0;
    case LengthUnit::Metre:
      return 1000.0;
    case LengthUnit::Inch:
      return 25.4;
  }
  return 1.0;
}

std::string_view unitSymbol(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Millimetre:
      return "mm";
    case LengthUnit::Centimetre:
      return "cm";
    case LengthUnit::Metre:
      return "m";
    case LengthUnit::Inch:
      return "in";
  }
  return "mm";
}

std::optional<LengthUnit> parseLengthUnit(std::string_view text) {
  static const std::array<std::pair<const char*, LengthUnit>, 18> kNames = {{
      {"mm", LengthUnit::Millimetre},
      {"millimetre", LengthUnit::Millimetre},
      {"millimetres", LengthUnit::Millimetre},
      {"millimeter", LengthUnit::Millimetre},
      {"millimeters", LengthUnit::Millimetre},
      {"cm", LengthUnit::Centimetre},
      {"centimetre", LengthUnit::Centimetre},
      {"centimetres", LengthUnit::Centimetre},
      {"centimeter", LengthUnit::Centimetre},
      {"centimeters", LengthUnit::Centimetre},
      {"m", LengthUnit::Metre},
      {"metre", LengthUnit::Metre},
      {"metres", LengthUnit::Metre},
      {"meter", LengthUnit::Metre},
      {"meters", LengthUnit::Metre},
      {"in", LengthUnit::Inch},
      {"inch", LengthUnit::Inch},
      {"inches", LengthUnit::Inch},
  }};
  const std::string key = lowered(text);
  for (const auto& [name, unit] : kNames)
    if (key == name) return unit;
  return std::nullopt;
}

std::string_view lengthUnitChoices() {
  return "mm, cm, m or in";
}

bool sizeSuggestsOtherUnit(double diagonal) {
  return diagonal < 1.0 || diagonal > 10000.0;
}

std::optional<LengthUnit> likelyUnit(double diagonal) {
  if (diagonal > 0.0 && diagonal < 1.0) return LengthUnit::Metre;
  return std::nullopt;
}

}  // namespace ddfcam
