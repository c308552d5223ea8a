// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: the parsed command line, and what importing the path file found.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/planning/inspection/coverage.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/placement/imported_path.h>
#include <ddfcam/planning/placement/path_sampling.h>
#include <ddfcam/planning/placement/tool_orientation.h>
#include <ddfcam/planning/tools/tool.h>

#include <Eigen/Geometry>

#include "arguments.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief Preston removal settings of the command line (units as on the command line).
struct PrestonOptions {
  bool enabled = false;                ///< --preston given (default false)
  double kpMm2PerN = 1e-7;             ///< K_p, mm^2/N (default 1e-7)
  double forceN = 10.0;                ///< normal force, N (default 10)
  double wheelSpeedMPerS = 30.0;       ///< wheel surface speed, m/s (default 30)
  std::optional<double> feedMmPerMin;  ///< feed, mm/min (default: the CSV's first cut row)
  double infeedMm = 0.1;               ///< nominal infeed of the undeformed tool, mm (0.1)
};

/// @brief Penetration correction settings of the command line.
struct CorrectionOptions {
  bool enabled = false;  ///< --correct given (default false)
  int every = 1;         ///< exact lift at every k-th pose (default 1)
  int grid = 50;         ///< tangential grid cells per axis (default 50)
};

/// @brief How a path file is read and placed on the part (--path-units, --translate, --rotate,
/// --keep-rapids, --vectors, --points).
struct ImportOptions {
  std::optional<LengthUnit> unit;             ///< --path-units (default: the file's own)
  ddf::Vec3 translateMm = ddf::Vec3::Zero();  ///< --translate X,Y,Z, mm (default 0)
  ddf::Vec3 rotateDeg = ddf::Vec3::Zero();    ///< --rotate AX,AY,AZ, deg (default 0)
  bool keepRapids = false;                    ///< --keep-rapids (default false)
  /// --vectors axis|approach|normal|auto: what the file's i,j,k vectors are (default auto).
  planning::PathVectorMeaning vectors = planning::PathVectorMeaning::Auto;
  /// --points contact|tip|file|auto: what the file's positions are (default auto).
  planning::PathPointMeaning points = planning::PathPointMeaning::Auto;

  /// File frame -> part frame: Translation(translateMm) * Rz(AZ) * Ry(AY) * Rx(AX).
  Eigen::Isometry3d transform() const;
};

/// @brief Everything the simulate command line chooses.
struct SimulateOptions {
  std::filesystem::path input, paths, output;      ///< PART, --paths, -o
  std::optional<std::filesystem::path> errorMap;   ///< --error-map (default none)
  std::optional<std::filesystem::path> report;     ///< --report (default none)
  std::optional<std::filesystem::path> stockMesh;  ///< --stock-mesh (default none)
  std::optional<ddfcam::LengthUnit> unit;   ///< --units of PART and the stock mesh (default none)
  planning::Tool tool;                      ///< the tool (default roll R5 W10)
  std::string toolKind = "roll";            ///< kind as named on the command line
  std::string toolSource = "command line";  ///< "command line" or the library file
  planning::PlacementParams placement;      ///< --lead, --tilt (default 0, 0)
  double allowanceMm = 0.0;                 ///< --allowance, mm (default 0)
  double toleranceMm = 0.01;                ///< --tolerance, mm (default 0.01)
  bool checkVConvexity = true;              ///< not --no-vconvexity-check
  std::optional<double> sampleToleranceMm;  ///< --sample-tolerance, mm (default none)
  std::optional<double> stepMm;             ///< --step, mm (default none)
  bool swept = false;                       ///< --swept (default false)
  CorrectionOptions correction;             ///< --correct ...
  PrestonOptions preston;                   ///< --preston ...
  ImportOptions import;                     ///< --path-units, --translate, ...
  /// --min-coverage: warn when the tool touches less of the part, % (default 5).
  double minCoveragePercent = planning::kLowPathCoveragePercent;
  bool strict = false;  ///< --strict: exit code 3 when the run had any warning (default false)

  /// True when the passes are resampled along the feed (--sample-tolerance or --step).
  bool resample() const { return sampleToleranceMm.has_value() || stepMm.has_value(); }
};

/// @brief The option table of "simulate", which also gives its --help.
Arguments simulateArguments();

/// @brief Parses the words after "simulate".
/// @throws UsageError for unknown, missing, malformed or conflicting options (exit code 2).
/// @throws IoError / InvalidInput if --tool-file cannot be read or has no tool --tool-name.
SimulateOptions parseSimulateOptions(std::span<const std::string> words);

/// @brief What reading and placing the path file found, for the report.
struct ImportFacts {
  std::string format;      ///< pathFormatName() of the file, e.g. "APT/CLDATA"
  std::string unit;        ///< unit the file's numbers were taken in: "mm", "in" or "m"
  std::string placement;   ///< "contacts" (CSV: --lead/--tilt at each contact) or "program axes"
  std::string vectors;     ///< vectors read as: "axis", "approach" or "normal"
  std::string points;      ///< points read as: "contact" or "tip"
  std::string convention;  ///< what was used for vectors and points, and why
  int pointsRead = 0;      ///< points of the program read
  int posesPlaced = 0;     ///< poses of the simulated path
  int pointsOffPart = 0;   ///< planning::ImportedPath::pointsOffPart of the placement
  double maxContactDistanceMm = 0.0;  ///< largest |contact distance| over all poses, mm
  /// Largest |contact distance| over the poses on the part, mm; empty if none is on it.
  std::optional<double> maxOnPartContactDistanceMm;
  /// Poses whose tool reaches into the part (planning::ImportedPath::gougingPoses); empty where
  /// nothing measured it.
  std::optional<int> gougingPoses;
  std::optional<double> maxGougeDepthMm;  ///< deepest reach into the part, mm; as gougingPoses
  int warnings = 0;                       ///< warnings of the reader and the placement
};

/// @brief The cut moves of a tool path and the contact normals.
struct CsvPath {
  planning::ToolPath path;                       ///< poses placed (or resampled)
  std::vector<ddf::Vec3> normals;                ///< #P unit contact normals; empty if resampled
  std::vector<planning::PassSampling> sampling;  ///< per pass when resampled, else empty
  ImportFacts facts;                             ///< set by importSimulationPath()
};

}  // namespace ddfcam::cli
