// SPDX-License-Identifier: MIT
// ddfcam: traced lines made ready for tool placement: cleaned, ordered and oriented for cutting.
#include <ddfcam/planning/lines/line_ordering.h>

#include <algorithm>
#include <utility>

namespace ddfcam::planning {

void dropRepeatedPoints(Streamline& line) {
  constexpr double kEpsMm = 1e-6;
  const auto same = [](const ddf::SurfaceLocation& a, const ddf::SurfaceLocation& b) {
    return (a.point - b.point).norm() <= kEpsMm;
  };
  const std::size_t seedIn =
      std::min(line.seedIndex, std::max<std::size_t>(line.points.size(), 1) - 1);
  std::vector<ddf::SurfaceLocation> kept;
  std::size_t seed = 0;  // where the seed, or the point kept in its place, ends up
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    const ddf::SurfaceLocation& q = line.points[i];
    if (kept.size() >= 2 && !same(q, kept.back()) && same(q, kept[kept.size() - 2])) {
      kept.pop_back();
      seed = std::min(seed, kept.size() - 1);
    } else if (kept.empty() || !same(q, kept.back())) {
      kept.push_back(q);
    }
    if (i == seedIn) seed = kept.size() - 1;
  }
  line.points = std::move(kept);
  line.seedIndex = seed;
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
