// SPDX-License-Identifier: MIT
// ddfcam: reading FANUC teach-pendant programs in their ASCII form (.ls).
#include <ddfcam/io/fanuc_ls_reader.h>

#include <ddfcam/error.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>

#include "file_access.h"

namespace ddfcam::io {
namespace {

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{1} << 30;
constexpr std::size_t kMaxMotions = 50'000'000;
constexpr std::size_t kMaxStatementBytes = 1 << 16;

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> splitSpaces(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && isSpace(s[i])) ++i;
    const std::size_t start = i;
    while (i < s.size() && !isSpace(s[i])) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

bool startsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

std::string clip(std::string_view s) {
  return std::string(s.substr(0, 40)) + (s.size() > 40 ? "..." : "");
}

/// Parses a leading number of @p s; advances @p s past it. nullopt if none.
std::optional<double> leadingNumber(std::string_view& s) {
  std::string_view t = s;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || !std::isfinite(value)) return std::nullopt;
  s.remove_prefix(static_cast<std::size_t>(end - s.data()));
  return value;
}

struct Motion {
  int line = 0;
  long index = 0;  // n of P[n]
  planning::MoveKind move = planning::MoveKind::Cut;
  double feedMmPerMin = 0.0;
};

struct Position {
  int line = 0;
  bool joint = false;  // only joint angles J1.. given
  int userFrame = 0;
  double value[6] = {0, 0, 0, 0, 0, 0};  // X Y Z (mm) W P R (deg)
};

enum class Section { None, Attr, Main, Pos, End, Other };

class LsReader {
 public:
  LsReader(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  ClProgram read() {
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
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw IoError(name_ + ": line " + std::to_string(line) + ": " + what);
  }

  void warn(int line, std::string text) { program_.warnings.push_back({line, std::move(text)}); }

  void readLine(std::string_view line, int number) {
    if (!sawProg_) {
      if (trim(line).empty()) return;
      if (!startsWith(line, "/PROG"))
        fail(number, "not a FANUC TP program (expected '/PROG name')");
      const auto tokens = splitSpaces(line.substr(5));
      if (!tokens.empty()) program_.partName = std::string(tokens[0]);
      sawProg_ = true;
      section_ = Section::Attr;
      return;
    }
    if (startsWith(line, "/")) return startSection(line);
    if (section_ == Section::Main) return mainLine(line, number);
    if (section_ == Section::Pos) return posLine(line, number);
    if (section_ == Section::End && !trim(line).empty()) fail(number, "text after /END");
  }

  void startSection(std::string_view line) {
    closeSection();
    const std::string_view name = splitSpaces(line).front();
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
    if (entryOpen_) fail(entryLine_, "position entry does not end with '};'");
  }

  // ---- /MN ----

  void mainLine(std::string_view line, int number) {
    std::string_view t = trim(line);
    if (t.empty()) return;
    if (t.front() == ':') {
      if (!pending_) fail(number, "continuation line ':' without an instruction");
      pendingText_ += ' ';
      pendingText_ += t.substr(1);
    } else {
      std::size_t digits = 0;
      while (digits < t.size() && t[digits] >= '0' && t[digits] <= '9') ++digits;
      if (digits == 0 || digits == t.size() || t[digits] != ':')
        fail(number, "expected a numbered instruction 'N: ... ;', found '" + clip(t) + "'");
      if (pending_) fail(pendingLine_, "instruction does not end with ';'");
      pending_ = true;
      pendingLine_ = number;
      pendingText_.assign(t.substr(digits + 1));
    }
    if (pendingText_.size() > kMaxStatementBytes) fail(pendingLine_, "instruction too long");
    const std::size_t semicolon = pendingText_.rfind(';');
    if (semicolon == std::string::npos) return;
    pending_ = false;
    instruction(trim(std::string_view(pendingText_).substr(0, semicolon)), pendingLine_);
  }

  void instruction(std::string_view t, int line) {
    if (t.empty()) return;
    if (t.front() == '!') return program_.comments.push_back(std::string(trim(t.substr(1))));
    if (startsWith(t, "//")) return program_.comments.push_back(std::string(t));
    const char kind = t.front();
    if (t.size() > 1 && isSpace(t[1]) && (kind == 'J' || kind == 'L' || kind == 'C' || kind == 'A'))
      return motion(kind, t.substr(1), line, t);
    if (startsWith(t, "UTOOL_NUM") || startsWith(t, "UFRAME_NUM")) return frameNumber(t, line);
    program_.comments.push_back(std::string(t));
    warn(line, "instruction '" + clip(t) + "' kept as a comment");
  }

  void frameNumber(std::string_view t, int line) {
    program_.comments.push_back(std::string(t));
    std::string_view value =
        trim(t.substr(t.find('=') == std::string_view::npos ? t.size() : t.find('=') + 1));
    const auto n = leadingNumber(value);
    if (!n || !trim(value).empty()) {
      warn(line, "frame number of '" + clip(t) + "' is not a constant");
      return;
    }
    if (startsWith(t, "UTOOL_NUM") && !toolSet_ && *n >= 0 && *n < 1e6) {
      program_.toolNumber = static_cast<int>(*n);
      toolSet_ = true;
    }
  }

  /// Parses "P[n]" or "P[n:comment]" at the front of @p s; nullopt for a position register.
  std::optional<long> pointRef(std::string_view& s, int line) const {
    s = trim(s);
    if (startsWith(s, "PR[")) return std::nullopt;
    if (!startsWith(s, "P[")) fail(line, "expected a position 'P[n]', found '" + clip(s) + "'");
    s.remove_prefix(2);
    long index = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), index);
    if (ec != std::errc() || index < 0) fail(line, "bad position number in '" + clip(s) + "'");
    s.remove_prefix(static_cast<std::size_t>(end - s.data()));
    if (!s.empty() && s.front() == ':') {
      const std::size_t close = s.size() > 1 && s[1] == '"' ? s.find('"', 2) : 1;
      if (close == std::string_view::npos) fail(line, "unclosed position comment");
      s.remove_prefix(std::min(s.size(), s.find(']', close)));
    }
    if (s.empty() || s.front() != ']') fail(line, "expected ']' after the position number");
    s.remove_prefix(1);
    return index;
  }

  void motion(char kind, std::string_view rest, int line, std::string_view whole) {
    std::vector<long> points;
    for (int i = 0; i < (kind == 'C' ? 2 : 1); ++i) {
      const auto index = pointRef(rest, line);
      if (!index) {
        program_.comments.push_back(std::string(whole));
        warn(line, "motion to a position register kept as a comment: '" + clip(whole) + "'");
        return;
      }
      points.push_back(*index);
      rest = trim(rest);
      if (kind == 'C' && i == 0 && !rest.empty() && rest.front() == ':') rest.remove_prefix(1);
    }
    const auto tokens = splitSpaces(rest);
    if (tokens.size() < 2) fail(line, "motion needs a speed and a termination type");
    const double feed = speed(kind, tokens[0], line);
    if (tokens[1] != "FINE" && !startsWith(tokens[1], "CNT") && !startsWith(tokens[1], "CD"))
      fail(line, "unknown termination type '" + clip(tokens[1]) + "'");
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
    if (startsWith(token, "R[") || startsWith(token, "AR[") || token == "max_speed") {
      if (kind != 'J') warn(line, "speed '" + clip(token) + "' is not a constant: no feed");
      return 0.0;
    }
    std::string_view unit = token;
    const auto value = leadingNumber(unit);
    if (!value || *value < 0) fail(line, "bad speed '" + clip(token) + "'");
    double perMin = 0.0;
    if (unit == "mm/sec")
      perMin = 60.0;
    else if (unit == "cm/min")
      perMin = 10.0;
    else if (unit == "inch/min")
      perMin = 25.4;
    else if (unit != "%" && unit != "deg/sec" && unit != "sec" && unit != "msec")
      fail(line, "unknown speed unit in '" + clip(token) + "'");
    if (kind == 'J') return 0.0;
    if (perMin == 0.0) warn(line, "speed '" + clip(token) + "' gives no linear feed");
    return *value * perMin;
  }

  void option(std::string_view token, int line) {
    static constexpr std::string_view kMoving[] = {"Offset",  "Tool_Offset", "INC",
                                                   "VOFFSET", "Skip",        "TIME"};
    for (const std::string_view word : kMoving)
      if (startsWith(token, word)) {
        warn(line, "motion option '" + clip(token) + "' ignored: the point may differ");
        return;
      }
  }

  // ---- /POS ----

  void posLine(std::string_view line, int number) {
    if (!entryOpen_) {
      const std::string_view t = trim(line);
      if (t.empty()) return;
      if (!startsWith(t, "P["))
        fail(number, "expected a position entry 'P[n]{', found '" + clip(t) + "'");
      entryOpen_ = true;
      entryLine_ = number;
      entryText_.clear();
    }
    entryText_ += line;
    entryText_ += '\n';
    if (entryText_.size() > kMaxStatementBytes) fail(entryLine_, "position entry too long");
    if (line.find('}') == std::string_view::npos) return;
    entryOpen_ = false;
    positionEntry(entryText_, entryLine_);
  }

  void positionEntry(std::string_view text, int line) {
    std::string_view s = text;
    const long index = pointRef(s, line).value_or(-1);  // the "P[" prefix was checked
    s = trim(s);
    const std::size_t close = s.rfind('}');
    if (s.empty() || s.front() != '{' || close == std::string_view::npos || close == 0)
      fail(line, "expected '{' after P[" + std::to_string(index) + "]");
    const std::string_view after = trim(s.substr(close + 1));
    if (!after.empty() && after != ";") fail(line, "unexpected text after '}'");
    const std::string_view body = s.substr(1, close - 1);
    const std::size_t gp1 = body.find("GP1");
    if (gp1 == std::string_view::npos)
      fail(line, "P[" + std::to_string(index) + "] has no group GP1");
    std::string_view group = body.substr(gp1 + 3);
    group = trim(group);
    if (group.empty() || group.front() != ':') fail(line, "expected ':' after GP1");
    group.remove_prefix(1);
    const std::size_t next = group.find("GP");
    if (next != std::string_view::npos) group = group.substr(0, next);
    Position position = parseGroup(group, text, line, index);
    if (!positions_.emplace(index, position).second)
      fail(line, "P[" + std::to_string(index) + "] is defined twice");
  }

  Position parseGroup(std::string_view group, std::string_view text, int line, long index) const {
    Position position;
    position.line = line;
    bool seen[6] = {false, false, false, false, false, false};
    bool joints = false;
    std::size_t start = 0;
    bool quoted = false;
    for (std::size_t i = 0; i <= group.size(); ++i) {
      if (i < group.size() && group[i] == '\'') quoted = !quoted;
      if (i < group.size() && (quoted || group[i] != ',')) continue;
      const std::string_view item = trim(group.substr(start, i - start));
      start = i + 1;
      if (item.empty()) continue;
      const int itemLine = line + static_cast<int>(std::count(text.data(), item.data(), '\n'));
      joints |= groupItem(item, itemLine, position, seen);
    }
    static constexpr const char* kNames[] = {"X", "Y", "Z", "W", "P", "R"};
    const bool any = std::count(seen, seen + 6, true) > 0;
    if (!any && joints) {
      position.joint = true;
      return position;
    }
    for (int k = 0; k < 6; ++k)
      if (!seen[k]) fail(line, "P[" + std::to_string(index) + "] has no " + kNames[k] + " value");
    return position;
  }

  /// Reads "NAME = value unit" or "NAME : value"; true for a joint value J1...
  bool groupItem(std::string_view item, int line, Position& position, bool* seen) const {
    const std::size_t eq = item.find('=');
    if (eq == std::string_view::npos) {
      const std::size_t colon = item.find(':');
      if (colon == std::string_view::npos) fail(line, "unexpected '" + clip(item) + "'");
      if (trim(item.substr(0, colon)) == "UF") {
        std::string_view v = trim(item.substr(colon + 1));
        const auto uf = leadingNumber(v);
        if (!uf || !trim(v).empty() || *uf < 0 || *uf > 1000 || *uf != std::floor(*uf))
          fail(line, "bad user frame '" + clip(item) + "'");
        position.userFrame = static_cast<int>(*uf);
      }
      return false;
    }
    const std::string_view name = trim(item.substr(0, eq));
    std::string_view value = trim(item.substr(eq + 1));
    const auto number = leadingNumber(value);
    if (!number)
      fail(line, "expected a number for " + std::string(name) + ", found '" +
                     clip(trim(item.substr(eq + 1))) + "'");
    const std::string_view unit = trim(value);
    static constexpr std::string_view kNames = "XYZWPR";
    const std::size_t k = name.size() == 1 ? kNames.find(name[0]) : std::string_view::npos;
    if (k == std::string_view::npos) return startsWith(name, "J");
    const std::string_view expected = k < 3 ? "mm" : "deg";
    if (!unit.empty() && unit != expected)
      fail(line, std::string(name) + " must be in " + std::string(expected) + ", found '" +
                     clip(unit) + "'");
    position.value[k] = *number;
    seen[k] = true;
    return false;
  }

  // ---- result ----

  ClProgram assemble() {
    if (!sawMain_) throw IoError(name_ + ": no /MN section");
    if (motions_.empty()) throw IoError(name_ + ": no motion instructions in /MN");
    if (!sawEnd_) warn(0, "no /END: the file may be truncated");
    bool frameWarned = false;
    int path = 0;
    int point = 0;
    bool linearSeen = false;
    for (const Motion& m : motions_) {
      const auto it = positions_.find(m.index);
      if (it == positions_.end())
        fail(m.line, "P[" + std::to_string(m.index) + "] is used but has no /POS entry");
      const Position& p = it->second;
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

  static ClPoint makePoint(const Motion& m, const Position& p, int path, int index) {
    constexpr double kRad = std::numbers::pi / 180.0;
    const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(p.value[5] * kRad, ddf::Vec3::UnitZ()) *
                                      Eigen::AngleAxisd(p.value[4] * kRad, ddf::Vec3::UnitY()) *
                                      Eigen::AngleAxisd(p.value[3] * kRad, ddf::Vec3::UnitX()))
                                         .toRotationMatrix();
    ClPoint point;
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
  ClProgram program_;
  Section section_ = Section::None;
  bool sawProg_ = false;
  bool sawMain_ = false;
  bool sawEnd_ = false;
  bool toolSet_ = false;
  bool pending_ = false;
  int pendingLine_ = 0;
  std::string pendingText_;
  bool entryOpen_ = false;
  int entryLine_ = 0;
  std::string entryText_;
  std::vector<Motion> motions_;
  std::unordered_map<long, Position> positions_;
};

}  // namespace

ClProgram decodeFanucLs(std::string_view text, const std::string& sourceName) {
  return LsReader(text, sourceName).read();
}

ClProgram readFanucLs(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxFileBytes)
    throw IoError(file.string() + ": file larger than 1 GiB, refused as a tool path");
  return decodeFanucLs(detail::readFileBytes(file), file.string());
}

}  // namespace ddfcam::io
