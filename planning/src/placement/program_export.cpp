// SPDX-License-Identifier: MIT
// ddfcam: a project's selected tool paths grouped into cutter-location programs (all in one,
// per region, per tool) with normals from the part's surface.
#include <ddfcam/planning/placement/cl_program_builder.h>

#include <ddfcam/ddf/surface_locator.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/model/path_regions.h>
#include <ddfcam/planning/placement/path_sampling.h>

#include <algorithm>
#include <optional>
#include <string>

namespace ddfcam::planning {
namespace {

struct Group {
  std::string name;
  std::vector<int> paths;  ///< indices into Project::paths, project order
};

void checkIndices(const std::vector<int>& indices, std::size_t size, const char* what) {
  for (const int i : indices)
    if (i < 0 || static_cast<std::size_t>(i) >= size)
      throw InvalidInput(std::string("export: ") + what + " index " + std::to_string(i) +
                         " out of range (" + std::to_string(size) + " " + what + "s)");
}

bool listed(const std::vector<int>& list, int value) {
  return list.empty() || std::find(list.begin(), list.end(), value) != list.end();
}

/// Region of every path (-1 for all when the grouping does not need them or there is no part).
std::vector<int> regionsOfPaths(const Project& project, const ExportSelection& s) {
  const bool needed = s.perRegion || !s.regions.empty();
  if (!needed || !project.part || project.regions.empty())
    return std::vector<int>(project.paths.size(), -1);
  return pathRegions(*project.part, project.regions, project.paths);
}

std::vector<Group> groupsOf(const Project& project, const ExportSelection& s) {
  const std::vector<int> region = regionsOfPaths(project, s);
  std::vector<int> selected;
  for (std::size_t p = 0; p < project.paths.size(); ++p) {
    const int index = static_cast<int>(p);
    const bool regionOk = s.regions.empty() || (region[p] >= 0 && listed(s.regions, region[p]));
    if (listed(s.paths, index) && regionOk && !project.paths[p].poses.empty())
      selected.push_back(index);
  }
  if (!s.perRegion) return {{project.partName.empty() ? "paths" : project.partName, selected}};
  std::vector<Group> groups;
  for (std::size_t r = 0; r < project.regions.size(); ++r) {
    Group group{project.regions[r].name, {}};
    for (const int p : selected)
      if (region[static_cast<std::size_t>(p)] == static_cast<int>(r)) group.paths.push_back(p);
    if (!group.paths.empty()) groups.push_back(std::move(group));
  }
  Group unassigned{"unassigned", {}};
  for (const int p : selected)
    if (region[static_cast<std::size_t>(p)] < 0) unassigned.paths.push_back(p);
  if (!unassigned.paths.empty()) groups.push_back(std::move(unassigned));
  return groups;
}

/// Splits @p group per tool (order of first use) when its paths use several tools.
std::vector<Group> splitPerTool(const Project& project, const Group& group) {
  std::vector<int> tools;
  for (const int p : group.paths) {
    const int tool = project.paths[static_cast<std::size_t>(p)].tool;
    if (tool < 0 || static_cast<std::size_t>(tool) >= project.tools.size())
      throw InvalidInput("export: path '" + project.paths[static_cast<std::size_t>(p)].name +
                         "' uses tool " + std::to_string(tool) + " of " +
                         std::to_string(project.tools.size()));
    if (std::find(tools.begin(), tools.end(), tool) == tools.end()) tools.push_back(tool);
  }
  if (tools.size() <= 1) return {group};
  std::vector<Group> split;
  for (const int tool : tools) {
    Group g{group.name + " T" + std::to_string(tool + 1), {}};
    for (const int p : group.paths)
      if (project.paths[static_cast<std::size_t>(p)].tool == tool) g.paths.push_back(p);
    split.push_back(std::move(g));
  }
  return split;
}

/// Per pose: the part's smooth normal at the located contact, else the derived one (also when
/// the located normal faces away from the tool, e.g. the contact found on a thin wall's far
/// side, as far as the derived normal tells).
std::vector<ddf::Vec3> normalsOf(const Project& project,
                                 const std::optional<ddf::SurfaceLocator>& locator,
                                 const ToolPath& path, const Tool& tool) {
  std::vector<ddf::Vec3> normals;
  normals.reserve(path.poses.size());
  for (std::size_t i = 0; i < path.poses.size(); ++i) {
    const PathPose& pose = path.poses[i];
    const int index = static_cast<int>(i);
    std::optional<ddf::Vec3> located;
    if (locator)
      if (const auto location = locator->locate(pose.contact))
        located = smoothSurfaceNormal(*project.part, *location);
    if (!located || !located->allFinite()) {
      normals.push_back(derivedContactNormal(pose, tool, index));
      continue;
    }
    try {
      const ddf::Vec3 derived = derivedContactNormal(pose, tool, index);
      normals.push_back(located->dot(derived) > 0.0 ? *located : derived);
    } catch (const InvalidInput&) {
      normals.push_back(*located);  // the tool's geometry does not tell; trust the part
    }
  }
  return normals;
}

}  // namespace

std::vector<NamedProgram> programsForExport(const Project& project,
                                            const ExportSelection& selection) {
  checkIndices(selection.regions, project.regions.size(), "region");
  checkIndices(selection.paths, project.paths.size(), "path");
  std::optional<ddf::SurfaceLocator> locator;
  if (project.part) locator.emplace(*project.part);
  std::vector<NamedProgram> programs;
  for (const Group& regionGroup : groupsOf(project, selection))
    for (const Group& group : splitPerTool(project, regionGroup)) {
      if (group.paths.empty()) continue;
      const int toolIndex = project.paths[static_cast<std::size_t>(group.paths.front())].tool;
      const Tool& tool = project.tools[static_cast<std::size_t>(toolIndex)];
      NamedProgram named{group.name, {}};
      ClProgram& program = named.program;
      program.partName = group.name;
      program.pointKind = selection.pointKind;
      program.toolNumber = toolIndex + 1;
      program.toolName = tool.name;
      program.cutter = clCutterOf(tool);
      for (const int p : group.paths) {
        const ToolPath& path = project.paths[static_cast<std::size_t>(p)];
        const ClProgram one =
            clProgramFromPath(path, tool, selection.pointKind,
                              normalsOf(project, locator, path, tool), selection.link);
        appendClProgram(program, one, selection.link);
      }
      if (!program.points.empty()) programs.push_back(std::move(named));
    }
  return programs;
}

}  // namespace ddfcam::planning
