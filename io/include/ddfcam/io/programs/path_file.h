// SPDX-License-Identifier: MIT
// ddfcam: reading and writing tool-path files of any supported format, chosen by file type.
#pragma once

#include <ddfcam/io/programs/apt_reader.h>
#include <ddfcam/io/programs/apt_writer.h>
#include <ddfcam/io/programs/gcode_writer.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/tools/tool.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io {

/// @brief Tool-path file formats.
enum class PathFormat {
  Csv,      ///< ddfcam CSV or a common x,y,z[,i,j,k] table (read and write)
  Apt,      ///< APT/CLDATA source, NX CLSF, Pro/CLfile (read and write)
  GCode,    ///< RS274NGC G-code (write only)
  RosYaml,  ///< ROS-Industrial toolpath YAML (read only)
  FanucLs   ///< FANUC TP program in ASCII form (read only)
};

/// @brief Human-readable name of @p format for menus and messages: "CSV", "APT/CLDATA",
/// "G-code", "ROS toolpath YAML" or "FANUC TP (.ls)".
std::string_view pathFormatName(PathFormat format);

/// @brief File name extensions of @p format, lower case with the dot, the preferred one (the
/// one to append when writing) first: Csv .csv .txt; Apt .apt .cls .cl .ncl .aptsource .txt;
/// GCode .ngc .nc .gcode; RosYaml .yaml .yml; FanucLs .ls.
std::vector<std::string> pathFileExtensions(PathFormat format);

/// @brief Format of a tool-path file from its extension (any case) and the first bytes of its
/// content @p head (a few KiB suffice):
/// - .ls with "/PROG" on its first line: FanucLs;
/// - .yaml/.yml with a `paths:` or `poses:` key: RosYaml (other YAML: nullopt);
/// - .ngc/.nc/.gcode: GCode;
/// - .apt/.cls/.cl/.ncl/.aptsource: Apt; .csv: Csv;
/// - .txt: Apt when the first record (after "$$" comments) is an APT record (`WORD/...`,
///   PARTNO, RAPID, ...), GCode when the first lines after '%', an O word and comments are
///   RS274 blocks (address words with a G or M word, as posts write them), Csv when the first
///   line is a row of numbers or a header line followed by one;
/// - any other extension: the same content tests, for FANUC, ROS YAML, APT (an APT first
///   record and a GOTO in @p head), G-code and CSV in that order.
/// Binary content (NUL or other control bytes) is never a path file.
/// @return std::nullopt if the file is not a tool-path file of a known format.
std::optional<PathFormat> detectPathFormat(const std::filesystem::path& file,
                                           std::string_view head);

/// @brief Options of readPathFile(), one set per readable format.
struct PathReadParams {
  CsvReadParams csv;  ///< for CSV files (default: see CsvReadParams)
  AptReadParams apt;  ///< for APT/CLDATA files (default: see AptReadParams)
};

/// @brief A tool-path file as readPathFile() read it.
struct PathFile {
  planning::ClProgram program;          ///< the program, positions in mm
  PathFormat format = PathFormat::Csv;  ///< the format detected and read (never GCode)
};

/// @brief Reads a tool-path file of any readable format (detectPathFormat() on its extension
/// and first 4 KiB): readToolPathCsv(), readApt(), readRosToolpathYaml() or readFanucLs().
/// Positions of the program are in mm; the format is the one detected, so callers need not
/// detect it again.
/// @throws IoError if the file is missing or unreadable; "<file>: not a tool-path file
/// (expected CSV, APT/CLDATA, ROS toolpath YAML or FANUC .ls)" when no format matches (other
/// YAML, XML, meshes, text); "<file>: G-code cannot be read ..." for G-code; and as the reader
/// of the format.
PathFile readPathFile(const std::filesystem::path& file, const PathReadParams& params = {});

/// @brief Options of writePathFile(): the format and the options of each writable format.
struct PathWriteParams {
  PathFormat format = PathFormat::Csv;  ///< Csv, Apt or GCode (default Csv)
  CsvWriteParams csv;                   ///< for CSV (default: see CsvWriteParams)
  AptWriteParams apt;                   ///< for APT (default: see AptWriteParams)
  GCodeWriteParams gcode;               ///< for G-code (default: see GCodeWriteParams)
};

/// @brief Writes @p program to @p file in params.format, atomically: writeToolPathCsv(),
/// writeApt() (with CUTTER = program.cutter, or planning::aptCutter(@p tool) when the program has
/// none) or writeGCode() (which needs @p tool, a cutter). The extension of @p file is not changed.
/// @param tool the tool of the program; unused for CSV.
/// @throws InvalidInput for a format that cannot be written (RosYaml, FanucLs) and as the
/// writer of the format; IoError if the file cannot be written.
void writePathFile(const planning::ClProgram& program, const planning::Tool& tool,
                   const std::filesystem::path& file, const PathWriteParams& params);

}  // namespace ddfcam::io
