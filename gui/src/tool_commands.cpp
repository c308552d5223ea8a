// SPDX-License-Identifier: MIT
// ddfcam gui: SetToolsCommand.
#include <ddfcam/gui/tool_commands.h>

#include <ddfcam/error.h>

#include <string>
#include <utility>

namespace ddfcam::gui {

namespace {

std::vector<int> identityMap(std::size_t oldCount, std::size_t newCount) {
  std::vector<int> map(oldCount, -1);
  for (std::size_t i = 0; i < oldCount && i < newCount; ++i) map[i] = static_cast<int>(i);
  return map;
}

}  // namespace

SetToolsCommand::SetToolsCommand(Document& document, std::vector<planning::Tool> tools,
                                 std::vector<int> newIndexOfOld, const QString& text)
    : DocumentCommand(document, text), other_(std::move(tools)) {
  const planning::Project& project = document.project();
  for (const planning::Tool& t : other_) planning::validateTool(t);
  if (newIndexOfOld.empty()) newIndexOfOld = identityMap(project.tools.size(), other_.size());
  if (newIndexOfOld.size() != project.tools.size())
    throw InvalidInput("set tools: " + std::to_string(newIndexOfOld.size()) +
                       " index entries for " + std::to_string(project.tools.size()) + " tools");
  for (const int i : newIndexOfOld)
    if (i < -1 || i >= static_cast<int>(other_.size()))
      throw InvalidInput("set tools: tool index " + std::to_string(i) + " out of range");
  for (const planning::ToolPath& path : project.paths) {
    pathToolsBefore_.push_back(path.tool);
    const bool known = path.tool >= 0 && path.tool < static_cast<int>(newIndexOfOld.size());
    const int mapped = known ? newIndexOfOld[static_cast<std::size_t>(path.tool)] : -1;
    if (mapped < 0)
      throw InvalidInput("tool " + std::to_string(path.tool) + " is used by path '" + path.name +
                         "'; delete or change the path first");
    pathToolsAfter_.push_back(mapped);
  }
}

std::size_t SetToolsCommand::memoryBytes() const {
  return sizeof(*this) + other_.capacity() * sizeof(planning::Tool) +
         (pathToolsBefore_.capacity() + pathToolsAfter_.capacity()) * sizeof(int);
}

Changes SetToolsCommand::apply(planning::Project& project) {
  std::swap(project.tools, other_);
  for (std::size_t i = 0; i < project.paths.size(); ++i) project.paths[i].tool = pathToolsAfter_[i];
  return Changes(Change::Tools) | Change::Paths;
}

Changes SetToolsCommand::revert(planning::Project& project) {
  std::swap(project.tools, other_);
  for (std::size_t i = 0; i < project.paths.size(); ++i)
    project.paths[i].tool = pathToolsBefore_[i];
  return Changes(Change::Tools) | Change::Paths;
}

std::vector<planning::Tool> toolsWithAppended(const planning::Project& project,
                                              const planning::Tool& tool) {
  std::vector<planning::Tool> tools = project.tools;
  tools.push_back(tool);
  return tools;
}

}  // namespace ddfcam::gui
