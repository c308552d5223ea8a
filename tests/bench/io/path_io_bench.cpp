// SPDX-License-Identifier: MIT
// Benchmark: writing and reading tool-path files (CSV, APT/CLDATA, 5-axis G-code) of a large
// 5-axis program, against a textbook stream-based CSV reader in the same run, and placing an
// imported program on the demo part.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/io/programs/apt_reader.h>
#include <ddfcam/io/programs/apt_writer.h>
#include <ddfcam/io/programs/gcode_writer.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/placement/imported_path.h>
#include <ddfcam/planning/tools/tool.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace ddfcam::bench {
namespace {

constexpr int kPoints = 200'000;

/// A 5-axis finishing program: rows of a wavy 200 x 100 mm field, the axis leaning up to 30 deg
/// so the G-code's inverse kinematics has real work; 1000 points per row, tip as the point.
planning::ClProgram wavyProgram(int points) {
  planning::ClProgram program;
  program.partName = "wavy";
  program.pointKind = planning::ClPointKind::ToolReference;
  constexpr int kPerRow = 1000;
  for (int i = 0; i < points; ++i) {
    const int row = i / kPerRow;
    const double x = 200.0 * (i % kPerRow) / (kPerRow - 1);
    const double y = 0.5 * row;
    const double z = 3.0 * std::sin(x / 20.0) * std::cos(y / 15.0);
    const double lean = 0.5 * std::sin(x / 40.0 + y / 30.0);  // up to ~29 deg
    planning::ClPoint p;
    p.path = row;
    p.point = i % kPerRow;
    p.positionMm = {x, y, z};
    p.axis = ddf::Vec3(std::sin(lean), 0.3 * std::sin(lean), std::cos(lean)).normalized();
    p.feedMmPerMin = 1500.0;
    program.points.push_back(p);
  }
  return program;
}

const planning::ClProgram& program() {
  static const planning::ClProgram p = wavyProgram(kPoints);
  return p;
}

const std::string& csvText() {
  static const std::string text = io::encodeToolPathCsv(program());
  return text;
}

const std::string& aptText() {
  static const std::string text = io::encodeApt(program(), {.coordinateDecimals = 5});
  return text;
}

void setCounters(benchmark::State& state, std::size_t bytes) {
  state.SetItemsProcessed(state.iterations() * kPoints);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}

void BM_PathCsvWrite(benchmark::State& state) {
  std::size_t bytes = 0;
  for (auto _ : state) bytes = io::encodeToolPathCsv(program()).size();
  setCounters(state, bytes);
}
BENCHMARK(BM_PathCsvWrite)->Unit(benchmark::kMillisecond);

void BM_PathCsvRead(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(io::decodeToolPathCsv(csvText(), "bench.csv"));
  setCounters(state, csvText().size());
}
BENCHMARK(BM_PathCsvRead)->Unit(benchmark::kMillisecond);

/// The textbook reader: getline per line, commas to blanks, operator>> per value. No checks,
/// no error lines: the floor a careful reader is compared against.
void BM_PathCsvReadNaiveStreams(benchmark::State& state) {
  for (auto _ : state) {
    std::istringstream in(csvText());
    std::string line;
    std::getline(in, line);  // header
    std::vector<planning::ClPoint> points;
    while (std::getline(in, line)) {
      for (char& c : line)
        if (c == ',') c = ' ';
      std::istringstream fields(line);
      planning::ClPoint p;
      ddf::Vec3 axis, normal;
      std::string move;
      fields >> p.path >> p.point >> p.positionMm.x() >> p.positionMm.y() >> p.positionMm.z() >>
          axis.x() >> axis.y() >> axis.z() >> p.feedMmPerMin >> move;
      p.axis = axis;
      points.push_back(p);
    }
    benchmark::DoNotOptimize(points.data());
  }
  setCounters(state, csvText().size());
}
BENCHMARK(BM_PathCsvReadNaiveStreams)->Unit(benchmark::kMillisecond);

void BM_PathAptWrite(benchmark::State& state) {
  std::size_t bytes = 0;
  for (auto _ : state) bytes = io::encodeApt(program(), {.coordinateDecimals = 5}).size();
  setCounters(state, bytes);
}
BENCHMARK(BM_PathAptWrite)->Unit(benchmark::kMillisecond);

void BM_PathAptRead(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(io::decodeApt(aptText(), "bench.apt"));
  setCounters(state, aptText().size());
}
BENCHMARK(BM_PathAptRead)->Unit(benchmark::kMillisecond);

/// 5-axis A/C G-code: inverse kinematics per point plus formatting.
void BM_PathGCodeWrite5Axis(benchmark::State& state) {
  const planning::Tool ball{.kind = planning::ToolKind::BallEnd, .radiusMm = 5.0, .widthMm = 20.0};
  io::GCodeWriteParams params;
  params.mode = io::GCodeWriteParams::Mode::FiveAxis;
  std::size_t bytes = 0;
  for (auto _ : state) bytes = io::encodeGCode(program(), ball, params).size();
  setCounters(state, bytes);
}
BENCHMARK(BM_PathGCodeWrite5Axis)->Unit(benchmark::kMillisecond);

/// Placing an imported 3-axis ball-end program of 2000 tip points on the demo part (raster
/// points of its surface, one per face from the first 2000 faces in wrap-around order): poses,
/// contacts on the part and their distances.
void BM_PlaceImportedProgram(benchmark::State& state) {
  const ddf::GeneratedSurface part = ddf::demoPart();
  const planning::Tool ball{.kind = planning::ToolKind::BallEnd, .radiusMm = 3.0, .widthMm = 6.0};
  planning::ClProgram raster;
  const int n = part.ddf.raster().m - 1;
  for (int i = 0; i < 2000; ++i) {
    planning::ClPoint p;
    p.path = i / 50;
    p.point = i % 50;
    p.positionMm = part.ddf.surfacePoint(i % part.ddf.faceCount(), n / 3, n / 3);
    p.feedMmPerMin = 1000.0;
    raster.points.push_back(p);
  }
  for (auto _ : state) benchmark::DoNotOptimize(planning::placeProgram(raster, ball, part.ddf));
  state.SetItemsProcessed(state.iterations() * 2000);
}
BENCHMARK(BM_PlaceImportedProgram)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ddfcam::bench
