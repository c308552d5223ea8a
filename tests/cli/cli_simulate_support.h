// SPDX-License-Identifier: MIT
// Shared set-up of the ddfcam-cli simulate tests: running the CLI, a flat plate, a straight pass.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/io/programs/tool_path_csv.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "../io/io_test_support.h"

namespace ddfcam::test {

struct CliRun {
  int exitCode = -1;
  std::string out, err;
};

inline CliRun cli(const ScratchDir& dir, const std::string& command,
                  const std::vector<std::string>& args) {
  std::string line = "'" DDFCAM_CLI_PATH "' " + command;
  for (const std::string& a : args) line += " '" + a + "'";
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  line += " > '" + out.string() + "' 2> '" + err.string() + "' < /dev/null";
  const int status = std::system(line.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readBytes(out), readBytes(err)};
}

/// The number after "key": in @p json (keys of the report are unique); NaN if absent or null.
inline double jsonNumber(const std::string& json, const std::string& key) {
  std::smatch match;
  const std::regex pattern("\"" + key + "\": (-?[0-9.eE+-]+)");
  if (!std::regex_search(json, match, pattern)) return std::nan("");
  return std::stod(match[1]);
}

// A 20 x 20 mm plate in z = 0: 4 x 4 cells of 5 mm, m = 21 (a regular 0.25 mm grid of
// raster points), vectors (0, 0, 1), heights 0.
constexpr double kPlate = 20.0, kSpacing = 0.25;

inline ddf::DisplacementField plate() {
  std::vector<ddf::Vec3> points;
  std::vector<std::array<int, 3>> faces;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) points.emplace_back(5.0 * i, 5.0 * j, 0.0);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int a = 5 * j + i;
      faces.push_back({a, a + 1, a + 6});
      faces.push_back({a, a + 6, a + 5});
    }
  return ddf::DisplacementField(ddf::makeSupportMesh(points, faces),
                                std::vector<ddf::Vec3>(points.size(), {0, 0, 1}), 21, 0.0f);
}

/// One cut pass along x at y = 10 from x = 2 to 18 every @p step mm: contacts on z = 0, roll
/// axis along y, normal +z.
inline planning::ClProgram straightPass(double step = 0.1) {
  planning::ClProgram table;
  table.pointKind = planning::ClPointKind::Contact;
  const int count = static_cast<int>(std::lround(16.0 / step));
  for (int p = 0; p <= count; ++p) {
    planning::ClPoint row;
    row.point = p;
    row.positionMm = {2.0 + step * p, 10.0, 0.0};
    row.axis = ddf::Vec3(0, 1, 0);
    row.normal = ddf::Vec3(0, 0, 1);
    row.feedMmPerMin = 1000;
    table.points.push_back(row);
  }
  return table;
}

/// z of every distinct raster point of a DDF on the plate's support, keyed by its 0.25 mm
/// grid index (x / 0.25, y / 0.25); the plate's vectors are +z, so z = h.
inline std::map<std::pair<long, long>, double> heightGrid(const ddf::DisplacementField& ddf) {
  std::map<std::pair<long, long>, double> grid;
  const int n = ddf.raster().m - 1;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const ddf::Vec3 q = ddf.surfacePoint(f, i, k);
        grid[{std::lround(q.x() / kSpacing), std::lround(q.y() / kSpacing)}] = q.z();
      }
  return grid;
}

}  // namespace ddfcam::test
