// SPDX-License-Identifier: MIT
// ddfcam: a cutter-location program, the tool path as exchanged with CAM systems, posts and robots.
#include <ddfcam/io/cl_program.h>

#include <algorithm>

namespace ddfcam::io {

double millimetresPer(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Inch:
      return 25.4;
    case LengthUnit::Metre:
      return 1000.0;
    case LengthUnit::Millimetre:
      break;
  }
  return 1.0;
}

std::string_view lengthUnitName(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Inch:
      return "in";
    case LengthUnit::Metre:
      return "m";
    case LengthUnit::Millimetre:
      break;
  }
  return "mm";
}

bool ClProgram::multiAxis() const {
  return std::any_of(points.begin(), points.end(),
                     [](const ClPoint& p) { return p.axis.has_value(); });
}

int ClProgram::pathCount() const {
  int last = -1;
  for (const ClPoint& p : points) last = std::max(last, p.path);
  return last + 1;
}

}  // namespace ddfcam::io
