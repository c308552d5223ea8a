// SPDX-License-Identifier: MIT
// ddfcam: encoding and bounds-checked decoding of the .ddfproj chunk payloads.
#include "project_chunks.h"

#include <ddfcam/error.h>

#include "../common/byte_codec.h"

#include <limits>
#include <utility>

namespace ddfcam::io::detail {
namespace {

constexpr std::size_t kPoseBytes = 19 * 8;

void putI32(std::string& out, int value) {
  putU32(out, static_cast<std::uint32_t>(value));
}

void putCount(std::string& out, std::size_t count) {
  putU64(out, static_cast<std::uint64_t>(count));
}

void putPose(std::string& out, const planning::PathPose& pose) {
  const Eigen::Matrix4d& m = pose.pose.matrix();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) putF64(out, m(r, c));
  putVec3(out, pose.contact);
}

planning::PathPose readPose(PayloadReader& in) {
  planning::PathPose pose;
  Eigen::Matrix4d& m = pose.pose.matrix();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m(r, c) = in.f64("pose matrix");
  pose.contact = readVec3(in, "pose contact");
  return pose;
}

}  // namespace

void putVec3(std::string& out, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) putF64(out, v[i]);
}

Eigen::Vector3d readVec3(PayloadReader& in, const char* what) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = in.f64(what);
  return v;
}

std::vector<int> readIntList(PayloadReader& in, const char* what) {
  std::vector<int> out(in.count(4, what));
  for (int& value : out) value = in.i32(what);
  return out;
}

std::vector<float> readFloatList(PayloadReader& in, const char* what) {
  std::vector<float> out(in.count(4, what));
  for (float& value : out) value = in.f32(what);
  return out;
}

void putIntList(std::string& out, const std::vector<int>& values) {
  putCount(out, values.size());
  for (const int value : values) putI32(out, value);
}

void putFloatList(std::string& out, const std::vector<float>& values) {
  putCount(out, values.size());
  for (const float value : values) putF32(out, value);
}

const char* PayloadReader::take(std::size_t bytes, const char* what) {
  if (rest_.size() < bytes)
    fail("the payload ends in the " + std::string(what) + " (" + std::to_string(bytes) +
         " bytes needed, " + std::to_string(rest_.size()) + " left)");
  const char* at = rest_.data();
  rest_.remove_prefix(bytes);
  return at;
}

std::uint8_t PayloadReader::u8(const char* what) {
  return static_cast<std::uint8_t>(*take(1, what));
}
std::int32_t PayloadReader::i32(const char* what) {
  return static_cast<std::int32_t>(getU32(take(4, what)));
}
std::uint64_t PayloadReader::u64(const char* what) {
  return getU64(take(8, what));
}
float PayloadReader::f32(const char* what) {
  return getF32(take(4, what));
}
double PayloadReader::f64(const char* what) {
  return getF64(take(8, what));
}

std::string PayloadReader::string(const char* what) {
  const std::uint32_t length = getU32(take(4, what));
  if (length > rest_.size())
    fail("the " + std::string(what) + " claims " + std::to_string(length) + " bytes, only " +
         std::to_string(rest_.size()) + " are left");
  return std::string(take(length, what), length);
}

std::size_t PayloadReader::count(std::size_t elementBytes, const char* what) {
  const std::uint64_t n = u64(what);
  if (n > rest_.size() / elementBytes)
    fail("the " + std::string(what) + " count " + std::to_string(n) + " needs more than the " +
         std::to_string(rest_.size()) + " bytes left");
  return static_cast<std::size_t>(n);
}

std::string_view PayloadReader::rest() {
  return std::exchange(rest_, std::string_view{});
}

void PayloadReader::finish() const {
  if (!rest_.empty())
    fail(std::to_string(rest_.size()) + " unexpected bytes at the end of the payload");
}

void PayloadReader::fail(const std::string& what) const {
  throw IoError(context_ + ": " + what);
}

void putString(std::string& out, std::string_view text) {
  if (text.size() > std::numeric_limits<std::uint32_t>::max())
    throw InvalidInput("a name of " + std::to_string(text.size()) + " bytes is too long to save");
  putU32(out, static_cast<std::uint32_t>(text.size()));
  out.append(text);
}

void putProjectInfo(std::string& out, const planning::Project& project) {
  putString(out, project.partName);
  putString(out, project.sourcePath);
}

void readProjectInfo(PayloadReader& in, planning::Project& project) {
  project.partName = in.string("part name");
  project.sourcePath = in.string("source path");
}

void putDesignMesh(std::string& out, const ddf::TriangleMesh& mesh) {
  putCount(out, mesh.vertices.size());
  putCount(out, mesh.triangles.size());
  for (const Eigen::Vector3d& v : mesh.vertices) putVec3(out, v);
  for (const auto& triangle : mesh.triangles)
    for (const int v : triangle) putI32(out, v);
}

ddf::TriangleMesh readDesignMesh(PayloadReader& in) {
  const std::uint64_t vertices = in.u64("design mesh vertex count");
  const std::uint64_t triangles = in.u64("design mesh triangle count");
  const std::size_t left = in.left();
  // Checked before allocating; after the first test the subtraction cannot wrap.
  if (vertices > left / 24 || triangles > (left - vertices * 24) / 12)
    in.fail("the design mesh claims " + std::to_string(vertices) + " vertices and " +
            std::to_string(triangles) + " triangles, more than the " + std::to_string(left) +
            " bytes left");
  ddf::TriangleMesh mesh;
  mesh.vertices.resize(vertices);
  for (Eigen::Vector3d& v : mesh.vertices) v = readVec3(in, "design mesh vertex");
  mesh.triangles.resize(triangles);
  for (auto& triangle : mesh.triangles)
    for (int& v : triangle) v = in.i32("design mesh triangle");
  return mesh;
}

void putField(std::string& out, const planning::ScalarField& field) {
  putString(out, field.name);
  putString(out, field.unit);
  out += static_cast<char>(field.isSigned ? 1 : 0);
  putFloatList(out, field.values);
}

planning::ScalarField readField(PayloadReader& in) {
  planning::ScalarField field;
  field.name = in.string("field name");
  field.unit = in.string("field unit");
  const std::uint8_t isSigned = in.u8("signed flag");
  if (isSigned > 1)
    in.fail("field '" + field.name + "': signed flag " + std::to_string(isSigned) +
            " is neither 0 nor 1");
  field.isSigned = isSigned == 1;
  field.values = readFloatList(in, "field values");
  return field;
}

void putFieldDigest(std::string& out, int fieldIndex, std::uint64_t digest) {
  putI32(out, fieldIndex);
  putU64(out, digest);
}

void readFieldDigest(PayloadReader& in, std::vector<planning::ScalarField>& fields) {
  const std::int32_t index = in.i32("field index");
  if (index < 0 || static_cast<std::size_t>(index) >= fields.size())
    in.fail("heights digest of field " + std::to_string(index) + ", but " +
            std::to_string(fields.size()) + " fields come before it");
  planning::ScalarField& field = fields[static_cast<std::size_t>(index)];
  if (field.heightsDigest) in.fail("a second heights digest of field '" + field.name + "'");
  field.heightsDigest = in.u64("heights digest");
}

void putPlan(std::string& out, const planning::RegionPlan& plan) {
  putI32(out, plan.tool);
  putI32(out, static_cast<int>(plan.flowSource));
  putVec3(out, plan.fixedDirection);
  out += static_cast<char>(plan.smoothField ? 1 : 0);
  putF64(out, plan.smoothnessWeight);
  putI32(out, static_cast<int>(plan.spacingMode));
  putF64(out, plan.spacingMm);
  putF64(out, plan.scallopToleranceMm);
  putI32(out, plan.feedSign);
  putI32(out, static_cast<int>(plan.linking));
  putCount(out, plan.strokes.size());
  for (const std::vector<ddf::Vec3>& stroke : plan.strokes) {
    putCount(out, stroke.size());
    for (const ddf::Vec3& point : stroke) putVec3(out, point);
  }
}

// Enum values are stored as read; validateProject rejects unknown ones, naming the region.
planning::RegionPlan readPlan(PayloadReader& in, const std::string& region) {
  planning::RegionPlan plan;
  plan.tool = in.i32("plan tool index");
  plan.flowSource = static_cast<planning::FlowFieldSource>(in.i32("plan flow source"));
  plan.fixedDirection = readVec3(in, "plan fixed direction");
  const std::uint8_t smooth = in.u8("plan smoothing flag");
  if (smooth > 1)
    in.fail("region '" + region + "': smoothing flag " + std::to_string(smooth) +
            " is neither 0 nor 1");
  plan.smoothField = smooth == 1;
  plan.smoothnessWeight = in.f64("plan smoothness weight");
  plan.spacingMode = static_cast<planning::SpacingMode>(in.i32("plan spacing mode"));
  plan.spacingMm = in.f64("plan spacing");
  plan.scallopToleranceMm = in.f64("plan scallop tolerance");
  plan.feedSign = in.i32("plan feed sign");
  plan.linking = static_cast<planning::LinkingOrder>(in.i32("plan linking order"));
  // An empty stroke takes 8 bytes, which bounds the stroke count before allocating.
  plan.strokes.resize(in.count(8, "plan stroke"));
  for (std::vector<ddf::Vec3>& stroke : plan.strokes) {
    stroke.resize(in.count(24, "plan stroke point"));
    for (ddf::Vec3& point : stroke) point = readVec3(in, "plan stroke point");
  }
  return plan;
}

void putRegion(std::string& out, const planning::Region& region) {
  putString(out, region.name);
  for (const float c : region.color) putF32(out, c);
  putIntList(out, region.faces);
  putPlan(out, region.plan);
}

planning::Region readRegion(PayloadReader& in, std::uint32_t formatVersion) {
  planning::Region region;
  region.name = in.string("region name");
  for (float& c : region.color) c = in.f32("region colour");
  region.faces = readIntList(in, "region faces");
  // Version 1 regions carry no plan; they get the default one.
  if (formatVersion >= 2) region.plan = readPlan(in, region.name);
  return region;
}

void putTool(std::string& out, const planning::Tool& tool) {
  putString(out, tool.name);
  putI32(out, static_cast<int>(tool.kind));
  putF64(out, tool.radiusMm);
  putF64(out, tool.widthMm);
  putI32(out, tool.segments);
  for (const double value :
       {tool.edgeRadiusMm, tool.crownRadiusMm, tool.shankRadiusMm, tool.shankLengthMm,
        tool.holderRadiusMm, tool.holderLengthMm, tool.chordToleranceMm})
    putF64(out, value);
}

planning::Tool readTool(PayloadReader& in, std::uint32_t formatVersion) {
  planning::Tool tool;
  tool.name = in.string("tool name");
  // Any int is a representable ToolKind; validateTool rejects the unknown ones by name.
  tool.kind = static_cast<planning::ToolKind>(in.i32("tool kind"));
  tool.radiusMm = in.f64("tool radius");
  tool.widthMm = in.f64("tool width");
  tool.segments = in.i32("tool segments");
  // Before version 3 tools were bare rolls and balls: the other fields keep their defaults.
  if (formatVersion >= 3) {
    tool.edgeRadiusMm = in.f64("tool edge radius");
    tool.crownRadiusMm = in.f64("tool crown radius");
    tool.shankRadiusMm = in.f64("tool shank radius");
    tool.shankLengthMm = in.f64("tool shank length");
    tool.holderRadiusMm = in.f64("tool holder radius");
    tool.holderLengthMm = in.f64("tool holder length");
    tool.chordToleranceMm = in.f64("tool chord tolerance");
  }
  return tool;
}

void putPath(std::string& out, const planning::ToolPath& path) {
  putString(out, path.name);
  putI32(out, path.tool);
  putF64(out, path.feedMmPerMin);
  putCount(out, path.poses.size());
  for (const planning::PathPose& pose : path.poses) putPose(out, pose);
  putIntList(out, path.passStarts);
}

planning::ToolPath readPath(PayloadReader& in) {
  planning::ToolPath path;
  path.name = in.string("path name");
  path.tool = in.i32("path tool index");
  path.feedMmPerMin = in.f64("path feed");
  path.poses.resize(in.count(kPoseBytes, "path poses"));
  for (planning::PathPose& pose : path.poses) pose = readPose(in);
  path.passStarts = readIntList(in, "pass starts");
  return path;
}

void putState(std::string& out, const planning::SimulationState& state) {
  putString(out, state.name);
  putFloatList(out, state.heights);
}

planning::SimulationState readState(PayloadReader& in) {
  planning::SimulationState state;
  state.name = in.string("state name");
  state.heights = readFloatList(in, "state heights");
  return state;
}

}  // namespace ddfcam::io::detail
