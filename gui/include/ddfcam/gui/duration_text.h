// SPDX-License-Identifier: MIT
// ddfcam gui: a duration as a person reads it on a clock ("0:07", "12:30", "1:02:03").
#pragma once

#include <QString>

namespace ddfcam::gui {

/// @brief @p seconds (rounded, negative as 0) as m:ss, or h:mm:ss from one hour on.
QString durationText(double seconds);

}  // namespace ddfcam::gui
