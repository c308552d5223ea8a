// SPDX-License-Identifier: MIT
// ddfcam: reading and writing tool-path files of any supported format, chosen by file type.
#include <ddfcam/io/programs/path_file.h>

#include <ddfcam/error.h>
#include <ddfcam/io/programs/fanuc_ls_reader.h>
#include <ddfcam/io/programs/ros_toolpath_reader.h>
#include <ddfcam/planning/placement/cutter_tool.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>

#include "../common/file_access.h"
#include "../common/text_parsing.h"

namespace ddfcam::io {
namespace {

constexpr std::size_t kHeadBytes = 4096;

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

/// Non-blank lines of @p head, trimmed; a line cut off by the end of a full head is dropped.
std::vector<std::string_view> headLines(std::string_view head) {
  std::vector<std::string_view> lines;
  std::size_t pos = 0;
  while (pos < head.size()) {
    const std::size_t end = head.find('\n', pos);
    if (end == std::string_view::npos && head.size() >= kHeadBytes) break;
    const std::size_t stop = end == std::string_view::npos ? head.size() : end;
    const std::string_view line = trim(head.substr(pos, stop - pos));
    if (!line.empty()) lines.push_back(line);
    pos = stop + 1;
  }
  return lines;
}

bool isAptRecord(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size() && (std::isalnum(static_cast<unsigned char>(line[i])) || line[i] == '_'))
    ++i;
  if (i == 0 || !std::isalpha(static_cast<unsigned char>(line[0]))) return false;
  const std::string word = upper(line.substr(0, i));
  static constexpr std::string_view kBare[] = {"PARTNO", "RAPID", "END", "FINI", "STOP", "OPSTOP"};
  if (std::find(std::begin(kBare), std::end(kBare), word) != std::end(kBare)) return true;
  std::string_view rest = line.substr(i);
  if (word == "TOOL" && upper(trim(rest).substr(0, 4)) == "PATH") rest = trim(rest).substr(4);
  rest = trim(rest);
  return !rest.empty() && rest.front() == '/';
}

/// First APT record after "$$" comments is an APT record.
bool startsLikeApt(const std::vector<std::string_view>& lines) {
  for (const std::string_view line : lines) {
    if (line.substr(0, 2) == "$$") continue;
    return isAptRecord(line);
  }
  return false;
}

bool hasGoto(std::string_view head) {
  return upper(head).find("GOTO") != std::string::npos;
}

std::vector<std::string_view> csvFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i < line.size() && std::string_view(",; \t").find(line[i]) == std::string_view::npos)
      continue;
    fields.push_back(trim(line.substr(start, i - start)));
    start = i + 1;
  }
  return fields;
}

bool isNumber(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size();
}

bool isNumericRow(std::string_view line) {
  int numbers = 0;
  for (const std::string_view f : csvFields(line)) {
    if (f.empty()) continue;
    const std::string word = upper(f);
    if (isNumber(f))
      ++numbers;
    else if (word != "CUT" && word != "LINK" && word != "RAPID")
      return false;
  }
  return numbers >= 3;
}

bool isHeaderRow(std::string_view line) {
  int names = 0;
  for (const std::string_view f : csvFields(line)) {
    if (f.empty()) continue;
    if (!std::isalpha(static_cast<unsigned char>(f.front()))) return false;
    for (const char c : f)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    ++names;
  }
  return names >= 3;
}

bool looksLikeCsv(const std::vector<std::string_view>& lines) {
  std::vector<std::string_view> rows;
  for (const std::string_view line : lines)
    if (line.front() != '#' && rows.size() < 2) rows.push_back(line);
  if (rows.empty()) return false;
  if (isNumericRow(rows[0])) return true;
  return isHeaderRow(rows[0]) && rows.size() == 2 && isNumericRow(rows[1]);
}

bool looksLikeRosYaml(const std::vector<std::string_view>& lines) {
  for (std::string_view line : lines) {
    if (line.substr(0, 2) == "- ") line = trim(line.substr(2));
    for (const std::string_view key : {"paths:", "poses:"})
      if (line.substr(0, key.size()) == key &&
          (line.size() == key.size() || line[key.size()] == ' ' || line[key.size()] == '\t'))
        return true;
  }
  return false;
}

bool looksLikeFanuc(const std::vector<std::string_view>& lines) {
  return !lines.empty() && lines.front().substr(0, 5) == "/PROG";
}

/// @p line without its "(...)" comments and anything after a ';' comment, trimmed.
std::string_view withoutGCodeComments(std::string_view line, std::string& scratch) {
  scratch.clear();
  int depth = 0;
  for (const char c : line) {
    if (c == ';' && depth == 0) break;
    if (c == '(') ++depth;
    if (depth == 0) scratch += c;
    if (c == ')' && depth > 0) --depth;
  }
  return trim(scratch);
}

/// An RS274 block: an optional block-delete '/', then address words (a letter followed by a
/// number, a parameter '#' or an expression '['), at least one G or M word among them.
bool isGCodeBlock(std::string_view block) {
  if (!block.empty() && block.front() == '/') block.remove_prefix(1);
  bool motionOrMisc = false;
  std::size_t i = 0;
  while (i < block.size()) {
    const unsigned char c = static_cast<unsigned char>(block[i]);
    if (std::isspace(c)) {
      ++i;
      continue;
    }
    if (!std::isalpha(c) || i + 1 >= block.size()) return false;
    const char letter = static_cast<char>(std::toupper(c));
    const char next = block[i + 1];
    if (!std::isdigit(static_cast<unsigned char>(next)) &&
        std::string_view("+-.#[").find(next) == std::string_view::npos)
      return false;
    if (letter == 'G' || letter == 'M') motionOrMisc = true;
    // Skip the value: digits and signs, a #<name> parameter, a [...] expression.
    for (++i; i < block.size() && !std::isalpha(static_cast<unsigned char>(block[i]));) {
      const char closing = block[i] == '[' ? ']' : block.substr(i, 2) == "#<" ? '>' : '\0';
      if (closing == '\0') {
        ++i;
        continue;
      }
      const std::size_t end = block.find(closing, i);
      if (end == std::string_view::npos) return false;
      i = end + 1;
    }
  }
  return motionOrMisc;
}

/// G-code: after '%' lines, an O program number or name and comments, the first lines are
/// RS274 blocks (two at least, none of another kind before them).
bool looksLikeGCode(const std::vector<std::string_view>& lines) {
  int blocks = 0;
  std::string scratch;
  for (const std::string_view raw : lines) {
    const std::string_view line = withoutGCodeComments(raw, scratch);
    if (line.empty() || line == "%") continue;
    if (blocks == 0 && (line.front() == 'O' || line.front() == 'o') &&
        line.find('/') == std::string_view::npos && line.find(',') == std::string_view::npos)
      continue;
    if (!isGCodeBlock(line)) return false;
    if (++blocks >= 2) return true;
  }
  return false;
}

std::optional<PathFormat> sniffUnknown(std::string_view head,
                                       const std::vector<std::string_view>& lines) {
  if (looksLikeFanuc(lines)) return PathFormat::FanucLs;
  if (looksLikeRosYaml(lines)) return PathFormat::RosYaml;
  if (startsLikeApt(lines) && hasGoto(head)) return PathFormat::Apt;
  if (looksLikeGCode(lines)) return PathFormat::GCode;
  if (looksLikeCsv(lines)) return PathFormat::Csv;
  return std::nullopt;
}

std::string readHead(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw IoError("file " + file.string() + " does not exist");
  if (std::filesystem::is_directory(file, ec))
    throw IoError(file.string() + " is a directory, not a file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError("cannot open " + file.string());
  std::string head(kHeadBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

}  // namespace

std::string_view pathFormatName(PathFormat format) {
  switch (format) {
    case PathFormat::Csv:
      return "CSV";
    case PathFormat::Apt:
      return "APT/CLDATA";
    case PathFormat::GCode:
      return "G-code";
    case PathFormat::RosYaml:
      return "ROS toolpath YAML";
    case PathFormat::FanucLs:
      break;
  }
  return "FANUC TP (.ls)";
}

std::vector<std::string> pathFileExtensions(PathFormat format) {
  switch (format) {
    case PathFormat::Csv:
      return {".csv", ".txt"};
    case PathFormat::Apt:
      return {".apt", ".cls", ".cl", ".ncl", ".aptsource", ".txt"};
    case PathFormat::GCode:
      return {".ngc", ".nc", ".gcode"};
    case PathFormat::RosYaml:
      return {".yaml", ".yml"};
    case PathFormat::FanucLs:
      break;
  }
  return {".ls"};
}

std::optional<PathFormat> detectPathFormat(const std::filesystem::path& file,
                                           std::string_view head) {
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);  // UTF-8 byte order mark
  if (detail::looksBinary(head)) return std::nullopt;
  const std::string ext = detail::lowerExtension(file);
  const std::vector<std::string_view> lines = headLines(head);
  if (ext == ".ls")
    return looksLikeFanuc(lines) ? std::optional(PathFormat::FanucLs) : std::nullopt;
  if (ext == ".yaml" || ext == ".yml")
    return looksLikeRosYaml(lines) ? std::optional(PathFormat::RosYaml) : std::nullopt;
  if (ext == ".ngc" || ext == ".nc" || ext == ".gcode") return PathFormat::GCode;
  if (ext == ".csv") return PathFormat::Csv;
  if (ext == ".apt" || ext == ".cls" || ext == ".cl" || ext == ".ncl" || ext == ".aptsource")
    return PathFormat::Apt;
  if (ext == ".txt") {
    if (startsLikeApt(lines)) return PathFormat::Apt;
    if (looksLikeGCode(lines)) return PathFormat::GCode;
    if (looksLikeCsv(lines)) return PathFormat::Csv;
    return std::nullopt;
  }
  return sniffUnknown(head, lines);
}

PathFile readPathFile(const std::filesystem::path& file, const PathReadParams& params) {
  const std::optional<PathFormat> format = detectPathFormat(file, readHead(file));
  if (!format)
    throw IoError(file.string() +
                  ": not a tool-path file (expected CSV, APT/CLDATA, ROS toolpath YAML or FANUC "
                  ".ls)");
  switch (*format) {
    case PathFormat::Csv:
      return {readToolPathCsv(file, params.csv), *format};
    case PathFormat::Apt:
      return {readApt(file, params.apt), *format};
    case PathFormat::RosYaml:
      return {readRosToolpathYaml(file), *format};
    case PathFormat::FanucLs:
      return {readFanucLs(file), *format};
    case PathFormat::GCode:
      break;
  }
  throw IoError(file.string() +
                ": G-code cannot be read (it is written only); read CSV, APT/CLDATA, ROS "
                "toolpath YAML or FANUC .ls");
}

void writePathFile(const planning::ClProgram& program, const planning::Tool& tool,
                   const std::filesystem::path& file, const PathWriteParams& params) {
  switch (params.format) {
    case PathFormat::Csv:
      return writeToolPathCsv(program, file, params.csv);
    case PathFormat::Apt: {
      if (program.cutter) return writeApt(program, file, params.apt);
      planning::ClProgram withCutter = program;
      withCutter.cutter = planning::aptCutter(tool);
      return writeApt(withCutter, file, params.apt);
    }
    case PathFormat::GCode:
      return writeGCode(file, program, tool, params.gcode);
    case PathFormat::RosYaml:
    case PathFormat::FanucLs:
      break;
  }
  throw InvalidInput("writing " + std::string(pathFormatName(params.format)) +
                     " files is not supported (write CSV, APT/CLDATA or G-code)");
}

}  // namespace ddfcam::io
