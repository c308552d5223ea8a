// SPDX-License-Identifier: MIT
// ddfcam: the "line" chunk of a .ddfproj (layout in project_file.h).
#include "path_lines_chunk.h"

#include "../common/byte_codec.h"

#include <cstdint>

namespace ddfcam::io::detail {
namespace {

// i32 face, 3 f64 bary, f64 h, 3 f64 point.
constexpr std::size_t kLocationBytes = 4 + 7 * 8;
// i32 stop, i32 backwardStop, u64 seedIndex, f64 lengthMm, u64 point count.
constexpr std::size_t kLineHeaderBytes = 4 + 4 + 8 + 8 + 8;

void putLine(std::string& out, const planning::Streamline& line) {
  putU32(out, static_cast<std::uint32_t>(line.stop));
  putU32(out, static_cast<std::uint32_t>(line.backwardStop));
  putU64(out, line.seedIndex);
  putF64(out, line.lengthMm);
  putU64(out, line.points.size());
  for (const ddf::SurfaceLocation& p : line.points) {
    putU32(out, static_cast<std::uint32_t>(p.face));
    putVec3(out, p.bary);
    putF64(out, p.h);
    putVec3(out, p.point);
  }
}

planning::Streamline readLine(PayloadReader& in) {
  planning::Streamline line;
  // Unknown stop reasons are stored as read; planning::validateProject rejects them.
  line.stop = static_cast<planning::Streamline::StopReason>(in.i32("line stop"));
  line.backwardStop = static_cast<planning::Streamline::StopReason>(in.i32("line stop"));
  line.seedIndex = in.u64("line seed index");
  line.lengthMm = in.f64("line length");
  line.points.resize(in.count(kLocationBytes, "line points"));
  for (ddf::SurfaceLocation& p : line.points) {
    p.face = in.i32("line point face");
    p.bary = readVec3(in, "line point bary");
    p.h = in.f64("line point height");
    p.point = readVec3(in, "line point");
  }
  return line;
}

}  // namespace

bool hasPathLines(const planning::ToolPath& path) {
  return !path.rawLines.empty() || path.linkedIdleMm.has_value();
}

void putPathLines(std::string& out, int index, const planning::ToolPath& path) {
  putU32(out, static_cast<std::uint32_t>(index));
  out.push_back(path.linkedIdleMm ? '\1' : '\0');
  putF64(out, path.linkedIdleMm.value_or(0.0));
  putU64(out, path.rawLines.size());
  for (const planning::Streamline& line : path.rawLines) putLine(out, line);
}

void readPathLines(PayloadReader& in, std::vector<planning::ToolPath>& paths) {
  const std::int32_t index = in.i32("path index");
  if (index < 0 || index >= static_cast<std::int32_t>(paths.size()))
    in.fail("path index " + std::to_string(index) + " out of range (" +
            std::to_string(paths.size()) + " paths before it)");
  planning::ToolPath& path = paths[static_cast<std::size_t>(index)];
  if (hasPathLines(path)) in.fail("a second 'line' chunk for path " + std::to_string(index));
  const std::uint8_t linked = in.u8("linked flag");
  if (linked > 1) in.fail("linked flag " + std::to_string(linked) + " is not 0 or 1");
  const double idleMm = in.f64("linked idle length");
  if (linked) path.linkedIdleMm = idleMm;
  const std::size_t lines = in.count(kLineHeaderBytes, "raw lines");
  path.rawLines.reserve(lines);
  for (std::size_t l = 0; l < lines; ++l) path.rawLines.push_back(readLine(in));
  in.rest();  // members of later versions
}

}  // namespace ddfcam::io::detail
