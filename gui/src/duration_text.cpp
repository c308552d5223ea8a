// SPDX-License-Identifier: MIT
// ddfcam gui: durationText.
#include <ddfcam/gui/duration_text.h>

#include <algorithm>
#include <cmath>

namespace ddfcam::gui {

QString durationText(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  const QChar zero('0');
  if (s >= 3600)
    return QString("%1:%2:%3").arg(s / 3600).arg(s / 60 % 60, 2, 10, zero).arg(s % 60, 2, 10, zero);
  return QString("%1:%2").arg(s / 60).arg(s % 60, 2, 10, zero);
}

}  // namespace ddfcam::gui
