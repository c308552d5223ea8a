// SPDX-License-Identifier: MIT
// ddfcam: the length units a part or path may come in, and their factors to millimetres.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace ddfcam {

/// @brief Length unit of an input file. Everything inside ddfcam is in millimetres; a file in
/// another unit is scaled by millimetresPer() when it is read.
enum class LengthUnit { Millimetre, Centimetre, Metre, Inch };

/// @brief Millimetres per one @p unit (1, 10, 1000, 25.4).
double millimetresPer(LengthUnit unit);

/// @brief Short symbol of @p unit as the CLI and the project file spell it: "mm", "cm", "m",
/// "in".
std::string_view unitSymbol(LengthUnit unit);

/// @brief @p unit from its symbol or name, any case: "mm", "millimetre(s)", "millimeter(s)",
/// "cm", ..., "m", "metre", "meter", "in", "inch", "inches"; std::nullopt for anything else.
std::optional<LengthUnit> parseLengthUnit(std::string_view text);

/// @brief The units accepted by parseLengthUnit, for messages: "mm, cm, m or in".
std::string_view lengthUnitChoices();

/// @brief Whether a part whose bounding-box diagonal is @p diagonal file units looks as if it
/// was read in the wrong unit: under 1 or over 10,000 (a part under 1 mm or over 10 m is
/// unusual for grinding, whereas one in metres or in micrometres is common).
bool sizeSuggestsOtherUnit(double diagonal);

/// @brief The unit a part of @p diagonal file units most likely uses when sizeSuggestsOtherUnit
/// holds: metres for a diagonal under 1 (a 0.3-unit blade is 300 mm), otherwise std::nullopt
/// (over 10,000 fits no unit ddfcam offers; the caller shows the size in each unit and asks).
std::optional<LengthUnit> likelyUnit(double diagonal);

}  // namespace ddfcam
