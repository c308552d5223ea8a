// SPDX-License-Identifier: MIT
// ddfcam gui: DocumentCommand and the edits of the workbench shell (heights, fields, paths).
#include <ddfcam/error.h>
#include <ddfcam/gui/document_command.h>

#include <string>
#include <utility>

namespace ddfcam::gui {
namespace {

std::size_t fieldBytes(const planning::ScalarField& field) {
  return field.name.capacity() + field.unit.capacity() + field.values.capacity() * sizeof(float);
}

const ddf::DisplacementField& requirePart(const planning::Project& project, const char* what) {
  if (!project.part) throw InvalidInput(std::string(what) + ": the project has no part");
  return *project.part;
}

QString quotedName(const std::string& name) {
  return "'" + QString::fromStdString(name) + "'";
}

}  // namespace

// ---- DocumentCommand ------------------------------------------------------------------------

DocumentCommand::DocumentCommand(Document& document, const QString& text)
    : QUndoCommand(text), document_(document) {}

void DocumentCommand::redo() {
  const Changes changes = apply(document_.editableProject());
  document_.notify(changes);
}

void DocumentCommand::undo() {
  const Changes changes = revert(document_.editableProject());
  document_.notify(changes);
}

std::size_t DocumentCommand::memoryBytes() const {
  return sizeof(*this);
}

// ---- SetHeightsCommand ----------------------------------------------------------------------

SetHeightsCommand::SetHeightsCommand(Document& document, const QString& text,
                                     const std::vector<float>& after,
                                     std::optional<planning::SimulationState> state)
    : DocumentCommand(document, text), state_(std::move(state)) {
  const ddf::DisplacementField& part = requirePart(document.project(), "set heights");
  const std::vector<float>& before = part.allHeights();
  if (after.size() != before.size())
    throw InvalidInput("set heights: " + std::to_string(after.size()) + " values, expected " +
                       std::to_string(before.size()));
  if (state_ && state_->heights.size() != before.size())
    throw InvalidInput("set heights: state '" + state_->name +
                       "': " + std::to_string(state_->heights.size()) + " values, expected " +
                       std::to_string(before.size()));
  delta_ = planning::HeightDelta::between(before, after, part.pointsPerFace());
}

std::size_t SetHeightsCommand::memoryBytes() const {
  std::size_t bytes = sizeof(*this) + delta_.memoryBytes();
  if (state_) bytes += state_->name.capacity() + state_->heights.capacity() * sizeof(float);
  return bytes;
}

Changes SetHeightsCommand::apply(planning::Project& project) {
  if (!project.part) throw InvalidInput("set heights: the project has no part");
  // Everything that can throw happens before the first change, so a refused apply leaves the
  // project as it was.
  if (state_) project.states.reserve(project.states.size() + 1);
  delta_.apply(*project.part);
  Changes changes = Change::Heights;
  if (state_) {
    // Moved, not copied: while applied the state lives only in the project.
    project.states.push_back(std::move(*state_));
    changes |= Change::States;
  }
  return changes;
}

Changes SetHeightsCommand::revert(planning::Project& project) {
  if (!project.part) throw InvalidInput("set heights: the project has no part");
  delta_.revert(*project.part);
  Changes changes = Change::Heights;
  if (state_) {
    *state_ = std::move(project.states.back());
    project.states.pop_back();
    changes |= Change::States;
  }
  return changes;
}

// ---- AddFieldCommand ------------------------------------------------------------------------

AddFieldCommand::AddFieldCommand(Document& document, planning::ScalarField field)
    : DocumentCommand(document, "Add field " + quotedName(field.name)), field_(std::move(field)) {
  const ddf::DisplacementField& part = requirePart(document.project(), "add field");
  if (field_.values.size() != part.allHeights().size())
    throw InvalidInput("field '" + field_.name + "': " + std::to_string(field_.values.size()) +
                       " values, expected " + std::to_string(part.allHeights().size()));
}

std::size_t AddFieldCommand::memoryBytes() const {
  // While applied, an appended field lives in the project and the command holds nothing; a
  // replacing command holds the field it replaced.
  return sizeof(*this) + fieldBytes(field_) + (replaced_ ? fieldBytes(*replaced_) : 0);
}

Changes AddFieldCommand::apply(planning::Project& project) {
  std::vector<planning::ScalarField>& fields = project.fields;
  index_ = -1;
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i].name == field_.name) index_ = static_cast<int>(i);
  if (index_ >= 0) {
    // Swapping keeps one copy of each version and cannot throw.
    std::swap(fields[static_cast<std::size_t>(index_)], field_);
    replaced_.emplace(std::move(field_));
    field_ = {};
  } else {
    fields.push_back(std::move(field_));  // strong guarantee: field_ intact if this throws
    field_ = {};
  }
  return Change::Fields;
}

Changes AddFieldCommand::revert(planning::Project& project) {
  std::vector<planning::ScalarField>& fields = project.fields;
  if (index_ < 0) {
    field_ = std::move(fields.back());
    fields.pop_back();
  } else {
    field_ = std::move(fields[static_cast<std::size_t>(index_)]);
    fields[static_cast<std::size_t>(index_)] = std::move(*replaced_);
    replaced_.reset();
  }
  return Change::Fields;
}

// ---- RemoveFieldCommand ---------------------------------------------------------------------

RemoveFieldCommand::RemoveFieldCommand(Document& document, int index)
    : DocumentCommand(document, {}), index_(index) {
  const std::vector<planning::ScalarField>& fields = document.project().fields;
  if (index < 0 || index >= static_cast<int>(fields.size()))
    throw InvalidInput("remove field: index " + std::to_string(index) + " out of range (" +
                       std::to_string(fields.size()) + " fields)");
  setText("Remove field " + quotedName(fields[static_cast<std::size_t>(index)].name));
}

std::size_t RemoveFieldCommand::memoryBytes() const {
  return sizeof(*this) + fieldBytes(removed_);
}

Changes RemoveFieldCommand::apply(planning::Project& project) {
  std::vector<planning::ScalarField>& fields = project.fields;
  if (index_ < 0 || index_ >= static_cast<int>(fields.size()))
    throw InvalidInput("remove field: index " + std::to_string(index_) + " out of range");
  removed_ = std::move(fields[static_cast<std::size_t>(index_)]);
  fields.erase(fields.begin() + index_);
  return Change::Fields;
}

Changes RemoveFieldCommand::revert(planning::Project& project) {
  project.fields.insert(project.fields.begin() + index_, std::move(removed_));
  removed_ = {};
  return Change::Fields;
}

// ---- AddPathCommand -------------------------------------------------------------------------

AddPathCommand::AddPathCommand(Document& document, planning::ToolPath path,
                               std::optional<planning::Tool> tool)
    : DocumentCommand(document, "Add path " + quotedName(path.name)),
      path_(std::move(path)),
      tool_(std::move(tool)) {
  // Check the path by the project's own rules, against the tools it will see once applied.
  planning::Project probe;
  probe.tools = document.project().tools;
  if (tool_) {
    planning::toolMesh(*tool_);  // refuses unusable sizes, naming the tool
    path_.tool = static_cast<int>(probe.tools.size());
    probe.tools.push_back(*tool_);
  }
  probe.paths.push_back(path_);
  planning::validateProject(probe);
}

std::size_t AddPathCommand::memoryBytes() const {
  std::size_t bytes = sizeof(*this) + path_.name.capacity() +
                      path_.poses.capacity() * sizeof(planning::PathPose) +
                      path_.passStarts.capacity() * sizeof(int) +
                      planning::rawLinesBytes(path_);
  if (tool_) bytes += tool_->name.capacity();
  return bytes;
}

Changes AddPathCommand::apply(planning::Project& project) {
  Changes changes = Change::Paths;
  if (tool_) {
    project.tools.reserve(project.tools.size() + 1);
    project.paths.reserve(project.paths.size() + 1);
    path_.tool = static_cast<int>(project.tools.size());
    project.tools.push_back(std::move(*tool_));
    changes |= Change::Tools;
  }
  project.paths.push_back(std::move(path_));
  path_ = {};
  return changes;
}

Changes AddPathCommand::revert(planning::Project& project) {
  path_ = std::move(project.paths.back());
  project.paths.pop_back();
  if (tool_) {
    *tool_ = std::move(project.tools.back());
    project.tools.pop_back();
  }
  return Change::Paths | (tool_ ? Change::Tools : Change{});
}

}  // namespace ddfcam::gui
