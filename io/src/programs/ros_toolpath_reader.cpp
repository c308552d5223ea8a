// SPDX-License-Identifier: MIT
// ddfcam: reading ROS-Industrial tool paths saved as YAML (paths of geometry_msgs poses).
#include <ddfcam/io/programs/ros_toolpath_reader.h>

#include <ddfcam/error.h>

#include <Eigen/Geometry>

#include <charconv>
#include <cmath>
#include <cstdint>

#include "../common/file_access.h"
#include "path_file_limits.h"
#include "yaml_subset.h"

namespace ddfcam::io {
namespace {

using detail::YamlKind;
using detail::YamlNode;

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{1} << 30;

class PoseReader {
 public:
  explicit PoseReader(const std::string& name) : name_(name) {
    program_.sourceUnit = LengthUnit::Metre;
    program_.pointKind = planning::ClPointKind::ToolReference;
  }

  planning::ClProgram read(const YamlNode& root) {
    if (root.kind == YamlKind::Mapping && root.find("paths")) {
      readEntry(root);
    } else if (root.kind == YamlKind::Sequence) {
      for (const YamlNode& entry : root.items) readEntry(entry);
    } else {
      fail(root.line, "not a ROS toolpath (expected a list of entries with 'paths:')");
    }
    if (program_.points.empty()) throw IoError(name_ + ": no poses in the document");
    return std::move(program_);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw IoError(name_ + ": line " + std::to_string(line) + ": " + what);
  }

  const YamlNode& require(const YamlNode& map, std::string_view key,
                          std::string_view context) const {
    if (map.kind != YamlKind::Mapping)
      fail(map.line, "expected a mapping for " + std::string(context));
    const YamlNode* value = map.find(key);
    if (!value) fail(map.line, "missing '" + std::string(key) + "' in " + std::string(context));
    return *value;
  }

  const YamlNode& requireSequence(const YamlNode& map, std::string_view key,
                                  std::string_view context) const {
    const YamlNode& value = require(map, key, context);
    if (value.kind != YamlKind::Sequence) {
      std::string what = "'";  // appended piecewise: GCC 12 -Wrestrict false positive
      what += key;
      what += "' must be a list";
      fail(value.line, what);
    }
    return value;
  }

  double number(const YamlNode& map, std::string_view key, std::string_view context) const {
    const YamlNode& value = require(map, key, context);
    if (value.kind != YamlKind::Scalar || value.quoted)
      fail(value.line,
           "expected a number for '" + std::string(key) + "' in " + std::string(context));
    std::string_view t = value.text;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    double result = 0.0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), result);
    if (ec != std::errc() || end != t.data() + t.size() || t.empty() || !std::isfinite(result))
      fail(value.line, "expected a number for '" + std::string(key) + "', found '" +
                           value.text.substr(0, 40) + "'");
    return result;
  }

  /// Coordinate @p key ("x", "y" or "z") of @p position (metres) in mm, checked after the
  /// conversion; errors name the coordinate's line.
  double millimetres(const YamlNode& position, std::string_view key) const {
    const double mm = number(position, key, "a position") * millimetresPer(LengthUnit::Metre);
    ddf::Vec3 alone = ddf::Vec3::Zero();  // the message names the coordinate by its slot
    alone[key[0] - 'x'] = mm;
    if (const auto problem = detail::positionProblem(alone))
      fail(require(position, key, "a position").line, *problem);
    return mm;
  }

  void readEntry(const YamlNode& entry) {
    for (const YamlNode& path : requireSequence(entry, "paths", "a toolpath entry").items)
      readPath(path);
  }

  void readPath(const YamlNode& path) {
    const YamlNode& poses = requireSequence(path, "poses", "a path");
    keepFrameId(path);
    if (poses.items.empty()) {
      program_.warnings.push_back({poses.line, "empty 'poses' list skipped"});
      return;
    }
    int index = 0;
    for (const YamlNode& pose : poses.items) readPose(pose, index++);
    ++pathIndex_;
  }

  void keepFrameId(const YamlNode& path) {
    if (frameKept_) return;
    const YamlNode* header = path.find("header");
    const YamlNode* frame = header ? header->find("frame_id") : nullptr;
    if (frame && frame->kind == YamlKind::Scalar) {
      program_.comments.push_back("frame_id: " + frame->text);
      frameKept_ = true;
    }
  }

  void readPose(const YamlNode& pose, int index) {
    const YamlNode& position = require(pose, "position", "a pose");
    const YamlNode& orientation = require(pose, "orientation", "a pose");
    planning::ClPoint point;
    point.path = pathIndex_;
    point.point = index;
    point.positionMm = ddf::Vec3(millimetres(position, "x"), millimetres(position, "y"),
                                 millimetres(position, "z"));
    point.axis = toolAxis(orientation);
    point.move = planning::MoveKind::Cut;
    point.sourceLine = pose.line;
    program_.points.push_back(std::move(point));
  }

  /// The tool axis (+z of the pose) of the quaternion @p orientation, normalised without
  /// overflow: the coefficients are scaled by the largest one first.
  ddf::Vec3 toolAxis(const YamlNode& orientation) {
    const auto coefficient = [&](std::string_view key) {
      return number(orientation, key, "an orientation");
    };
    Eigen::Vector4d c(coefficient("x"), coefficient("y"), coefficient("z"), coefficient("w"));
    const double largest = c.cwiseAbs().maxCoeff();
    const double norm = largest > 0.0 ? largest * (c / largest).norm() : 0.0;
    if (!(norm > 1e-9)) fail(orientation.line, "zero quaternion: the tool axis is undefined");
    if (std::abs(norm - 1.0) > 1e-3)
      program_.warnings.push_back(
          {orientation.line, "quaternion of length " + std::to_string(norm) + " normalised"});
    c /= largest;
    c.normalize();
    const Eigen::Quaterniond q(c[3], c[0], c[1], c[2]);
    return (q * ddf::Vec3::UnitZ()).normalized();
  }

  const std::string& name_;
  planning::ClProgram program_;
  int pathIndex_ = 0;
  bool frameKept_ = false;
};

}  // namespace

planning::ClProgram decodeRosToolpathYaml(std::string_view text, const std::string& sourceName) {
  const YamlNode root = detail::parseYamlSubset(text, sourceName);
  return PoseReader(sourceName).read(root);
}

planning::ClProgram readRosToolpathYaml(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxFileBytes)
    throw IoError(file.string() + ": file larger than 1 GiB, refused as a tool path");
  planning::ClProgram program = decodeRosToolpathYaml(detail::readFileBytes(file), file.string());
  if (program.partName.empty()) program.partName = file.stem().string();
  return program;
}

}  // namespace ddfcam::io
