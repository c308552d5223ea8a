// SPDX-License-Identifier: MIT
// ddfcam: traced lines made ready for tool placement: cleaned, ordered and oriented for cutting.
#include <ddfcam/planning/lines/line_ordering.h>

#include <algorithm>
#include <utility>

namespace ddfcam::planning {

void dropRepeatedPoints(Streamline& line) {
  constexpr double kEpsMm = 1e-6;
  std::vector<ddf::SurfaceLocation> kept;
  for (const ddf::SurfaceLocation& q : line.points) {
    if (!kept.empty() && (q.point - kept.back().point).norm() <= kEpsMm) continue;
    if (kept.size() >= 2 && (q.point - kept[kept.size() - 2].point).norm() <= kEpsMm) {
      kept.pop_back();
      continue;
    }
    kept.push_back(q);
  }
  line.points = std::move(kept);
  line.seedIndex = std::min(line.seedIndex, line.points.empty() ? 0 : line.points.size() - 1);
}

Streamline reversedStreamline(Streamline line) {
  std::reverse(line.points.begin(), line.points.end());
  std::swap(line.stop, line.backwardStop);
  line.seedIndex = line.points.empty() ? 0 : line.points.size() - 1 - line.seedIndex;
  return line;
}

LinkedPaths orderLinesForCutting(const ddf::DisplacementField& part, std::vector<Streamline>& lines,
                                 const LinkingParams& params) {
  LinkedPaths linked = linkStreamlines(part, lines, params);
  std::vector<Streamline> ordered;
  for (const PathMove& move : linked.moves)
    if (move.kind == MoveKind::Cut)
      ordered.push_back(move.reversed ? reversedStreamline(lines[move.path]) : lines[move.path]);
  lines = std::move(ordered);
  return linked;
}

}  // namespace ddfcam::planning
