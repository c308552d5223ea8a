// SPDX-License-Identifier: MIT
// ddfcam: machine files (JSON) through nlohmann-json.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/machine_file.h>

#include "../common/file_access.h"

#include <nlohmann/json.hpp>

#include <array>
#include <set>

namespace ddfcam::io {
namespace {

using nlohmann::json;
using planning::RotarySolution;

constexpr std::uintmax_t kMaxMachineFileBytes = std::uintmax_t{1} << 20;

const std::set<std::string> kKeys = {
    "name",      "description",      "rotary_axes",     "tilt_direction",        "rotary_direction",
    "pivot_mm",  "rotary_offset_mm", "tilt_limits_deg", "rotary_limits_deg",     "solution",
    "positions", "tcp_on",           "tcp_off",         "singular_tolerance_deg"};

/// Reads the JSON document and the keys of one machine file, failing with its name.
class MachineReader {
 public:
  MachineReader(const json& doc, std::string source) : doc_(doc), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& what) const { throw IoError(source_ + ": " + what); }

  const json* find(const char* key) const {
    const auto it = doc_.find(key);
    return it == doc_.end() ? nullptr : &*it;
  }

  std::string text(const char* key, std::string fallback) const {
    const json* v = find(key);
    if (!v) return fallback;
    if (!v->is_string()) fail(std::string("\"") + key + "\" must be a string");
    return v->get<std::string>();
  }

  double number(const char* key, double fallback) const {
    const json* v = find(key);
    if (!v) return fallback;
    if (!v->is_number()) fail(std::string("\"") + key + "\" must be a number");
    return v->get<double>();
  }

  double direction(const char* key) const {
    const double d = number(key, 1.0);
    if (d != 1.0 && d != -1.0) fail(std::string("\"") + key + "\" must be 1 or -1");
    return d;
  }

  template <std::size_t N>
  std::optional<std::array<double, N>> numbers(const char* key) const {
    const json* v = find(key);
    if (!v || v->is_null()) return std::nullopt;
    if (!v->is_array() || v->size() != N)
      fail(std::string("\"") + key + "\" must be an array of " + std::to_string(N) + " numbers");
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
      if (!(*v)[i].is_number()) fail(std::string("\"") + key + "\" must hold numbers");
      out[i] = (*v)[i].get<double>();
    }
    return out;
  }

 private:
  const json& doc_;
  std::string source_;
};

RotarySolution solutionNamed(const MachineReader& r, const std::string& name) {
  if (name == "nearest") return RotarySolution::Nearest;
  if (name == "positive-tilt") return RotarySolution::PositiveTilt;
  if (name == "negative-tilt") return RotarySolution::NegativeTilt;
  r.fail("\"solution\": '" + name + "' is not nearest, positive-tilt or negative-tilt");
}

std::string solutionName(RotarySolution s) {
  switch (s) {
    case RotarySolution::PositiveTilt:
      return "positive-tilt";
    case RotarySolution::NegativeTilt:
      return "negative-tilt";
    case RotarySolution::Nearest:
      break;
  }
  return "nearest";
}

planning::TableKinematics readKinematics(const MachineReader& r) {
  planning::TableKinematics k;
  const std::string axes = r.text("rotary_axes", "AC");
  if (axes != "AC" && axes != "BC") r.fail("\"rotary_axes\": '" + axes + "' is not AC or BC");
  k.pair = axes == "AC" ? planning::RotaryPair::AC : planning::RotaryPair::BC;
  k.tiltDirection = r.direction("tilt_direction");
  k.rotaryDirection = r.direction("rotary_direction");
  if (const auto v = r.numbers<3>("pivot_mm")) k.pivotMm = {(*v)[0], (*v)[1], (*v)[2]};
  if (const auto v = r.numbers<3>("rotary_offset_mm"))
    k.rotaryOffsetMm = {(*v)[0], (*v)[1], (*v)[2]};
  if (const auto v = r.numbers<2>("tilt_limits_deg")) {
    k.tiltMinDeg = (*v)[0];
    k.tiltMaxDeg = (*v)[1];
  }
  if (const auto v = r.numbers<2>("rotary_limits_deg")) {
    k.rotaryLimited = true;
    k.rotaryMinDeg = (*v)[0];
    k.rotaryMaxDeg = (*v)[1];
  }
  k.solution = solutionNamed(r, r.text("solution", "nearest"));
  k.singularToleranceDeg = r.number("singular_tolerance_deg", k.singularToleranceDeg);
  return k;
}

}  // namespace

MachineSetup parseMachineFile(std::string_view text, const std::string& sourceName) {
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    throw IoError(sourceName + ": not valid JSON: " + e.what());
  }
  const MachineReader r(doc, sourceName);
  if (!doc.is_object()) r.fail("a machine file is one JSON object");
  for (const auto& [key, value] : doc.items())
    if (!kKeys.count(key)) r.fail("unknown key \"" + key + "\"");
  MachineSetup m;
  m.name = r.text("name", "");
  if (m.name.empty()) r.fail("\"name\" is required");
  m.description = r.text("description", "");
  m.kinematics = readKinematics(r);
  const std::string positions = r.text("positions", "machine");
  if (positions != "machine" && positions != "tool-tip")
    r.fail("\"positions\": '" + positions + "' is not machine or tool-tip");
  m.tcpPositions = positions == "tool-tip";
  m.tcpOnBlock = r.text("tcp_on", "");
  m.tcpOffBlock = r.text("tcp_off", "");
  try {
    planning::validateKinematics(m.kinematics);
  } catch (const InvalidInput& e) {
    r.fail(e.what());
  }
  return m;
}

std::string formatMachineFile(const MachineSetup& m) {
  const planning::TableKinematics& k = m.kinematics;
  planning::validateKinematics(k);
  json doc = {
      {"name", m.name},
      {"description", m.description},
      {"rotary_axes", k.pair == planning::RotaryPair::AC ? "AC" : "BC"},
      {"tilt_direction", k.tiltDirection},
      {"rotary_direction", k.rotaryDirection},
      {"pivot_mm", {k.pivotMm.x(), k.pivotMm.y(), k.pivotMm.z()}},
      {"rotary_offset_mm", {k.rotaryOffsetMm.x(), k.rotaryOffsetMm.y(), k.rotaryOffsetMm.z()}},
      {"tilt_limits_deg", {k.tiltMinDeg, k.tiltMaxDeg}},
      {"solution", solutionName(k.solution)},
      {"positions", m.tcpPositions ? "tool-tip" : "machine"},
      {"tcp_on", m.tcpOnBlock},
      {"tcp_off", m.tcpOffBlock},
      {"singular_tolerance_deg", k.singularToleranceDeg}};
  doc["rotary_limits_deg"] = k.rotaryLimited ? json{k.rotaryMinDeg, k.rotaryMaxDeg} : json(nullptr);
  return doc.dump(2) + "\n";
}

MachineSetup readMachineFile(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxMachineFileBytes)
    throw IoError(path.string() + ": larger than 1 MiB; not a machine file");
  return parseMachineFile(detail::readFileBytes(path), path.string());
}

void applyMachine(const MachineSetup& machine, GCodeWriteParams& params) {
  params.mode = GCodeWriteParams::Mode::FiveAxis;
  params.kinematics = machine.kinematics;
  params.tcpPositions = machine.tcpPositions;
  params.tcpOnBlock = machine.tcpOnBlock;
  params.tcpOffBlock = machine.tcpOffBlock;
  params.machineName = machine.name;
}

}  // namespace ddfcam::io
