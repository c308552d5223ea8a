// SPDX-License-Identifier: MIT
// ddfcam: a cutter-location program, the tool path as exchanged with CAM systems, posts and robots.
#include <ddfcam/planning/placement/cl_program.h>

#include <algorithm>

namespace ddfcam::planning {

bool ClProgram::multiAxis() const {
  return std::any_of(points.begin(), points.end(),
                     [](const ClPoint& p) { return p.axis.has_value(); });
}

int ClProgram::pathCount() const {
  int last = -1;
  for (const ClPoint& p : points) last = std::max(last, p.path);
  return last + 1;
}

std::vector<ClProgram> splitByTool(const ClProgram& program) {
  std::vector<ClProgram> parts;
  ClProgram header = program;
  header.points.clear();
  header.toolChanges.clear();
  std::size_t begin = 0;
  for (std::size_t c = 0; c <= program.toolChanges.size(); ++c) {
    const std::size_t end =
        c < program.toolChanges.size() ? program.toolChanges[c].firstPoint : program.points.size();
    ClProgram part = header;
    if (c > 0) {
      const ClToolChange& change = program.toolChanges[c - 1];
      part.toolNumber = change.toolNumber;
      part.toolName = change.toolName;
      part.cutter = change.cutter;
    }
    part.points.assign(program.points.begin() + static_cast<std::ptrdiff_t>(begin),
                       program.points.begin() + static_cast<std::ptrdiff_t>(std::max(begin, end)));
    // Paths renumbered from 0 within each part, in order of first appearance.
    int lastPath = -1, path = -1;
    for (ClPoint& p : part.points) {
      if (p.path != lastPath) ++path;
      lastPath = p.path;
      p.path = path;
    }
    if (!part.points.empty()) parts.push_back(std::move(part));
    begin = std::max(begin, end);
  }
  return parts;
}

}  // namespace ddfcam::planning
