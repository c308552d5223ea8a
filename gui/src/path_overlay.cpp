// SPDX-License-Identifier: MIT
// ddfcam gui: pathOverlayLines and the looks of the path overlays.
#include <ddfcam/gui/path_overlay.h>

#include <array>
#include <cstddef>

namespace ddfcam::gui {

namespace {

// The passes of @p path as contact polylines; the links between them as 2-point lines.
void addPath(const planning::ToolPath& path,
             std::vector<std::vector<Eigen::Vector3d>>& passes,
             std::vector<std::vector<Eigen::Vector3d>>* links) {
  for (std::size_t s = 0; s < path.passStarts.size(); ++s) {
    const auto begin = static_cast<std::size_t>(path.passStarts[s]);
    const std::size_t end = s + 1 < path.passStarts.size()
                                ? static_cast<std::size_t>(path.passStarts[s + 1])
                                : path.poses.size();
    if (begin >= end) continue;
    std::vector<Eigen::Vector3d>& line = passes.emplace_back();
    for (std::size_t i = begin; i < end; ++i) line.push_back(path.poses[i].contact);
    if (links && begin > 0) links->push_back({path.poses[begin - 1].contact, path.poses[begin].contact});
  }
}

OverlayStyle onTopLine(const std::array<double, 3>& rgb, double widthPx) {
  OverlayStyle style;
  style.rgb = rgb;
  style.lineWidth = widthPx;
  style.onTop = true;
  return style;
}

}  // namespace

PathOverlayLines pathOverlayLines(const planning::Project& project,
                                  const std::set<std::string>& hidden, int selected) {
  PathOverlayLines out;
  for (std::size_t p = 0; p < project.paths.size(); ++p) {
    const planning::ToolPath& path = project.paths[p];
    if (hidden.count(path.name)) continue;
    addPath(path, out.cuts, &out.links);
    if (static_cast<int>(p) == selected) addPath(path, out.selected, nullptr);
  }
  return out;
}

OverlayStyle pathCutStyle() {
  return onTopLine({0.97, 0.97, 0.97}, 2.5);
}

OverlayStyle pathLinkStyle() {
  return onTopLine({0.08, 0.08, 0.1}, 1.2);
}

OverlayStyle selectedPathStyle() {
  return onTopLine({1.0, 0.9, 0.0}, 4.5);
}

}  // namespace ddfcam::gui
