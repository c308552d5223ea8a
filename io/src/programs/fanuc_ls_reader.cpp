// SPDX-License-Identifier: MIT
// ddfcam: reading FANUC teach-pendant programs in their ASCII form (.ls).
#include <ddfcam/io/programs/fanuc_ls_reader.h>

#include <ddfcam/error.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>

#include "../common/file_access.h"
#include "fanuc_ls_position_reader.h"
#include "path_file_limits.h"

namespace ddfcam::io {
namespace {

using detail::lsClip;
using detail::lsIsSpace;
using detail::lsLeadingNumber;
using detail::lsSplitSpaces;
using detail::lsStartsWith;
using detail::lsTrim;

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{1} << 30;
constexpr std::size_t kMaxMotions = 50'000'000;

struct Motion {
  int line = 0;
  long index = 0;  // n of P[n]
  planning::MoveKind move = planning::MoveKind::Cut;
  double feedMmPerMin = 0.0;
};

enum class Section { None, Attr, Main, Pos, End, Other };

class LsReader {
 public:
  LsReader(std::string_view text, const std::string& name)
      : text_(text), name_(name), errors_(name), positions_(errors_) {}

  planning::ClProgram read() {
    std::size_t pos = text_.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;  // UTF-8 byte order mark
    int number = 0;
    while (pos < text_.size()) {
      const std::size_t end = text_.find('\n', pos);
      const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
      std::string_view line = text_.substr(pos, stop - pos);
      pos = end == std::string_view::npos ? text_.size() : end + 1;
      ++number;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      for (const char c : line)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
          fail(number, "control character (binary data?)");
      readLine(line, number);
    }
    closeSection();
    return assemble();
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const { errors_.fail(line, what); }

  void warn(int line, std::string text) { program_.warnings.push_back({line, std::move(text)}); }

  void readLine(std::string_view line, int number) {
    if (!sawProg_) {
      if (lsTrim(line).empty()) return;
      if (!lsStartsWith(line, "/PROG"))
        fail(number, "not a FANUC TP program (expected '/PROG name')");
      const auto tokens = lsSplitSpaces(line.substr(5));
      if (!tokens.empty()) program_.partName = std::string(tokens[0]);
      sawProg_ = true;
      section_ = Section::Attr;
      return;
    }
    if (lsStartsWith(line, "/")) return startSection(line);
    if (section_ == Section::Main) return mainLine(line, number);
    if (section_ == Section::Pos) return positions_.line(line, number);
    if (section_ == Section::End && !lsTrim(line).empty()) fail(number, "text after /END");
  }

  void startSection(std::string_view line) {
    closeSection();
    const std::string_view name = lsSplitSpaces(line).front();
    if (name == "/MN") {
      sawMain_ = true;
      section_ = Section::Main;
    } else if (name == "/POS") {
      section_ = Section::Pos;
    } else if (name == "/END") {
      sawEnd_ = true;
      section_ = Section::End;
    } else {
      section_ = Section::Other;
    }
  }

  void closeSection() {
    if (pending_) fail(pendingLine_, "instruction does not end with ';'");
    positions_.close();
  }

  // ---- /MN ----

  void mainLine(std::string_view line, int number) {
    std::string_view t = lsTrim(line);
    if (t.empty()) return;
    if (t.front() == ':') {
      if (!pending_) fail(number, "continuation line ':' without an instruction");
      pendingText_ += ' ';
      pendingText_ += t.substr(1);
    } else {
      std::size_t digits = 0;
      while (digits < t.size() && t[digits] >= '0' && t[digits] <= '9') ++digits;
      if (digits == 0 || digits == t.size() || t[digits] != ':')
        fail(number, "expected a numbered instruction 'N: ... ;', found '" + lsClip(t) + "'");
      if (pending_) fail(pendingLine_, "instruction does not end with ';'");
      pending_ = true;
      pendingLine_ = number;
      pendingText_.assign(t.substr(digits + 1));
    }
    if (pendingText_.size() > detail::kMaxLsStatementBytes)
      fail(pendingLine_, "instruction too long");
    const std::size_t semicolon = pendingText_.rfind(';');
    if (semicolon == std::string::npos) return;
    pending_ = false;
    instruction(lsTrim(std::string_view(pendingText_).substr(0, semicolon)), pendingLine_);
  }

  void instruction(std::string_view t, int line) {
    if (t.empty()) return;
    if (t.front() == '!') return program_.comments.push_back(std::string(lsTrim(t.substr(1))));
    if (lsStartsWith(t, "//")) return program_.comments.push_back(std::string(t));
    const char kind = t.front();
    if (t.size() > 1 && lsIsSpace(t[1]) &&
        (kind == 'J' || kind == 'L' || kind == 'C' || kind == 'A'))
      return motion(kind, t.substr(1), line, t);
    if (lsStartsWith(t, "UTOOL_NUM") || lsStartsWith(t, "UFRAME_NUM")) return frameNumber(t, line);
    program_.comments.push_back(std::string(t));
    warn(line, "instruction '" + lsClip(t) + "' kept as a comment");
  }

  void frameNumber(std::string_view t, int line) {
    program_.comments.push_back(std::string(t));
    std::string_view value =
        lsTrim(t.substr(t.find('=') == std::string_view::npos ? t.size() : t.find('=') + 1));
    const auto n = lsLeadingNumber(value);
    if (!n || !lsTrim(value).empty()) {
      warn(line, "frame number of '" + lsClip(t) + "' is not a constant");
      return;
    }
    if (lsStartsWith(t, "UTOOL_NUM") && !toolSet_ && *n >= 0 && *n < 1e6) {
      program_.toolNumber = static_cast<int>(*n);
      toolSet_ = true;
    }
  }

  void motion(char kind, std::string_view rest, int line, std::string_view whole) {
    std::vector<long> points;
    for (int i = 0; i < (kind == 'C' ? 2 : 1); ++i) {
      const auto index = lsPointRef(rest, line, errors_);
      if (!index) {
        program_.comments.push_back(std::string(whole));
        warn(line, "motion to a position register kept as a comment: '" + lsClip(whole) + "'");
        return;
      }
      points.push_back(*index);
      rest = lsTrim(rest);
      if (kind == 'C' && i == 0 && !rest.empty() && rest.front() == ':') rest.remove_prefix(1);
    }
    const auto tokens = lsSplitSpaces(rest);
    if (tokens.size() < 2) fail(line, "motion needs a speed and a termination type");
    const double feed = speed(kind, tokens[0], line);
    if (tokens[1] != "FINE" && !lsStartsWith(tokens[1], "CNT") && !lsStartsWith(tokens[1], "CD"))
      fail(line, "unknown termination type '" + lsClip(tokens[1]) + "'");
    for (std::size_t i = 2; i < tokens.size(); ++i) option(tokens[i], line);
    if (kind == 'C' || kind == 'A')
      warn(line, "circular motion approximated by straight moves through its points");
    if (motions_.size() + points.size() > kMaxMotions)
      fail(line, "more than " + std::to_string(kMaxMotions) + " motions");
    for (const long index : points) {
      const bool joint = kind == 'J';
      motions_.push_back({line, index, joint ? planning::MoveKind::Rapid : planning::MoveKind::Cut,
                          joint ? 0.0 : feed});
    }
  }

  double speed(char kind, std::string_view token, int line) {
    if (lsStartsWith(token, "R[") || lsStartsWith(token, "AR[") || token == "max_speed") {
      if (kind != 'J') warn(line, "speed '" + lsClip(token) + "' is not a constant: no feed");
      return 0.0;
    }
    std::string_view unit = token;
    const auto value = lsLeadingNumber(unit);
    if (!value || *value < 0) fail(line, "bad speed '" + lsClip(token) + "'");
    double perMin = 0.0;
    if (unit == "mm/sec")
      perMin = 60.0;
    else if (unit == "cm/min")
      perMin = 10.0;
    else if (unit == "inch/min")
      perMin = 25.4;
    else if (unit != "%" && unit != "deg/sec" && unit != "sec" && unit != "msec")
      fail(line, "unknown speed unit in '" + lsClip(token) + "'");
    if (kind == 'J') return 0.0;
    if (perMin == 0.0) warn(line, "speed '" + lsClip(token) + "' gives no linear feed");
    const double feed = *value * perMin;
    if (const auto problem = detail::feedProblem(feed)) fail(line, "speed: " + *problem);
    return feed;
  }

  void option(std::string_view token, int line) {
    static constexpr std::string_view kMoving[] = {"Offset",  "Tool_Offset", "INC",
                                                   "VOFFSET", "Skip",        "TIME"};
    for (const std::string_view word : kMoving)
      if (lsStartsWith(token, word)) {
        warn(line, "motion option '" + lsClip(token) + "' ignored: the point may differ");
        return;
      }
  }

  // ---- result ----

  planning::ClProgram assemble() {
    if (!sawMain_) throw IoError(name_ + ": no /MN section");
    if (motions_.empty()) throw IoError(name_ + ": no motion instructions in /MN");
    if (!sawEnd_) warn(0, "no /END: the file may be truncated");
    bool frameWarned = false;
    int path = 0;
    int point = 0;
    bool linearSeen = false;
    for (const Motion& m : motions_) {
      const auto it = positions_.positions().find(m.index);
      if (it == positions_.positions().end())
        fail(m.line, "P[" + std::to_string(m.index) + "] is used but has no /POS entry");
      const detail::LsPosition& p = it->second;
      if (p.joint)
        fail(m.line, "P[" + std::to_string(m.index) +
                         "] is given in joint angles; only Cartesian positions can be read");
      if (p.userFrame != 0 && !frameWarned) {
        warn(p.line, "positions are relative to user frame " + std::to_string(p.userFrame));
        frameWarned = true;
      }
      if (m.move == planning::MoveKind::Rapid && linearSeen) {
        ++path;
        point = 0;
        linearSeen = false;
      }
      linearSeen |= m.move == planning::MoveKind::Cut;
      program_.points.push_back(makePoint(m, p, path, point++));
    }
    return std::move(program_);
  }

  static planning::ClPoint makePoint(const Motion& m, const detail::LsPosition& p, int path,
                                     int index) {
    constexpr double kRad = std::numbers::pi / 180.0;
    const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(p.value[5] * kRad, ddf::Vec3::UnitZ()) *
                                      Eigen::AngleAxisd(p.value[4] * kRad, ddf::Vec3::UnitY()) *
                                      Eigen::AngleAxisd(p.value[3] * kRad, ddf::Vec3::UnitX()))
                                         .toRotationMatrix();
    planning::ClPoint point;
    point.path = path;
    point.point = index;
    point.positionMm = ddf::Vec3(p.value[0], p.value[1], p.value[2]);
    point.axis = rotation.col(2).normalized();
    point.feedMmPerMin = m.feedMmPerMin;
    point.move = m.move;
    point.sourceLine = m.line;
    return point;
  }

  std::string_view text_;
  const std::string& name_;
  planning::ClProgram program_;
  Section section_ = Section::None;
  bool sawProg_ = false;
  bool sawMain_ = false;
  bool sawEnd_ = false;
  bool toolSet_ = false;
  bool pending_ = false;
  int pendingLine_ = 0;
  std::string pendingText_;
  detail::LsErrors errors_;
  std::vector<Motion> motions_;
  detail::LsPositionReader positions_;
};

}  // namespace

planning::ClProgram decodeFanucLs(std::string_view text, const std::string& sourceName) {
  return LsReader(text, sourceName).read();
}

planning::ClProgram readFanucLs(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxFileBytes)
    throw IoError(file.string() + ": file larger than 1 GiB, refused as a tool path");
  return decodeFanucLs(detail::readFileBytes(file), file.string());
}

}  // namespace ddfcam::io
